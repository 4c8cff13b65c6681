// The report of the hybrid-vessel comparison: JSON, the table in three formats, the plots and
// the files written (the demo report's section is hybrid_vessel_demo.cpp).

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "dynpos/analysis/hybrid_vessel.hpp"
#include "dynpos/analysis/json_fields.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/report/svg_plot.hpp"

namespace dynpos::analysis {
namespace {

nlohmann::json design_json(const scenario::DesignRun& d) {
  const scenario::LoadResponse& r = d.response;
  return {{"peak_offset_m", r.peak_offset_m},
          {"back_within_s", number_json(r.back_within_s)},
          {"iae_m_s", r.iae_m_s},
          {"energy_kJ", r.energy_kJ},
          {"jumps", d.jumps}};
}

using Row = std::pair<std::string, std::pair<std::string, std::string>>;

// The table's rows: label, conventional, hybrid.
std::vector<Row> table_rows(const HybridVesselReport& r) {
  const scenario::DesignRun& c = r.comparison.conventional;
  const scenario::DesignRun& h = r.comparison.hybrid;
  return {
      {"peak position offset [m]",
       {fmt::format("{:.2f}", c.response.peak_offset_m),
        fmt::format("{:.2f}", h.response.peak_offset_m)}},
      {fmt::format("time back within {:g} m [s]", c.response.within_m),
       {number_cell(c.response.back_within_s, "{:.1f}"),
        number_cell(h.response.back_within_s, "{:.1f}")}},
      {"IAE of position [m·s]",
       {fmt::format("{:.0f}", c.response.iae_m_s), fmt::format("{:.0f}", h.response.iae_m_s)}},
      {"energy used [kJ]",
       {fmt::format("{:.0f}", c.response.energy_kJ), fmt::format("{:.0f}", h.response.energy_kJ)}},
      {"jumps of the integral state", {fmt::format("{}", c.jumps), fmt::format("{}", h.jumps)}},
  };
}

// Horizontal distance from the setpoint [m] of a truth log.
std::vector<double> offset_m(const core::Log& log) {
  std::vector<double> d(log.size());
  for (std::size_t i = 0; i < log.size(); ++i) {
    d[i] = std::hypot(log.values("north")[i] - log.values("setpoint.north")[i],
                      log.values("east")[i] - log.values("setpoint.east")[i]);
  }
  return d;
}

std::vector<double> scaled(const std::vector<double>& v, double factor) {
  std::vector<double> out(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) out[i] = v[i] * factor;
  return out;
}

// P_port + P_stb + P_tunnel [kW].
std::vector<double> total_power_kW(const core::Log& log) {
  std::vector<double> out(log.size());
  for (std::size_t i = 0; i < log.size(); ++i) {
    out[i] =
        (log.values("power.port")[i] + log.values("power.stb")[i] + log.values("power.tunnel")[i]) /
        1e3;
  }
  return out;
}

report::Axis time_axis() { return report::Axis{"Time", "s", {}, {}}; }

// Hybrid solid blue, conventional dashed red.
void add_designs(report::Panel& p, const core::Log& hyb, const core::Log& conv,
                 std::vector<double> hyb_y, std::vector<double> conv_y) {
  p.series.push_back({"hybrid", hyb.time(), std::move(hyb_y), "#1f77b4"});
  report::Series c{"conventional", conv.time(), std::move(conv_y), "#d62728"};
  c.dashed = true;
  p.series.push_back(c);
}

report::Figure position_figure(const HybridVesselReport& r) {
  const core::Log& conv = r.comparison.conventional.run.truth_log;
  const core::Log& hyb = r.comparison.hybrid.run.truth_log;
  const double t_load = r.comparison.t_load_s;
  report::Figure position;
  position.title =
      fmt::format("{}: distance from the DP setpoint, conventional vs hybrid", r.scenario_name);
  report::Panel p;
  p.title = "Horizontal position offset";
  p.x_axis = time_axis();
  p.y_axis = {"Offset", "m", 0.0, {}};
  add_designs(p, hyb, conv, offset_m(hyb), offset_m(conv));
  p.x_markers = {t_load};
  p.zoom = report::XRange{std::max(conv.time().front(), t_load - 30.0),
                          std::min(conv.time().back(), t_load + 240.0)};
  position.panels.push_back(p);
  return position;
}

report::Figure integral_figure(const HybridVesselReport& r) {
  const core::Log& conv = r.comparison.conventional.run.truth_log;
  const core::Log& hyb = r.comparison.hybrid.run.truth_log;
  report::Figure integral;
  integral.title = fmt::format("{}: bias estimate (integral state) and the load", r.scenario_name);
  for (const auto& [axis, label] : {std::pair{"north", "North"}, std::pair{"east", "East"}}) {
    report::Panel q;
    q.title = label;
    q.x_axis = time_axis();
    q.y_axis = {std::string("b̂ ") + axis, "kN", {}, {}};
    const std::string ch = std::string("bias_estimate.") + axis;
    const std::string load = std::string("load.") + axis;
    add_designs(q, hyb, conv, scaled(hyb.values(ch), 1e-3), scaled(conv.values(ch), 1e-3));
    q.series.push_back({"load (true)", conv.time(), scaled(conv.values(load), 1e-3), "#2ca02c"});
    q.x_markers = {r.comparison.t_load_s};
    integral.panels.push_back(q);
  }
  return integral;
}

report::Figure power_figure(const HybridVesselReport& r) {
  const core::Log& conv = r.comparison.conventional.run.truth_log;
  const core::Log& hyb = r.comparison.hybrid.run.truth_log;
  report::Figure power;
  power.title = fmt::format("{}: total thruster power", r.scenario_name);
  report::Panel w;
  w.title = "P_port + P_stb + P_tunnel";
  w.x_axis = time_axis();
  w.y_axis = {"Power", "kW", 0.0, {}};
  add_designs(w, hyb, conv, total_power_kW(hyb), total_power_kW(conv));
  w.x_markers = {r.comparison.t_load_s};
  power.panels.push_back(w);
  return power;
}

}  // namespace

nlohmann::json to_json(const HybridVesselReport& r) {
  const scenario::LoadResponse& c = r.comparison.conventional.response;
  const hybrid::IntegralJumpParams& p = r.jump_params;
  const nlohmann::json parameters = {
      {"lambda", {p.lambda.x(), p.lambda.y(), p.lambda.z()}},
      {"epsilon1", p.epsilon1},
      {"epsilon2", p.epsilon2},
      {"sigma", p.sigma},
      {"dwell_s", p.dwell_s},
      {"rule", "practical jump set (5.64)-(5.67), b_hat += Lambda R(psi) x2"}};
  return {{"case", "vessel"},
          {"scenario", r.name},
          {"scenario_file", r.scenario_name},
          {"seed", r.seed},
          {"load_time_s", r.comparison.t_load_s},
          {"within_m", c.within_m},
          {"evaluated_s", c.duration_s},
          {"hybrid_parameters", parameters},
          {"conventional", design_json(r.comparison.conventional)},
          {"hybrid", design_json(r.comparison.hybrid)}};
}

nlohmann::json to_json(const HybridVesselReport& r,
                       const std::vector<std::filesystem::path>& plots) {
  nlohmann::json doc = to_json(r);
  doc["plots"] = nlohmann::json::array();
  for (const auto& p : plots) doc["plots"].push_back(p.string());
  return doc;
}

std::string to_text(const HybridVesselReport& r) {
  std::string out = fmt::format("{} (seed {}), load change at {:.0f} s:\n", r.scenario_name, r.seed,
                                r.comparison.t_load_s);
  out += fmt::format("{:<32}{:>14}{:>10}\n", "", "conventional", "hybrid");
  for (const auto& [label, v] : table_rows(r)) {
    out += fmt::format("{:<32}{:>14}{:>10}\n", label, v.first, v.second);
  }
  return out;
}

std::string to_markdown(const HybridVesselReport& r) {
  std::string out = "| after the load | conventional | hybrid |\n|---|---:|---:|\n";
  for (const auto& [label, v] : table_rows(r)) {
    out += fmt::format("| {} | {} | {} |\n", label, v.first, v.second);
  }
  return out;
}

std::string to_html(const HybridVesselReport& r) {
  std::string out =
      "<table>\n<tr><th>after the load</th><th>conventional</th><th>hybrid</th></tr>\n";
  for (const auto& [label, v] : table_rows(r)) {
    out += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td></tr>\n", label, v.first, v.second);
  }
  out += "</table>\n";
  return out;
}

std::vector<std::filesystem::path> write_figures(const HybridVesselReport& r,
                                                 const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  const std::string stem = "hybrid_vessel_" + r.name;
  std::vector<std::filesystem::path> written;
  for (const auto& [name, figure] :
       {std::pair{"position", position_figure(r)}, std::pair{"integral", integral_figure(r)},
        std::pair{"power", power_figure(r)}}) {
    written.push_back(dir / (stem + "_" + name + ".svg"));
    report::write_svg(written.back(), figure);
  }
  return written;
}

Written write_outputs(const HybridVesselReport& report, const Outputs& outputs) {
  Written written;
  if (!outputs.figures.empty()) written = write_figures(report, outputs.figures);
  write_json_output(outputs, to_json(report, written), written);
  return written;
}

}  // namespace dynpos::analysis
