// The stationkeeping section of the `dynpos demo` report: the pure-DP run per heading hold.

#include <filesystem>
#include <string>

#include "dynpos/analysis/demo_sections.hpp"
#include "dynpos/analysis/station_keeping.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/report/table.hpp"

namespace dynpos::analysis {

ReportSection station_keeping_demo_section(const std::filesystem::path& campaign_dir) {
  const std::filesystem::path log = campaign_dir / "pure-dp" / "log.csv";
  if (!std::filesystem::exists(log)) return {};
  StationKeepingRequest request;
  request.source.log = log;
  request.source.columns = {"north=gnss1.north", "east=gnss1.east"};
  request.per_setpoint = true;
  request.waves = "Hs 2.0 m, Tp 7 s, from 0° (simulated)";
  request.current = "0.2 m/s towards 180° (simulated)";
  StationKeepingReport result = run_station_keeping(request);
  result.log = "pure-dp/log.csv";  // relative to the report, so the report is relocatable
  result.input = relative_to(std::move(result.input), campaign_dir);
  const std::filesystem::path dir = campaign_dir / "analysis" / "station-keeping";
  std::filesystem::create_directories(dir);
  io::write_json((dir / "pure-dp.json").string(), to_json(result));
  const report::Table table = station_keeping_table(result);
  const std::string intro =
      "Pure DP (`pure-dp`): the last 5 min of each heading hold, relative to the weather "
      "(waves " +
      request.waves + ", current " + request.current +
      "; wind from the log). Thesis tables 3.14–3.22 in Hs 1.7–2.3 m: position std 0.3–0.9 m, "
      "heading std 0.4–0.9° (2.8° once), mean total thrust 1–45 kN. Position from GNSS antenna "
      "1; JSON: analysis/station-keeping/pure-dp.json.";
  ReportSection s;
  s.title = "Stationkeeping (pure DP)";
  s.markdown = intro + "\n\n" + report::render_markdown(table);
  s.html = "<p>" + intro + "</p>\n" + report::render_html(table);
  return s;
}

}  // namespace dynpos::analysis
