// Run a scenario of the virtual sea trial and read its truth: what an analysis of the log
// should find.
//
// The built-in forward surge step test (data/scenarios/surge-steps-forward.toml) is cut to its
// first step, a joystick surge lever 0 → 5 % at 20 s. The run returns the trial logger's log
// (sensors at their rates, logger units), the true states (SI) and the truth: the vessel's
// sensor lever arms and, per propeller step, the time constant and dead time of the model.

#include <fmt/core.h>

#include <exception>
#include <filesystem>
#include <string>

#include "dynpos/analysis/data_dir.hpp"
#include "dynpos/scenario/runner.hpp"

namespace {

void run() {
  using namespace dynpos;
  const std::filesystem::path data = analysis::find_data_dir();
  scenario::ScenarioSpec spec =
      scenario::load_scenario(data / "scenarios" / "surge-steps-forward.toml");
  spec.settle_s = 0.0;      // start at rest instead of drifting for 10 minutes first
  spec.set_duration(60.0);  // keep the first step only
  const scenario::VesselConfig vessel =
      scenario::load_vessel_config(data / "vessels" / "gunnerus.toml");

  // Deterministic: the same seed gives the same log, bit for bit.
  const scenario::ScenarioRun run = scenario::run_scenario(spec, vessel, /*seed=*/1);
  fmt::print("{}: {} log rows, {} channels, {} truth channels\n", spec.name, run.log.time().size(),
             run.log.channels().size(), run.truth_log.channels().size());

  // Lever arms in BODY (x forward, y starboard, z down) from the control origin [m].
  for (const auto& [sensor, arm] : run.truth.lever_arms) {
    fmt::print("lever arm {:6} ({:7.3f}, {:7.3f}, {:7.3f}) m\n", sensor, arm.x(), arm.y(), arm.z());
  }

  // Each step of each main propeller: the shaft speed and thrust responses as the model
  // defines them, first order plus dead time (thesis 2.29).
  for (const scenario::PropellerStepTruth& step : run.truth.propeller_steps) {
    fmt::print(
        "propeller {:4} step at {:.1f} s, {:.0f} -> {:.0f} rpm: shaft speed T = {:.2f} s, "
        "delay = {:.2f} s; thrust T = {:.2f} s, delay = {:.2f} s\n",
        step.thruster, step.t_s, 60.0 * step.n_from_rps, 60.0 * step.n_to_rps,
        step.shaft_speed.time_constant, step.shaft_speed.dead_time, step.thrust.time_constant,
        step.thrust.dead_time);
  }
}

}  // namespace

int main() {
  try {
    run();
    return 0;
  } catch (const std::exception& e) {
    fmt::print(stderr, "scenario_truth: {}\n", e.what());
    return 1;
  }
}
