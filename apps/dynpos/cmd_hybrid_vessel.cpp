// dynpos hybrid vessel --scenario ice|mooring: the DP controller of the virtual Gunnerus with
// conventional and with hybrid integral action under a sudden load, side by side.

#include <fmt/core.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "dynpos/analysis/data_dir.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/report/svg_plot.hpp"
#include "dynpos/scenario/load_response.hpp"

namespace dynpos::cli {
namespace {

nlohmann::json optional_json(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

nlohmann::json design_json(const scenario::DesignRun& d) {
  const scenario::LoadResponse& r = d.response;
  return {{"peak_offset_m", r.peak_offset_m},
          {"back_within_s", optional_json(r.back_within_s)},
          {"iae_m_s", r.iae_m_s},
          {"energy_kJ", r.energy_kJ},
          {"jumps", d.jumps}};
}

std::string fmt_optional(const std::optional<double>& v, const char* spec) {
  return v ? fmt::format(fmt::runtime(spec), *v) : std::string("—");
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

std::vector<std::filesystem::path> write_plots(const HybridVesselResult& r,
                                               const std::filesystem::path& dir) {
  const core::Log& conv = r.comparison.conventional.run.truth_log;
  const core::Log& hyb = r.comparison.hybrid.run.truth_log;
  const double t_load = r.comparison.t_load_s;
  const std::string stem = "hybrid_vessel_" + r.name;
  const auto time_axis = [] { return report::Axis{"Time", "s", {}, {}}; };
  std::vector<std::filesystem::path> written;

  report::Figure position;
  position.title =
      fmt::format("{}: distance from the DP setpoint, conventional vs hybrid", r.scenario_name);
  report::Panel p;
  p.title = "Horizontal position offset";
  p.x_axis = time_axis();
  p.y_axis = {"Offset", "m", 0.0, {}};
  p.series.push_back({"hybrid", hyb.time(), offset_m(hyb), "#1f77b4"});
  report::Series c{"conventional", conv.time(), offset_m(conv), "#d62728"};
  c.dashed = true;
  p.series.push_back(c);
  p.x_markers = {t_load};
  p.zoom = report::XRange{std::max(conv.time().front(), t_load - 30.0),
                          std::min(conv.time().back(), t_load + 240.0)};
  position.panels.push_back(p);
  written.push_back(dir / (stem + "_position.svg"));
  report::write_svg(written.back(), position);

  report::Figure integral;
  integral.title = fmt::format("{}: bias estimate (integral state) and the load", r.scenario_name);
  for (const auto& [axis, label] : {std::pair{"north", "North"}, std::pair{"east", "East"}}) {
    report::Panel q;
    q.title = label;
    q.x_axis = time_axis();
    q.y_axis = {std::string("b̂ ") + axis, "kN", {}, {}};
    const std::string ch = std::string("bias_estimate.") + axis;
    const std::string load = std::string("load.") + axis;
    q.series.push_back({"hybrid", hyb.time(), scaled(hyb.values(ch), 1e-3), "#1f77b4"});
    report::Series cs{"conventional", conv.time(), scaled(conv.values(ch), 1e-3), "#d62728"};
    cs.dashed = true;
    q.series.push_back(cs);
    q.series.push_back({"load (true)", conv.time(), scaled(conv.values(load), 1e-3), "#2ca02c"});
    q.x_markers = {t_load};
    integral.panels.push_back(q);
  }
  written.push_back(dir / (stem + "_integral.svg"));
  report::write_svg(written.back(), integral);

  report::Figure power;
  power.title = fmt::format("{}: total thruster power", r.scenario_name);
  report::Panel w;
  w.title = "P_port + P_stb + P_tunnel";
  w.x_axis = time_axis();
  w.y_axis = {"Power", "kW", 0.0, {}};
  const auto total_kw = [](const core::Log& log) {
    std::vector<double> out(log.size());
    for (std::size_t i = 0; i < log.size(); ++i) {
      out[i] = (log.values("power.port")[i] + log.values("power.stb")[i] +
                log.values("power.tunnel")[i]) /
               1e3;
    }
    return out;
  };
  w.series.push_back({"hybrid", hyb.time(), total_kw(hyb), "#1f77b4"});
  report::Series cw{"conventional", conv.time(), total_kw(conv), "#d62728"};
  cw.dashed = true;
  w.series.push_back(cw);
  w.x_markers = {t_load};
  power.panels.push_back(w);
  written.push_back(dir / (stem + "_power.svg"));
  report::write_svg(written.back(), power);
  return written;
}

struct VesselOptions {
  std::string scenario;
  std::uint64_t seed = 1;
  std::filesystem::path out_dir;
  std::string json;
  double within_m = 1.0;
};

}  // namespace

std::string hybrid_vessel_scenario_file(const std::string& short_name) {
  if (short_name == "ice") return "dp-ice-load";
  if (short_name == "mooring") return "dp-mooring-snap";
  throw core::InputError({{}, {}, {}, "--scenario"}, "unknown load scenario '" + short_name + "'",
                         "choose ice (a 20 kN ice load sets in) or mooring (a mooring line "
                         "holding 20 kN snaps)");
}

HybridVesselResult run_hybrid_vessel(const std::string& short_name, std::uint64_t seed,
                                     double within_m) {
  const std::filesystem::path data = analysis::find_data_dir();
  const scenario::ScenarioSpec spec = scenario::load_scenario(
      data / "scenarios" / (hybrid_vessel_scenario_file(short_name) + ".toml"));
  const scenario::VesselConfig vessel =
      scenario::load_vessel_config(data / "vessels" / "gunnerus.toml");
  HybridVesselResult r;
  r.name = short_name;
  r.scenario_name = spec.name;
  r.seed = seed;
  r.comparison = scenario::compare_integral_action(spec, vessel, seed, within_m);
  const hybrid::IntegralJumpParams p = spec.hybrid_integral.value_or(hybrid::IntegralJumpParams{});
  r.parameters = {{"lambda", {p.lambda.x(), p.lambda.y(), p.lambda.z()}},
                  {"epsilon1", p.epsilon1},
                  {"epsilon2", p.epsilon2},
                  {"sigma", p.sigma},
                  {"dwell_s", p.dwell_s},
                  {"rule", "practical jump set (5.64)-(5.67), b_hat += Lambda R(psi) x2"}};
  return r;
}

nlohmann::json hybrid_vessel_json(const HybridVesselResult& r) {
  const scenario::LoadResponse& c = r.comparison.conventional.response;
  return {{"case", "vessel"},
          {"scenario", r.name},
          {"scenario_file", r.scenario_name},
          {"seed", r.seed},
          {"load_time_s", r.comparison.t_load_s},
          {"within_m", c.within_m},
          {"evaluated_s", c.duration_s},
          {"hybrid_parameters", r.parameters},
          {"conventional", design_json(r.comparison.conventional)},
          {"hybrid", design_json(r.comparison.hybrid)}};
}

std::string hybrid_vessel_table(const HybridVesselResult& r, TableFormat format) {
  const scenario::DesignRun& c = r.comparison.conventional;
  const scenario::DesignRun& h = r.comparison.hybrid;
  const double within = c.response.within_m;
  const std::pair<std::string, std::pair<std::string, std::string>> rows[] = {
      {"peak position offset [m]",
       {fmt::format("{:.2f}", c.response.peak_offset_m),
        fmt::format("{:.2f}", h.response.peak_offset_m)}},
      {fmt::format("time back within {:g} m [s]", within),
       {fmt_optional(c.response.back_within_s, "{:.1f}"),
        fmt_optional(h.response.back_within_s, "{:.1f}")}},
      {"IAE of position [m·s]",
       {fmt::format("{:.0f}", c.response.iae_m_s), fmt::format("{:.0f}", h.response.iae_m_s)}},
      {"energy used [kJ]",
       {fmt::format("{:.0f}", c.response.energy_kJ), fmt::format("{:.0f}", h.response.energy_kJ)}},
      {"jumps of the integral state", {fmt::format("{}", c.jumps), fmt::format("{}", h.jumps)}},
  };
  std::string out;
  if (format == TableFormat::kHtml) {
    out += "<table>\n<tr><th>after the load</th><th>conventional</th><th>hybrid</th></tr>\n";
    for (const auto& [label, v] : rows) {
      out += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td></tr>\n", label, v.first, v.second);
    }
    out += "</table>\n";
  } else if (format == TableFormat::kMarkdown) {
    out += "| after the load | conventional | hybrid |\n|---|---:|---:|\n";
    for (const auto& [label, v] : rows)
      out += fmt::format("| {} | {} | {} |\n", label, v.first, v.second);
  } else {
    out += fmt::format("{:<32}{:>14}{:>10}\n", "", "conventional", "hybrid");
    for (const auto& [label, v] : rows) {
      out += fmt::format("{:<32}{:>14}{:>10}\n", label, v.first, v.second);
    }
  }
  return out;
}

std::vector<std::filesystem::path> write_hybrid_vessel_plots(const HybridVesselResult& r,
                                                             const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  return write_plots(r, dir);
}

void add_hybrid_vessel(CLI::App& hybrid) {
  auto opt = std::make_shared<VesselOptions>();
  CLI::App* sub = hybrid.add_subcommand(
      "vessel",
      "Hybrid vs conventional integral action on the virtual Gunnerus under a sudden load");
  sub->add_option("--scenario", opt->scenario,
                  "ice: a 20 kN ice load sets in; mooring: a mooring line holding 20 kN snaps")
      ->required();
  sub->add_option("--seed", opt->seed, "Master seed (the same for both designs)")
      ->capture_default_str();
  sub->add_option("--out", opt->out_dir, "Folder for the SVG plots (created if needed)");
  sub->add_option("--json", opt->json, "Write the results as JSON to FILE, or '-' for stdout");
  sub->add_option("--within", opt->within_m, "Distance for 'back within' [m]")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  sub->footer(
      "Runs data/scenarios/dp-ice-load.toml or dp-mooring-snap.toml twice on the virtual "
      "Gunnerus (thrusters with dynamics and saturation, waves, wind, current): the DP "
      "controller (5.35)-(5.38) with continuous integral action, and with hybrid integral action "
      "(jumps by the practical rule (5.64)-(5.67)). Figures after the load: peak offset, time "
      "back within 1 m, IAE, energy, jumps. Plots: hybrid_vessel_<scenario>_{position,integral,"
      "power}.svg.");
  sub->callback([opt] {
    const std::string file = hybrid_vessel_scenario_file(opt->scenario);  // checks the name
    (void)file;
    const HybridVesselResult r = run_hybrid_vessel(opt->scenario, opt->seed, opt->within_m);
    std::vector<std::filesystem::path> plots;
    if (!opt->out_dir.empty()) plots = write_hybrid_vessel_plots(r, opt->out_dir);
    if (!opt->json.empty()) {
      nlohmann::json doc = hybrid_vessel_json(r);
      doc["plots"] = nlohmann::json::array();
      for (const auto& p : plots) doc["plots"].push_back(p.string());
      io::write_json(opt->json, doc);
    }
    std::FILE* out = opt->json == "-" ? stderr : stdout;
    fmt::print(out, "{} (seed {}), load change at {:.0f} s:\n{}", r.scenario_name, r.seed,
               r.comparison.t_load_s, hybrid_vessel_table(r, TableFormat::kText));
    for (const auto& p : plots) fmt::print(out, "wrote {}\n", p.string());
    if (!opt->json.empty() && opt->json != "-") fmt::print(out, "wrote {}\n", opt->json);
  });
}

}  // namespace dynpos::cli
