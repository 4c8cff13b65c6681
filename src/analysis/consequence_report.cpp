// The consequence analysis' report: its JSON document, its text, the points' CSV and the
// outputs.

#include <fmt/core.h>

#include <iterator>
#include <string>

#include "dynpos/analysis/consequence.hpp"
#include "dynpos/capability/environment_table.hpp"
#include "dynpos/core/angle.hpp"
#include "dynpos/io/atomic_file.hpp"
#include "dynpos/io/csv_writer.hpp"

namespace dynpos::analysis {
namespace {

nlohmann::json body_load_json(const Eigen::Vector3d& load_b) {
  return {{"X_N", load_b.x()}, {"Y_N", load_b.y()}, {"N_Nm", load_b.z()}};
}

nlohmann::json point_json(const ConsequenceReport& r, std::size_t i) {
  const ConsequencePoint& p = r.points[i];
  return {{"time_s", p.t_s},
          {"heading_deg", core::rad_to_deg(p.heading_rad)},
          {"load_b", body_load_json(p.load_b)},
          {"failure", r.cases[p.worst]},
          {"load_factor", p.factors[p.worst]},
          {"margin", p.margin()},
          {"limiting", p.limiting}};
}

nlohmann::json cases_json(const ConsequenceReport& r, const ConsequenceSummary& s) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t k = 0; k < r.cases.size(); ++k) {
    const ConsequencePoint& p = r.points[s.case_min[k]];
    out.push_back({{"failure", r.cases[k]},
                   {"min_load_factor", p.factors[k]},
                   {"time_s", p.t_s},
                   {"fraction_below_one", s.case_fraction_below_one[k]}});
  }
  return out;
}

// A CSV number as the project's CSVs write it (io/csv_writer.hpp): the shortest round trip.
void append_cell(std::string& line, double v) {
  line += ',';
  fmt::format_to(std::back_inserter(line), "{}", v);
}

void write_csv(const ConsequenceReport& r) {
  io::AtomicFile file(r.csv);
  std::string line = io::csv_column_header("time", "s");
  for (const auto& [name, unit] :
       std::initializer_list<std::pair<const char*, const char*>>{{"heading", "deg"},
                                                                  {"load.x", "kN"},
                                                                  {"load.y", "kN"},
                                                                  {"load.n", "kN*m"},
                                                                  {"lambda.intact", ""}}) {
    line += ',' + io::csv_column_header(name, unit);
  }
  for (const std::string& c : r.cases) line += ',' + io::csv_column_header("lambda." + c, "");
  line += ",worst,lambda,margin\n";
  file.stream() << line;
  for (const ConsequencePoint& p : r.points) {
    line.clear();
    fmt::format_to(std::back_inserter(line), "{}", p.t_s);
    append_cell(line, core::rad_to_deg(p.heading_rad));
    for (int i = 0; i < 3; ++i) append_cell(line, p.load_b[i] * 1e-3);
    append_cell(line, p.intact);
    for (const double f : p.factors) append_cell(line, f);
    line += ',' + io::csv_column_header(r.cases[p.worst], "");  // quoted as a header would be
    append_cell(line, p.factors[p.worst]);
    append_cell(line, p.margin());
    file.stream() << line << '\n';
  }
  file.commit();
}

}  // namespace

nlohmann::json to_json(const ConsequenceReport& r) {
  const ConsequenceSummary s = summarise(r);
  nlohmann::json doc;
  doc["analysis"] = "consequence";
  doc["log"] = r.estimate.log.string();
  doc["vessel"] = r.estimate.vessel;
  doc["vessel_file"] = r.estimate.vessel_source.empty() ? nlohmann::json(nullptr)
                                                        : nlohmann::json(r.estimate.vessel_source);
  doc["layout"] = r.layout;
  doc["cases"] = r.cases;
  doc["step_s"] = r.step_s;
  doc["window_s"] = r.mean_window_s;
  doc["points"] = r.points.size();
  doc["from_s"] = r.points.front().t_s;
  doc["to_s"] = r.points.back().t_s;
  doc["smallest_margin"] = point_json(r, s.smallest);
  doc["fraction_negative"] = s.fraction_negative;
  doc["reserve"] = capability::kDynamicAllowance;
  doc["fraction_below_reserve"] = s.fraction_below_reserve;
  doc["per_case"] = cases_json(r, s);
  const ConsequencePoint& intact = r.points[s.intact_min];
  doc["intact"] = {
      {"min_load_factor", intact.intact}, {"capped", intact.intact_capped}, {"time_s", intact.t_s}};
  doc["csv"] = r.csv.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.csv.string());
  doc["estimate"] = to_json(r.estimate);
  return doc;
}

std::string to_text(const ConsequenceReport& r) {
  const ConsequenceSummary s = summarise(r);
  const EstimateReport& e = r.estimate;
  const ConsequencePoint& w = r.points[s.smallest];
  std::string text = fmt::format(
      "{}: worst single failure against the estimated load ({} observer, T_p {:g} s), every {:g} "
      "s on the {:g} s mean of b̂, {}–{} s ({} points), vessel {} ({})\n",
      e.log.string(), control::observer_name(e.observer), e.tp_s, r.step_s, r.mean_window_s,
      r.points.front().t_s, r.points.back().t_s, r.points.size(), e.vessel, r.layout);
  text += fmt::format(
      "smallest margin {:+.2f} at {:g} s: {} lost (λ {:.2f}), heading {:.1f}°, load X {:.2f} kN, "
      "Y {:.2f} kN, N {:.2f} kN·m\n",
      w.margin(), w.t_s, r.cases[w.worst], w.factors[w.worst], core::rad_to_deg(w.heading_rad),
      w.load_b.x() * 1e-3, w.load_b.y() * 1e-3, w.load_b.z() * 1e-3);
  text += fmt::format(
      "margin < 0 (position lost had the worst failure happened): {:.1f} % of the points; λ < "
      "{:g} (DNV's reserve for dynamics): {:.1f} %\n",
      100.0 * s.fraction_negative, capability::kDynamicAllowance, 100.0 * s.fraction_below_reserve);
  text += fmt::format("{:<16} {:>9} {:>9} {:>9}\n", "failure", "min λ", "at [s]", "λ<1 [%]");
  for (std::size_t k = 0; k < r.cases.size(); ++k) {
    const ConsequencePoint& p = r.points[s.case_min[k]];
    text += fmt::format("{:<16} {:>9.3f} {:>9g} {:>9.1f}\n", r.cases[k], p.factors[k], p.t_s,
                        100.0 * s.case_fraction_below_one[k]);
  }
  const ConsequencePoint& intact = r.points[s.intact_min];
  text += fmt::format("{:<16} {:>9.3f} {:>9g} {:>9}\n", "(intact)", intact.intact, intact.t_s,
                      intact.intact_capped ? "capped" : "");
  return text;
}

Written write_outputs(const ConsequenceReport& report, const Outputs& outputs) {
  Written written;
  if (!report.csv.empty()) {
    write_csv(report);
    written.push_back(report.csv);
  }
  write_json_output(outputs, to_json(report), written);
  return written;
}

}  // namespace dynpos::analysis
