// dynpos simulate SCENARIO --out DIR [--seed N] [--vessel FILE]: one virtual sea-trial run.

#include <fmt/core.h>

#include <cstdlib>
#include <filesystem>
#include <memory>

#include "commands.hpp"
#include "dynpos/analysis/data_dir.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/io/csv_writer.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/scenario/campaign.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::cli {

std::vector<scenario::ScenarioSpec> load_campaign(const std::filesystem::path& scenario_dir) {
  std::vector<scenario::ScenarioSpec> specs;
  for (const std::string& name : scenario::list_scenarios(scenario_dir)) {
    specs.push_back(scenario::load_scenario(scenario_dir / (name + ".toml")));
  }
  if (specs.empty()) {
    throw core::InputError({scenario_dir.string(), {}, {}, {}}, "no scenario files found");
  }
  return specs;
}

void print_campaign(const std::vector<scenario::RunSummary>& runs,
                    const std::filesystem::path& out_dir) {
  double simulated = 0.0, wall = 0.0;
  for (const scenario::RunSummary& r : runs) {
    fmt::print("{:<24} {:>6.0f} s simulated in {:5.2f} s  max {:5.2f} kn  {:8.0f} kJ\n", r.name,
               r.duration_s, r.wall_time_s, r.max_speed_mps * 3600.0 / 1852.0, r.energy_kJ);
    simulated += r.duration_s;
    wall += r.wall_time_s;
  }
  fmt::print("{} scenarios, {:.0f} s of sea trial in {:.1f} s\n", runs.size(), simulated, wall);
  fmt::print("report: {}\n", (out_dir / "index.html").string());
}

namespace {

struct SimulateOptions {
  std::string scenario;
  std::filesystem::path out_dir;
  std::uint64_t seed = 1;
  std::filesystem::path vessel_file;
  double duration_s = 0.0;   // 0 = the scenario's
  double log_rate_hz = 0.0;  // 0 = the scenario's
  bool list = false;
};

void run_simulate(const SimulateOptions& opt) {
  const std::filesystem::path data = analysis::find_data_dir();
  const std::filesystem::path scenario_dir = data / "scenarios";
  if (opt.list) {
    for (const std::string& name : scenario::list_scenarios(scenario_dir)) {
      const scenario::ScenarioSpec spec = scenario::load_scenario(scenario_dir / (name + ".toml"));
      fmt::print("{:<24} {}\n", name, spec.description);
    }
    return;
  }
  if (opt.scenario.empty()) {
    throw core::InputError({}, "no scenario given",
                           "name one, e.g. 'dynpos simulate "
                           "surge-steps-forward --out DIR' (--list shows all)");
  }
  if (opt.out_dir.empty()) {
    throw core::InputError({}, "no output folder given", "add --out DIR");
  }
  const std::filesystem::path vessel_file =
      opt.vessel_file.empty() ? data / "vessels" / "gunnerus.toml" : opt.vessel_file;
  if (opt.scenario == kCampaign) {
    std::vector<scenario::ScenarioSpec> specs = load_campaign(scenario_dir);
    for (scenario::ScenarioSpec& spec : specs) {
      if (opt.duration_s > 0.0) spec.set_duration(opt.duration_s);
      if (opt.log_rate_hz > 0.0) spec.log_rate_hz = opt.log_rate_hz;
      spec.validate();
    }
    const auto vessel = scenario::load_vessel_config(vessel_file);
    const auto runs = scenario::run_campaign(specs, vessel, opt.seed, opt.out_dir);
    print_campaign(runs, opt.out_dir);
    return;
  }
  scenario::ScenarioSpec spec =
      scenario::load_scenario(scenario::resolve_scenario(opt.scenario, scenario_dir));
  if (opt.duration_s > 0.0) spec.set_duration(opt.duration_s);
  if (opt.log_rate_hz > 0.0) spec.log_rate_hz = opt.log_rate_hz;
  spec.validate();
  const scenario::VesselConfig vessel = scenario::load_vessel_config(vessel_file);

  const scenario::ScenarioRun run = scenario::run_scenario(spec, vessel, opt.seed);

  scenario::write_scenario_run(run, opt.out_dir);
  fmt::print("simulated '{}' ({:.0f} s, seed {}): {} rows x {} channels\n", spec.name,
             spec.duration_s, opt.seed, run.log.size(), run.log.channels().size());
  fmt::print("wrote {}\n      {}\n      {}\n", (opt.out_dir / "log.csv").string(),
             (opt.out_dir / "truth.csv").string(), (opt.out_dir / "truth.json").string());
}

}  // namespace

void register_simulate(CLI::App& app) {
  auto opt = std::make_shared<SimulateOptions>();
  CLI::App* sub = app.add_subcommand(
      "simulate",
      "Run a virtual sea trial on the virtual R/V Gunnerus; write log.csv, truth.csv and "
      "truth.json");
  sub->add_option("scenario", opt->scenario,
                  "Scenario name in data/scenarios (e.g. surge-steps-forward), a .toml file, or "
                  "'campaign' for all of them (one folder each)");
  sub->add_option("--out", opt->out_dir, "Output folder (created if needed)");
  sub->add_option("--seed", opt->seed,
                  "Master seed (unsigned 64-bit); the same seed gives byte-identical output")
      ->capture_default_str();
  sub->add_option("--vessel", opt->vessel_file,
                  "Vessel file (default: data/vessels/gunnerus.toml)");
  sub->add_option("--duration", opt->duration_s, "Override the run length [s]")
      ->check(CLI::PositiveNumber);
  sub->add_option("--log-rate", opt->log_rate_hz, "Override the log rate [Hz]")
      ->check(CLI::PositiveNumber);
  sub->add_flag("--list", opt->list, "List the built-in scenarios and exit");
  sub->footer(
      "Files: DIR/log.csv (the trial logger: every sensor at its rate, blank between samples,\n"
      "commands and setpoints), DIR/truth.csv (the true motion, SI), DIR/truth.json (parameters,\n"
      "lever arms, command times, true time constants). Columns: docs/log-format.md.");
  sub->callback([opt] { run_simulate(*opt); });
}

}  // namespace dynpos::cli
