// The DP 4-corner section of the demo report: the identified legs beside the simulator's own
// reach times.

#include <fmt/core.h>

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "dynpos/analysis/demo_sections.hpp"
#include "dynpos/analysis/four_corner.hpp"
#include "dynpos/report/table.hpp"
#include "dynpos/scenario/trial_truth.hpp"

namespace dynpos::analysis {
namespace {

// What the section takes from the scenario's truth.json.
struct FourCornerTruth {
  /// The surveyed horizontal lever arm of GNSS antenna 1 (x, y) [m], when given.
  std::optional<Eigen::Vector2d> gnss1_arm_m;
  /// The duration of each leg, t_reached − t_start of each setpoint but the hold, in order [s];
  /// absent without truth.json.
  std::optional<std::vector<double>> leg_durations_s;
};

// The one place the section reads truth.json; a missing file gives nothing.
FourCornerTruth read_truth(const std::filesystem::path& truth_json) {
  FourCornerTruth truth;
  if (!std::filesystem::exists(truth_json)) return truth;
  const scenario::TrialTruth t = scenario::read_trial_truth(truth_json);
  if (const auto arm = t.lever_arms.find("gnss1"); arm != t.lever_arms.end()) {
    truth.gnss1_arm_m = arm->second.head<2>();
  }
  truth.leg_durations_s.emplace();
  for (const scenario::SetpointTruth& s : t.setpoints) {
    if (s.t_reached_s && s.name != "hold") {
      truth.leg_durations_s->push_back(*s.t_reached_s - s.t_start_s);
    }
  }
  return truth;
}

// The identified leg durations beside the simulator's; no rows without the simulator's.
report::Table truth_table(const ident::FourCornerResult& result,
                          const std::optional<std::vector<double>>& durations) {
  report::Table truth;
  truth.header = {"leg", "duration [s], identified", "duration [s], simulator", "difference [s]"};
  if (!durations) return truth;
  for (std::size_t k = 0; k < result.legs.size(); ++k) {
    const auto& leg = result.legs[k];
    const bool known = k < durations->size();
    truth.rows.push_back({leg.name, fmt::format("{:.1f}", leg.duration_s),
                          known ? fmt::format("{:.1f}", (*durations)[k]) : "—",
                          known ? fmt::format("{:+.1f}", leg.duration_s - (*durations)[k]) : "—"});
  }
  return truth;
}

}  // namespace

ReportSection four_corner_demo_section(const std::filesystem::path& campaign_dir) {
  const std::filesystem::path log = campaign_dir / "four-corner" / "log.csv";
  if (!std::filesystem::exists(log)) return {};
  const FourCornerTruth truth = read_truth(campaign_dir / "four-corner" / "truth.json");
  FourCornerRequest request;
  request.source.log = log;
  request.source.columns = {"north=gnss1.north", "east=gnss1.east"};
  // The antenna's surveyed lever arm (the vessel file's, which truth.json repeats), so the
  // circle is tested at the control origin as the DP system does.
  request.arm_m = truth.gnss1_arm_m;
  FourCornerReport report = run_four_corner(request);
  report.log = "four-corner/log.csv";  // relative to the report, so it is relocatable
  report.input = relative_to(std::move(report.input), campaign_dir);
  const std::filesystem::path dir = campaign_dir / "analysis" / "four-corner";
  std::filesystem::create_directories(dir);
  Written written;
  write_json_output({.json = (dir / "four-corner.json").string(), .figures = {}}, to_json(report),
                    written);
  write_plot(report, dir / "four-corner_ne.svg", "DP 4-corner on the virtual Gunnerus");
  // The simulator's own reach times (truth.json) beside the identified legs.
  const report::Table truth_durations = truth_table(report.result, truth.leg_durations_s);
  const report::Table table = four_corner_table(report);
  const std::string intro =
      "DP 4-corner (`four-corner`, 50 m legs): legs from the logged setpoints, each ending when "
      "the control origin (GNSS antenna 1 moved by its lever arm) is within 2 m and the heading "
      "within 2° of the setpoint, both averaged over 10 s as a DP wave filter does. Thesis "
      "tables 3.6–3.10: 85–214 s per leg, 545–624 s in total. JSON: analysis/four-corner/"
      "four-corner.json.";
  ReportSection s;
  s.title = "DP 4-corner";
  s.markdown = intro + "\n\n" + report::render_markdown(table) + "\n" +
               report::render_markdown(truth_durations) +
               "\n![NE plot](analysis/four-corner/four-corner_ne.svg)\n";
  s.html = "<p>" + intro + "</p>\n" + report::render_html(table) +
           report::render_html(truth_durations) +
           "<p><img src=\"analysis/four-corner/four-corner_ne.svg\" alt=\"NE plot\"></p>\n";
  return s;
}

}  // namespace dynpos::analysis
