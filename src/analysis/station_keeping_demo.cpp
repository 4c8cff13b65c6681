// The stationkeeping section of the `dynpos demo` report: the pure-DP run per heading hold.

#include <fmt/core.h>

#include <filesystem>
#include <string>

#include "dynpos/analysis/demo_sections.hpp"
#include "dynpos/analysis/station_keeping.hpp"
#include "dynpos/report/table.hpp"
#include "dynpos/scenario/trial_truth.hpp"

namespace dynpos::analysis {
namespace {

// The run's weather as the request's observed waves and current: the scenario's environment
// that truth.json repeats (waves from, current towards, degrees clockwise from north).
void observed_from_truth(const std::filesystem::path& truth_json, StationKeepingRequest& request) {
  if (!std::filesystem::exists(truth_json)) return;
  const scenario::EnvironmentSpec& e = scenario::read_trial_truth(truth_json).scenario.environment;
  request.waves = fmt::format("Hs {:.1f} m, Tp {:g} s, from {:g}° (simulated)", e.hs_m, e.tp_s,
                              e.wave_from_deg);
  request.current =
      fmt::format("{:g} m/s towards {:g}° (simulated)", e.current_speed_mps, e.current_to_deg);
}

}  // namespace

ReportSection station_keeping_demo_section(const std::filesystem::path& campaign_dir) {
  const std::filesystem::path log = campaign_dir / "pure-dp" / "log.csv";
  if (!std::filesystem::exists(log)) return {};
  StationKeepingRequest request;
  request.source.log = log;
  request.source.columns = {"north=gnss1.north", "east=gnss1.east"};
  request.per_setpoint = true;
  observed_from_truth(campaign_dir / "pure-dp" / "truth.json", request);
  StationKeepingReport result = run_station_keeping(request);
  result.log = "pure-dp/log.csv";  // relative to the report, so the report is relocatable
  result.input = relative_to(std::move(result.input), campaign_dir);
  const std::filesystem::path dir = campaign_dir / "analysis" / "station-keeping";
  std::filesystem::create_directories(dir);
  write_outputs(result, {.json = (dir / "pure-dp.json").string(), .figures = {}});
  const report::Table table = station_keeping_table(result);
  const std::string weather = request.waves.empty() ? std::string("wind from the log")
                                                    : "waves " + request.waves + ", current " +
                                                          request.current + "; wind from the log";
  const std::string intro =
      "Pure DP (`pure-dp`): the last 5 min of each heading hold, relative to the weather (" +
      weather +
      "). Thesis tables 3.14–3.22 in Hs 1.7–2.3 m: position std 0.3–0.9 m, heading std "
      "0.4–0.9° (2.8° once), mean total thrust 1–45 kN. Position from GNSS antenna 1; JSON: "
      "analysis/station-keeping/pure-dp.json.";
  ReportSection s;
  s.title = "Stationkeeping (pure DP)";
  s.markdown = intro + "\n\n" + report::render_markdown(table);
  s.html = "<p>" + intro + "</p>\n" + report::render_html(table);
  return s;
}

}  // namespace dynpos::analysis
