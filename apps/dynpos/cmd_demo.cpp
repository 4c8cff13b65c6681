// dynpos demo --out DIR: the main job on the built-in virtual Gunnerus — the whole test
// programme simulated, one folder per scenario, with the analyses as a report
// (analysis/demo.hpp).

#include <fmt/core.h>

#include <memory>

#include "commands.hpp"
#include "dynpos/analysis/demo.hpp"

namespace dynpos::cli {

void register_demo(CLI::App& app) {
  auto request = std::make_shared<analysis::DemoRequest>();
  CLI::App* sub = app.add_subcommand(
      "demo", "Run the whole virtual Gunnerus campaign and write a report folder");
  output_folder(sub->add_option("--out", request->out_dir, "Report folder (created if needed)"))
      ->capture_default_str();
  add_seed_option(*sub, request->seed, "Master seed; the same seed gives byte-identical files");
  sub->footer(
      "Writes DIR/index.html, DIR/summary.md, DIR/summary.json and DIR/<scenario>/{log.csv,"
      "truth.csv,truth.json} for every scenario in data/scenarios, and DIR/hybrid/: hybrid vs "
      "conventional integral action under an ice load and a mooring line snap (JSON + SVG). "
      "The other analyses of the logs join the report as they become available.");
  sub->callback([request] {
    request->validate();
    print_text(stdout, "{}", analysis::to_text(analysis::run_demo(*request)));
  });
}

}  // namespace dynpos::cli
