// The thrust map's report: its JSON document, its text and its outputs (the applied thrust's
// CSV, the JSON).

#include <fmt/core.h>

#include "dynpos/analysis/json_fields.hpp"
#include "dynpos/analysis/thrust_map.hpp"
#include "dynpos/io/csv_writer.hpp"

namespace dynpos::analysis {
namespace {

// A coefficient in kN/rps² with its 1σ, as the table shows it.
std::string kn_cell(const std::optional<ident::Estimate>& e) {
  if (!e) return "—";
  return e->sigma ? fmt::format("{:.3f} ± {:.3f}", e->value / 1000.0, *e->sigma / 1000.0)
                  : fmt::format("{:.3f}", e->value / 1000.0);
}

}  // namespace

nlohmann::json to_json(const ThrustMapReport& report) {
  nlohmann::json doc;
  doc["analysis"] = "thrust-map";
  doc["log"] = report.log.string();
  doc["input"] = io::to_json(report.input);
  doc["unit"] = "N/rps^2";
  doc["thrusters"] = nlohmann::json::array();
  for (const ThrusterMapFit& t : report.thrusters) {
    const ident::ThrustMapFitResult& r = t.fit;
    doc["thrusters"].push_back(
        {{"name", t.name},
         {"c_pos", number_json(value_of(r.c_forward))},
         {"c_neg", number_json(value_of(r.c_reverse))},
         {"sigma", {{"c_pos", sigma_json(r.c_forward)}, {"c_neg", sigma_json(r.c_reverse)}}},
         {"c_mean", number_json(t.c_mean)},
         {"n_samples", {{"pos", r.samples_forward}, {"neg", r.samples_reverse}}},
         {"r_squared", number_json(r.r_squared)},
         {"status", std::string(ident::fit_status_name(r.status))},
         {"message", r.message}});
  }
  return doc;
}

std::string to_text(const ThrustMapReport& report) {
  if (report.applied) {
    const AppliedThrust& a = *report.applied;
    return fmt::format(
        "{}: thrust of {} thruster(s) from {} ({}) into {}\n", report.log.string(), a.thrusters,
        a.vessel_source.empty() ? std::string("the built-in vessel") : a.vessel_source,
        a.abs_speed ? "|n| only: mean coefficient (3.18)" : "signed n: c+ / c- (3.17)",
        a.csv.string());
  }
  std::string text = fmt::format("{}: thrust map T = c·n|n| (3.17), |n| ≥ {} rpm, ±1σ\n",
                                 report.log.string(), report.min_speed_rpm);
  text += fmt::format("{:<10} {:>20} {:>20} {:>9} {:>8} {:>8} {:>7}\n", "thruster", "c+ [kN/rps²]",
                      "c- [kN/rps²]", "c̄", "n+", "n-", "R²");
  for (const ThrusterMapFit& t : report.thrusters) {
    const ident::ThrustMapFitResult& r = t.fit;
    text +=
        fmt::format("{:<10} {:>20} {:>20} {:>9} {:>8} {:>8} {:>7}\n", t.name, kn_cell(r.c_forward),
                    kn_cell(r.c_reverse),
                    t.c_mean ? fmt::format("{:.3f}", *t.c_mean / 1000.0) : "—", r.samples_forward,
                    r.samples_reverse, r.r_squared ? fmt::format("{:.4f}", *r.r_squared) : "—");
  }
  return text + io::to_text(report.input);
}

Written write_outputs(const ThrustMapReport& report, const Outputs& outputs) {
  Written written;
  if (report.applied) io::write_csv(report.applied->csv, report.applied->log);
  write_json_output(outputs, to_json(report), written);
  return written;
}

}  // namespace dynpos::analysis
