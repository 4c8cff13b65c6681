// The thrust agility section of the demo report, with the thrust map (3.17) back-calculated
// from the surge step logs.

#include <fmt/core.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dynpos/analysis/agility.hpp"
#include "dynpos/analysis/data_dir.hpp"
#include "dynpos/analysis/demo_sections.hpp"
#include "dynpos/analysis/thrust_map.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/model/thruster.hpp"
#include "dynpos/report/table.hpp"
#include "dynpos/scenario/trial_truth.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::analysis {
namespace {

// Thrust map (3.17) back-calculated by the thrust-map analysis from each log with thrust and
// shaft speed, against the vessel file's c± (c = ρK_T·D⁴) and the thesis' table 3.2: a row per
// log (name, report) and main propeller.
report::Table thrust_map_table(const std::vector<std::pair<std::string, ThrustMapReport>>& maps,
                               const scenario::VesselConfig& vessel) {
  const model::Thruster propeller(vessel.propeller);
  const double true_pos = propeller.thrust_coefficient(1.0);
  const double true_neg = -propeller.thrust_coefficient(-1.0);
  report::Table t;
  t.header = {"log", "thruster", "c+ [kN/rps²]",        "c- [kN/rps²]",  "n+",
              "n-",  "R²",       "vessel file c+ / c-", "thesis c+ / c-"};
  t.first_numeric_column = 2;
  const auto kn = [](const std::optional<ident::Estimate>& e) {
    return e ? fmt::format("{:.3f}", e->value / 1000.0) : std::string("—");
  };
  for (const auto& [log_name, map] : maps) {
    for (const ThrusterMapFit& fit : map.thrusters) {
      if (fit.name == "tunnel") continue;
      const ident::ThrustMapFitResult& r = fit.fit;
      t.rows.push_back({log_name, fit.name, kn(r.c_forward), kn(r.c_reverse),
                        std::to_string(r.samples_forward), std::to_string(r.samples_reverse),
                        r.r_squared ? fmt::format("{:.4f}", *r.r_squared) : "—",
                        fmt::format("{:.2f} / {:.2f}", true_pos / 1000.0, true_neg / 1000.0),
                        "8.13 / -5.8"});
    }
  }
  return t;
}

// The thrust map paragraph from the surge step logs of the campaign (the public request and
// runner, with the analysis' default |n| ≥ 3 rpm); empty without them.
std::pair<std::string, std::string> thrust_map_part(const std::filesystem::path& campaign_dir) {
  std::vector<std::pair<std::string, ThrustMapReport>> maps;
  for (const char* name : {"surge-steps-forward", "surge-steps-backward"}) {
    const std::filesystem::path steps = campaign_dir / name / "log.csv";
    if (!std::filesystem::exists(steps)) continue;
    ThrustMapRequest request;
    request.source.log = steps;
    maps.emplace_back(name, run_thrust_map(request));
  }
  if (maps.empty()) return {};
  const scenario::VesselConfig vessel = scenario::load_vessel_config(vessel_file_or_default());
  const report::Table map = thrust_map_table(maps, vessel);
  const std::string text =
      "Thrust map T = c·n|n| (3.17) back-calculated from the surge step logs (logged thrust "
      "and shaft speed, |n| ≥ 0.05 rps; c+ from the forward steps, c- from the backward ones), "
      "against the vessel file (c = ρK_T·D⁴) and the thesis' table 3.2 (kN/rps²).";
  return {"\n" + text + "\n\n" + report::render_markdown(map),
          "<p>" + text + "</p>\n" + report::render_html(map)};
}

// The current of the run as an operator reads it off the DP display: the scenario's, from the
// run's truth.json; none without it or without a current.
std::optional<ObservedCurrent> observed_current(const std::filesystem::path& run_dir) {
  const std::filesystem::path file = run_dir / "truth.json";
  if (!std::filesystem::exists(file)) return std::nullopt;
  const scenario::EnvironmentSpec& env = scenario::read_trial_truth(file).scenario.environment;
  if (!(env.current_speed_mps > 0.0)) return std::nullopt;
  return ObservedCurrent{env.current_speed_mps, env.current_to_deg};
}

}  // namespace

ReportSection agility_demo_section(const std::filesystem::path& campaign_dir) {
  const std::filesystem::path log = campaign_dir / "agility" / "log.csv";
  if (!std::filesystem::exists(log)) return {};
  AgilityRequest request;
  request.source.log = log;
  request.current = observed_current(campaign_dir / "agility");
  const AgilityReport report = run_agility(request);
  nlohmann::json doc = to_json(report);
  doc["log"] = "agility/log.csv";  // relative, so the report is relocatable
  doc["input"] = io::to_json(relative_to(report.input, campaign_dir));
  const std::filesystem::path dir = campaign_dir / "analysis" / "agility";
  std::filesystem::create_directories(dir);
  io::write_json((dir / "agility.json").string(), doc);
  write_plot(report, dir / "agility.svg", "Thrust agility (simulated)");
  const report::Table table = agility_table(report);
  const std::string intro =
      "Thrust agility (`agility`): a joystick thrust step in each of 8 directions, at 50 % and "
      "100 % thrust, and at 100 % with 100 % yaw moment. Time from the step to 63.2 % of each "
      "thruster's thrust response (dead time included), the slowest of them (thrust envelope) "
      "and the speed response √(u²+v²) over the 40 s step; — = no response (e.g. the tunnel "
      "ahead and astern). Thesis figures 3.1–3.3 give 3–10 s for the main propellers. Plot: "
      "analysis/agility/agility.svg; JSON: analysis/agility/agility.json.";
  ReportSection s;
  s.title = "Thrust agility";
  s.markdown = intro + "\n\n" + report::render_markdown(table) +
               "\n\n![Thrust agility](analysis/agility/agility.svg)\n";
  s.html = "<p>" + intro + "</p>\n" + report::render_html(table) +
           "<p><img src=\"analysis/agility/agility.svg\" alt=\"Thrust agility polar plots\"></p>\n";
  const auto [map_markdown, map_html] = thrust_map_part(campaign_dir);
  s.markdown += map_markdown;
  s.html += map_html;
  return s;
}

}  // namespace dynpos::analysis
