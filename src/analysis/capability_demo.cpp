// The demo report's DP capability section: the virtual Gunnerus at level 1 (every single
// failure) and level 3 (time domain, intact and the failures that are worst at level 1).

#include <fmt/core.h>

#include <algorithm>
#include <set>

#include "dynpos/analysis/capability.hpp"
#include "dynpos/analysis/demo_sections.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/report/table.hpp"

namespace dynpos::analysis {
namespace {

// Level 3 in the demo: 30° steps, 300 s judged after 300 s, the wind to 0.5 m/s.
CapabilityRequest level3_request(std::uint64_t seed) {
  CapabilityRequest q;
  q.level = 3;
  q.direction_step = 30.0;
  q.settle = 300.0;
  q.duration = 300.0;
  q.wind_tolerance = 0.5;
  q.seed = seed;
  return q;
}

// Level 3 intact and for each failure that is the worst somewhere at level 1 (the others are
// never the worst there), with their worst case.
CapabilityReport level3_report(const CapabilityReport& l1, std::uint64_t seed) {
  CapabilityRequest q = level3_request(seed);
  std::set<std::string> worst_at_l1;
  for (const auto& p : l1.worst->points) worst_at_l1.insert(p.failure);
  q.failure = "worst";
  q.worst_of.assign(worst_at_l1.begin(), worst_at_l1.end());
  return run_capability(q);
}

report::Table summary_table(const CapabilityReport& l1, const CapabilityReport& l3) {
  report::Table t;
  t.header = {"from [deg]", "L1 intact", "L1 worst", "L3 intact", "L3 worst"};
  const auto cell = [](const capability::CapabilityPoint& p) {
    return fmt::format("{} ({}{:.1f} m/s)", p.dp_number, p.beyond_table ? "≥ " : "",
                       p.max_wind_mps);
  };
  for (std::size_t i = 0; i < l3.intact.points.size(); ++i) {
    const double deg = l3.intact.points[i].direction_deg;
    const auto at = [deg](const std::vector<capability::CapabilityPoint>& v) {
      return *std::find_if(v.begin(), v.end(),
                           [deg](const auto& p) { return std::abs(p.direction_deg - deg) < 1e-6; });
    };
    t.rows.push_back({fmt::format("{:.0f}", deg), cell(at(l1.intact.points)),
                      cell(at(l1.worst->points)), cell(l3.intact.points[i]),
                      cell(l3.worst->points[i])});
  }
  return t;
}

}  // namespace

ReportSection capability_demo_section(const std::filesystem::path& campaign_dir,
                                      std::uint64_t seed) {
  ReportSection section{"DP capability (DNV-ST-0111)", "", ""};
  const std::filesystem::path dir = campaign_dir / "analysis";
  std::filesystem::create_directories(dir);
  CapabilityRequest q1;
  q1.failure = "worst";  // level3_report() takes the failures worst at level 1
  const CapabilityReport l1 = run_capability(q1);
  const CapabilityReport l3 = level3_report(l1, seed);
  io::write_json(dir / "capability-l1.json", to_json(l1));
  io::write_json(dir / "capability-l3.json", to_json(l3));
  write_rose(l1, dir / "capability-l1.svg");
  write_rose(l3, dir / "capability-l3.svg");
  const std::string head = fmt::format(
      "The virtual Gunnerus' DP capability number (and the strongest wind held) per direction "
      "of wind, waves and current off the bow, intact and for the worst single failure. Level 1: "
      "the standard's environment table, rated thrust, mean load × {} balanced exactly ({}). "
      "Level 3: the DP-controlled vessel in the simulator, {:.0f} s judged after {:.0f} s, "
      "footprint {} m and {} deg, seed {}; its failure cases are those worst somewhere at level "
      "1 ({}). Level 3 holds more than level 1 where the 25 % reserve on the current's load, "
      "which the table keeps at 0.75 m/s, uses up the thrust (docs/theory.md).",
      l1.dynamic_allowance, notation_text(l1), l3.time_domain->duration_s, l3.time_domain->settle_s,
      l3.time_domain->footprint_m, l3.time_domain->footprint_deg, seed, notation_text(l3));
  const report::Table t = summary_table(l1, l3);
  section.markdown = head + "\n\n" + report::render_markdown(t) + "\n";
  section.html = "<p>" + head + "</p>\n" + report::render_html(t);
  for (const char* name : {"capability-l1.svg", "capability-l3.svg"}) {
    section.markdown += fmt::format("![{}](analysis/{})\n", name, name);
    section.html += fmt::format("<p><img src=\"analysis/{}\" alt=\"{}\"></p>\n", name, name);
  }
  return section;
}

}  // namespace dynpos::analysis
