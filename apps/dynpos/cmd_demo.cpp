// dynpos demo --out DIR: the main job on the built-in virtual Gunnerus — the whole test
// programme simulated, one folder per scenario, with a summary report.

#include <fmt/core.h>

#include <filesystem>
#include <memory>
#include <vector>

#include "commands.hpp"
#include "dynpos/analysis/data_dir.hpp"
#include "dynpos/analysis/demo_sections.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/scenario/campaign.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::cli {

void register_demo(CLI::App& app) {
  struct DemoOptions {
    std::filesystem::path out_dir = "dynpos-demo";
    std::uint64_t seed = 1;
  };
  auto opt = std::make_shared<DemoOptions>();
  CLI::App* sub = app.add_subcommand(
      "demo", "Run the whole virtual Gunnerus campaign and write a report folder");
  sub->add_option("--out", opt->out_dir, "Report folder (created if needed)")
      ->capture_default_str();
  sub->add_option("--seed", opt->seed, "Master seed; the same seed gives byte-identical files")
      ->capture_default_str();
  sub->footer(
      "Writes DIR/index.html, DIR/summary.md, DIR/summary.json and DIR/<scenario>/{log.csv,"
      "truth.csv,truth.json} for every scenario in data/scenarios, and DIR/hybrid/: hybrid vs "
      "conventional integral action under an ice load and a mooring line snap (JSON + SVG). "
      "The other analyses of the logs join the report as they become available.");
  sub->callback([opt] {
    const std::filesystem::path data = analysis::find_data_dir();
    const auto specs = load_campaign(data / "scenarios");
    const auto vessel = scenario::load_vessel_config(data / "vessels" / "gunnerus.toml");
    std::filesystem::create_directories(opt->out_dir);
    const auto runs = scenario::run_campaign(specs, vessel, opt->seed, opt->out_dir);
    // Hybrid integral action on the full vessel under both sudden loads (thesis ch. 5).
    scenario::ReportSection hybrid{"Hybrid integral action on the virtual Gunnerus", "", ""};
    const std::filesystem::path hybrid_dir = opt->out_dir / "hybrid";
    for (const char* load : {"ice", "mooring"}) {
      const HybridVesselResult r = run_hybrid_vessel(load, opt->seed);
      const auto plots = write_hybrid_vessel_plots(r, hybrid_dir);
      io::write_json((hybrid_dir / (std::string("vessel_") + load + ".json")).string(),
                     hybrid_vessel_json(r));
      const std::string head = fmt::format(
          "{} (seed {}): the load changes at {:.0f} s; DP controller (5.35)-(5.38) with "
          "continuous integral action vs hybrid integral action (jumps by (5.64)-(5.67)).",
          r.scenario_name, r.seed, r.comparison.t_load_s);
      hybrid.markdown += head + "\n\n" + hybrid_vessel_table(r, TableFormat::kMarkdown) + "\n";
      hybrid.html += "<p>" + head + "</p>\n" + hybrid_vessel_table(r, TableFormat::kHtml);
      for (const auto& p : plots) {
        const std::string rel = "hybrid/" + p.filename().string();
        hybrid.markdown += fmt::format("![{}]({})\n", p.filename().string(), rel);
        hybrid.html +=
            fmt::format("<p><img src=\"{}\" alt=\"{}\"></p>\n", rel, p.filename().string());
      }
    }
    std::vector<scenario::ReportSection> sections;
    for (auto* section_of :
         {&analysis::step_demo_section, &analysis::agility_demo_section,
          &analysis::four_corner_demo_section, &analysis::station_keeping_demo_section,
          &analysis::leverarm_gnss_demo_section, &analysis::leverarm_mru_demo_section}) {
      scenario::ReportSection section = (*section_of)(opt->out_dir);
      if (!section.title.empty()) sections.push_back(std::move(section));
    }
    sections.push_back(std::move(hybrid));
    scenario::write_campaign_report(runs, vessel, opt->seed, opt->out_dir, sections);
    print_campaign(runs, opt->out_dir);
  });
}

}  // namespace dynpos::cli
