// The demo report's section of hybrid against conventional integral action on the virtual
// Gunnerus: both sudden loads with the campaign's master seed (analysis/hybrid_vessel.hpp).

#include <fmt/core.h>

#include <filesystem>
#include <vector>

#include "dynpos/analysis/demo_sections.hpp"
#include "dynpos/analysis/hybrid_vessel.hpp"
#include "dynpos/io/json_writer.hpp"

namespace dynpos::analysis {

ReportSection hybrid_vessel_demo_section(const std::filesystem::path& campaign_dir,
                                         std::uint64_t seed) {
  ReportSection section{"Hybrid integral action on the virtual Gunnerus", "", ""};
  const std::filesystem::path dir = campaign_dir / "hybrid";
  for (const HybridLoad load : {HybridLoad::kIce, HybridLoad::kMooring}) {
    const HybridVesselReport r = run_hybrid_vessel({load, seed});
    // The plots, then the `--json` document, its plots named as the report links them
    // (relative to the report folder, so that the report is the same wherever it is written).
    std::vector<std::filesystem::path> links;
    for (const auto& p : write_figures(r, dir))
      links.push_back(std::filesystem::path("hybrid") / p.filename());
    io::write_json(dir / ("vessel_" + r.name + ".json"), to_json(r, links));
    const std::string head = fmt::format(
        "{} (seed {}): the load changes at {:.0f} s; DP controller (5.35)-(5.38) with "
        "continuous integral action vs hybrid integral action (jumps by (5.64)-(5.67)).",
        r.scenario_name, r.seed, r.comparison.t_load_s);
    section.markdown += head + "\n\n" + to_markdown(r) + "\n";
    section.html += "<p>" + head + "</p>\n" + to_html(r);
    for (const auto& link : links) {
      const std::string name = link.filename().string();
      section.markdown += fmt::format("![{}]({})\n", name, link.string());
      section.html += fmt::format("<p><img src=\"{}\" alt=\"{}\"></p>\n", link.string(), name);
    }
  }
  return section;
}

}  // namespace dynpos::analysis
