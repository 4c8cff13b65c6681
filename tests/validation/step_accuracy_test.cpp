// Step identification on the virtual sea trial, checked against its ground truth: the shaft
// speed and thrust time constants identified from the trial logger's columns (with their noise,
// quantisation and the tunnel/propeller feedback as logged) must lie within 15 % of the truth
// written to truth.json. The truth is defined by Smith's two-point method on the noise-free
// actuator response (model/fopdt_truth.hpp), so Smith's method is the one compared here.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "../source_dir.hpp"
#include "dynpos/ident/fopdt_fit.hpp"
#include "dynpos/ident/step_detector.hpp"
#include "dynpos/io/column_map.hpp"
#include "dynpos/io/csv_reader.hpp"
#include "dynpos/scenario/campaign.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/trial_truth.hpp"

namespace dynpos {
namespace {

const std::filesystem::path kSource = DYNPOS_SOURCE_DIR;

struct TrialRun {
  std::filesystem::path dir;
  scenario::TrialTruth truth;
};

TrialRun simulate(const std::string& name, std::uint64_t seed) {
  const scenario::ScenarioSpec spec =
      scenario::load_scenario(kSource / "data" / "scenarios" / (name + ".toml"));
  const scenario::VesselConfig vessel =
      scenario::load_vessel_config(kSource / "data" / "vessels" / "gunnerus.toml");
  TrialRun out;
  out.dir = std::filesystem::temp_directory_path() /
            ("dynpos_step_accuracy_" + name + "_" + std::to_string(seed));
  scenario::write_scenario_run(scenario::run_scenario(spec, vessel, seed), out.dir);
  out.truth = scenario::read_trial_truth(out.dir / "truth.json");
  return out;
}

struct Identified {
  double t_step;
  double time_constant_s;
};

std::vector<Identified> identify(const std::filesystem::path& log, const std::string& input,
                                 const std::string& output) {
  io::ColumnMap map;
  map.set_column("time", "time");
  map.set_column("input", input);
  map.set_column("output", output);
  const core::Log l = io::read_csv(log, map);
  const auto steps = ident::detect_steps(l.time(), l.values("input")).steps;
  ident::FopdtFitOptions f;
  f.method = ident::FopdtMethod::kSmith;
  std::vector<Identified> out;
  for (const ident::Step& s : steps) {
    const auto r = ident::fit_fopdt(l.time(), l.values("output"), s, f);
    out.push_back({s.t_step, r.time_constant ? r.time_constant->value : std::nan("")});
  }
  return out;
}

// Shaft speed change [rps] from which a step's T is compared: 12 rpm, 60 times the shaft
// pickup's noise (0.2 rpm). The smaller steps of the programme (0–5 … 15–20 % of the lever,
// 9 rpm each with the lever curve) are found and timed, but at the 10 Hz log rate their Smith
// crossings, one or two samples apart for T ≈ 0.55 s, move with the noise by up to a quarter
// of T (measured: 0.68 s against 0.55 s). The thesis, too, left out or flagged the small steps'
// thruster fits (tables 3.23 and 3.25).
constexpr double kComparedStepRps = 0.2;

// The truth of one quantity ("shaft_speed" or "thrust") of a propeller step.
const model::FopdtTruth& fopdt_of(const scenario::PropellerStepTruth& step,
                                  const std::string& quantity) {
  if (quantity == "shaft_speed") return step.shaft_speed;
  if (quantity == "thrust") return step.thrust;
  throw std::invalid_argument("no propeller step truth '" + quantity + "'");
}

// For every propeller step of truth.json, the identified step nearest in time (the logger times
// the command within one sample) and, for steps of at least kComparedStepRps, its T against the
// truth. Tolerance 15 % (the issue's).
void expect_within_truth(const TrialRun& run, const std::string& thruster,
                         const std::string& quantity, const std::string& output_column,
                         int min_compared) {
  const auto found = identify(run.dir / "log.csv", "command.rpm." + thruster, output_column);
  int compared = 0;
  for (const scenario::PropellerStepTruth& step : run.truth.propeller_steps) {
    if (step.thruster != thruster) continue;
    const double t_step = step.t_s;
    const double truth = fopdt_of(step, quantity).time_constant;
    const Identified* nearest = nullptr;
    for (const Identified& f : found) {
      if (nearest == nullptr || std::abs(f.t_step - t_step) < std::abs(nearest->t_step - t_step)) {
        nearest = &f;
      }
    }
    ASSERT_NE(nearest, nullptr) << "no step found near " << t_step << " s";
    EXPECT_NEAR(nearest->t_step, t_step, 0.5) << quantity << " step at " << t_step << " s";
    const double change_rps = std::abs(step.n_to_rps - step.n_from_rps);
    if (change_rps < kComparedStepRps) continue;
    EXPECT_NEAR(nearest->time_constant_s, truth, 0.15 * truth)
        << thruster << " " << quantity << " step at " << t_step << " s";
    ++compared;
  }
  EXPECT_GE(compared, min_compared) << "too few propeller steps compared";
}

TEST(StepAccuracy, SurgeForwardShaftSpeedAndThrustWithin15PercentOfTruth) {
  const TrialRun run = simulate("surge-steps-forward", 1);
  // 15–25 %, 25–40 %, 40–0 %, 0–80 % and 80–0 % are 0.3 rps or more.
  expect_within_truth(run, "stb", "shaft_speed", "rpm.stb", 5);
  expect_within_truth(run, "stb", "thrust", "thrust.stb", 5);
  std::filesystem::remove_all(run.dir);
}

TEST(StepAccuracy, SurgeBackwardShaftSpeedAndThrustWithin15PercentOfTruth) {
  const TrialRun run = simulate("surge-steps-backward", 2);
  // 20–0 %, 0–40 % and 40–0 % are 0.6 rps or more.
  expect_within_truth(run, "stb", "shaft_speed", "rpm.stb", 3);
  expect_within_truth(run, "stb", "thrust", "thrust.stb", 3);
  std::filesystem::remove_all(run.dir);
}

}  // namespace
}  // namespace dynpos
