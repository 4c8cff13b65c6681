// The adapters of the failure-test report: JSON, the events' table and the printed text.

#include <fmt/core.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "dynpos/analysis/failure_test.hpp"
#include "dynpos/analysis/json_fields.hpp"

namespace dynpos::analysis {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

std::string onset_name(ident::OnsetMethod m) {
  return m == ident::OnsetMethod::kFallFit ? "fall-fit" : "last-level";
}

// A direction [rad] in [0, 360) deg, or null.
nlohmann::json direction_json(const std::optional<double>& rad) {
  if (!rad || !std::isfinite(*rad)) return nullptr;
  const double d = std::fmod(*rad * kDeg, 360.0);
  return d < 0.0 ? d + 360.0 : d;
}

const FailureTestUnit& unit_named(const FailureTestReport& report, const std::string& name) {
  for (const FailureTestUnit& u : report.units) {
    if (u.name == name) return u;
  }
  return report.units.front();  // every event's unit is one of the report's
}

nlohmann::json redistribution_json(const FailureTestReport& report, const ident::FailureEvent& e) {
  nlohmann::json out = nlohmann::json::object();
  for (const ident::UnitRedistribution& r : e.redistribution) {
    const FailureTestUnit& u = unit_named(report, r.unit);
    out[r.unit] = {{"channel", u.channel},
                   {"unit", u.unit},
                   {"before", number_json(r.mean_before, u.per_si)},
                   {"after", number_json(r.mean_after, u.per_si)},
                   {"change", number_json(r.change, u.per_si)},
                   {"took_over", r.took_over}};
  }
  return out;
}

nlohmann::json event_json(const FailureTestReport& report, const ident::FailureEvent& e) {
  const FailureTestUnit& u = unit_named(report, e.unit);
  nlohmann::json j;
  j["time_s"] = e.time_s;
  j["unit"] = e.unit;
  j["units"] = e.units;
  j["channel"] = u.channel;
  j["onset"] = onset_name(e.onset);
  j["fall_time_constant_s"] = number_json(e.fall_time_constant_s);
  j["near_zero_s"] = e.near_zero_s;
  j["level_before"] = e.level_before * u.per_si;
  j["level_unit"] = u.unit;
  j["peak_excursion_m"] = number_json(e.peak_excursion_m);
  j["time_to_peak_s"] = number_json(e.time_to_peak_s);
  j["recovery_s"] = number_json(e.recovery_s);
  j["peak_heading_deg"] = number_json(e.peak_heading_rad, kDeg);
  j["footprint_m"] = number_json(e.footprint_m);
  j["median_peak_m"] = number_json(e.median_peak_m);
  j["recovery_at_footprint_edge"] = e.recovery_at_footprint_edge;
  j["pre_failure"] = {{"from_s", e.pre_from_s},
                      {"to_s", e.pre_to_s},
                      {"north_m", number_json(e.pre_north_m)},
                      {"east_m", number_json(e.pre_east_m)},
                      {"heading_deg", direction_json(e.pre_heading_rad)}};
  j["response_to_s"] = e.response_to_s;
  j["redistribution"] = redistribution_json(report, e);
  return j;
}

nlohmann::json units_json(const FailureTestReport& report) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t k = 0; k < report.units.size(); ++k) {
    const FailureTestUnit& u = report.units[k];
    const ident::UnitScale& s = report.result.units[k];
    out.push_back({{"name", u.name},
                   {"channel", u.channel},
                   {"unit", u.unit},
                   {"full_scale", s.full_scale * u.per_si},
                   {"noise_sigma", s.noise_sigma * u.per_si},
                   {"near_zero", s.near_zero * u.per_si}});
  }
  return out;
}

nlohmann::json windows_json(const ident::FailureTestOptions& o) {
  return {{"pre_window_s", o.pre_window_s},
          {"redistribution_window_s", o.redistribution_window_s},
          {"hold_s", o.hold_s},
          {"response_window_s", o.response_window_s},
          {"max_fall_s", o.max_fall_s},
          {"min_off_s", o.min_off_s},
          {"level_window_s", o.level_window_s},
          {"footprint_edge_share", o.footprint_edge_share}};
}

