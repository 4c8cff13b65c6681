// dynpos simulate SCENARIO --out DIR [--seed N] [--vessel FILE]: one virtual sea-trial run, or
// the whole campaign (analysis/simulate.hpp).

#include <fmt/core.h>

#include <memory>

#include "commands.hpp"
#include "dynpos/analysis/simulate.hpp"

namespace dynpos::cli {

void register_simulate(CLI::App& app) {
  auto request = std::make_shared<analysis::SimulateRequest>();
  CLI::App* sub = app.add_subcommand(
      "simulate",
      "Run a virtual sea trial on the virtual R/V Gunnerus; write log.csv, truth.csv and "
      "truth.json");
  sub->add_option("scenario", request->scenario,
                  "Scenario name in data/scenarios (e.g. surge-steps-forward), a .toml file, or "
                  "'campaign' for all of them (one folder each)");
  output_folder(sub->add_option("--out", request->out_dir, "Output folder (created if needed)"));
  add_seed_option(*sub, request->seed,
                  "Master seed (unsigned 64-bit); the same seed gives byte-identical output");
  sub->add_option("--vessel", request->vessel_file,
                  "Vessel file (default: data/vessels/gunnerus.toml)");
  // The library checks the values (SimulateRequest::validate); the type names say the range.
  sub->add_option("--duration", request->duration_s, "Override the run length [s]")
      ->type_name("FLOAT:POSITIVE");
  sub->add_option("--log-rate", request->log_rate_hz, "Override the log rate [Hz]")
      ->type_name("FLOAT:POSITIVE");
  sub->add_option("--observer", request->observer,
                  "DP scenarios: what the DP controller runs on: ideal (the true low-frequency "
                  "motion), passive, ekf, or raw (the measurements unfiltered)")
      ->type_name("NAME");
  sub->add_flag("--list", request->list, "List the built-in scenarios and exit");
  sub->add_option("--jobs", request->jobs,
                  "Campaign: scenarios run at once (default 0: every core); the files do not "
                  "depend on it")
      ->check(CLI::Range(0u, 256u));
  sub->footer(
      "Files: DIR/log.csv (the trial logger: every sensor at its rate, blank between samples,\n"
      "commands and setpoints), DIR/truth.csv (the true motion, SI), DIR/truth.json (parameters,\n"
      "lever arms, command times, true time constants). Columns: docs/log-format.md.");
  sub->callback([request] {
    request->validate();
    print_text(stdout, "{}", analysis::to_text(analysis::run_simulate(*request)));
  });
}

}  // namespace dynpos::cli
