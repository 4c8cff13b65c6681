// dynpos demo --out DIR: the main job on the built-in virtual Gunnerus — the whole test
// programme simulated, one folder per scenario, with a summary report.

#include <fmt/core.h>

#include <filesystem>
#include <memory>

#include "commands.hpp"
#include "data_dir.hpp"
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
      "truth.json} for every scenario in data/scenarios. The analyses of the logs join the "
      "report as they become available.");
  sub->callback([opt] {
    const std::filesystem::path data = find_data_dir();
    const auto specs = load_campaign(data / "scenarios");
    const auto vessel = scenario::load_vessel_config(data / "vessels" / "gunnerus.toml");
    std::filesystem::create_directories(opt->out_dir);
    const auto runs = scenario::run_campaign(specs, vessel, opt->seed, opt->out_dir);
    print_campaign(runs, opt->out_dir);
  });
}

}  // namespace dynpos::cli