// "stb 30.0 → 53.9 kN (+23.9)" per unit that did not trip.
std::string redistribution_text(const FailureTestReport& report, const ident::FailureEvent& e) {
  std::string out;
  for (const ident::UnitRedistribution& r : e.redistribution) {
    const FailureTestUnit& u = unit_named(report, r.unit);
    auto cell = [&](const std::optional<double>& v, const char* spec) {
      return number_cell(v ? std::optional<double>(*v * u.per_si) : std::nullopt, spec);
    };
    out += fmt::format("    {}: {} → {} {} ({}){}\n", r.unit, cell(r.mean_before, "{:.1f}"),
                       cell(r.mean_after, "{:.1f}"), u.unit, cell(r.change, "{:+.1f}"),
                       r.took_over ? ", took over" : "");
  }
  return out;
}

}  // namespace

nlohmann::json to_json(const FailureTestReport& report) {
  nlohmann::json doc;
  doc["analysis"] = "failure-test";
  doc["log"] = report.log.string();
  doc["input"] = io::to_json(report.input);
  doc["position"] = report.position;
  doc["heading_logged"] = report.has_heading;
  doc["arm_m"] = report.arm_m
                     ? nlohmann::json{report.arm_m->x(), report.arm_m->y(), report.arm_m->z()}
                     : nlohmann::json(nullptr);
  doc["arm_with_attitude"] = report.attitude;
  doc["units"] = units_json(report);
  doc["windows"] = windows_json(report.options);
  doc["notes"] = report.notes;
  doc["events"] = nlohmann::json::array();
  for (const ident::FailureEvent& e : report.result.events) {
    doc["events"].push_back(event_json(report, e));
  }
  return doc;
}

report::Table failure_test_table(const FailureTestReport& report) {
  report::Table t;
  t.header = {"unit",         "time [s]",      "peak [m]",     "to peak [s]",
              "recovery [s]", "heading [deg]", "footprint [m]"};
  for (const ident::FailureEvent& e : report.result.events) {
    std::string units = e.unit;
    for (const std::string& u : e.units) {
      if (u != e.unit) units += "+" + u;
    }
    t.rows.push_back(
        {units, fmt::format("{:.1f}", e.time_s), number_cell(e.peak_excursion_m, "{:.2f}"),
         number_cell(e.time_to_peak_s, "{:.1f}"), number_cell(e.recovery_s, "{:.1f}"),
         number_cell(e.peak_heading_rad ? std::optional(*e.peak_heading_rad * kDeg) : std::nullopt,
                     "{:.1f}"),
         number_cell(e.footprint_m, "{:.2f}")});
  }
  return t;
}

std::string to_text(const FailureTestReport& report) {
  std::string out = fmt::format("{}: failure test, {} event(s)\n", report.log.string(),
                                report.result.events.size());
  std::string units;
  for (const FailureTestUnit& u : report.units) {
    units += (units.empty() ? "" : ", ") + u.channel;
  }
  out += fmt::format("  units: {}\n", units);
  out += fmt::format("  position: {}{}\n", report.position,
                     report.arm_m
                         ? fmt::format(", moved to the control origin by the arm "
                                       "({:g}, {:g}, {:g}) m{}",
                                       report.arm_m->x(), report.arm_m->y(), report.arm_m->z(),
                                       report.attitude ? " with roll and pitch" : "")
                         : std::string());
  const ident::FailureTestOptions& o = report.options;
  out += fmt::format(
      "  windows: pre-failure {:g} s, redistribution {:g} s, hold {:g} s, response {:g} s\n",
      o.pre_window_s, o.redistribution_window_s, o.hold_s, o.response_window_s);
  for (const std::string& note : report.notes) out += "  note: " + note + "\n";
  if (!report.result.events.empty()) out += report::render_text(failure_test_table(report));
  for (const ident::FailureEvent& e : report.result.events) {
    if (e.recovery_at_footprint_edge) {
      out += fmt::format(
          "  note: {} at {:.1f} s: the recovery is at the footprint's edge (the distance's "
          "median peaks at {:.2f} m against a footprint of {:.2f} m): whether the vessel left "
          "it turns on where the footprint is drawn\n",
          e.unit, e.time_s, *e.median_peak_m, *e.footprint_m);
    }
    out += fmt::format("  redistribution after {} at {:.1f} s:\n", e.unit, e.time_s);
    out += redistribution_text(report, e);
  }
  return out + io::to_text(report.input);
}

Written write_outputs(const FailureTestReport& report, const Outputs& outputs) {
  Written written;
  write_json_output(outputs, to_json(report), written);
  return written;
}

}  // namespace dynpos::analysis
