#include "dynpos/scenario/runner.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "dynpos/core/error.hpp"
#include "dynpos/io/csv_reader.hpp"
#include "dynpos/io/csv_writer.hpp"
#include "dynpos/scenario/campaign.hpp"
#include "dynpos/scenario/vessel_plant.hpp"

namespace dynpos::scenario {
namespace {

// A calm-water vessel: no bias, no current/wind variation, so closed forms apply.
VesselConfig calm_vessel() {
  VesselConfig v;
  v.bias.std.setZero();
  v.current.speed_std_mps = 0.0;
  v.current.dir_std_rad = 0.0;
  v.wind.gust_std_fraction = 0.0;
  v.wind.dir_std_rad = 0.0;
  return v;
}

ScenarioSpec surge_step(double pct, double duration) {
  ScenarioSpec s;
  s.name = "test-surge";
  s.duration_s = duration;
  s.log_rate_hz = 10.0;
  s.joystick = {{10.0, pct, 0.0, 0.0}};
  return s;
}

ScenarioSpec rough(double duration) {
  ScenarioSpec s = surge_step(30.0, duration);
  s.joystick.push_back({20.0, 30.0, 40.0, 10.0});
  s.environment.hs_m = 2.0;
  s.environment.tp_s = 7.0;
  s.environment.wind_speed_mps = 10.0;
  s.environment.current_speed_mps = 0.3;
  return s;
}

bool bit_identical(const core::Log& a, const core::Log& b) {
  if (a.size() != b.size() || a.channels().size() != b.channels().size()) return false;
  if (std::memcmp(a.time().data(), b.time().data(), a.size() * sizeof(double)) != 0) return false;
  for (std::size_t c = 0; c < a.channels().size(); ++c) {
    if (std::memcmp(a.channels()[c].values.data(), b.channels()[c].values.data(),
                    a.size() * sizeof(double)) != 0) {
      return false;
    }
  }
  return true;
}

// A control rate whose period is not a whole number of the scenario's steps (3 Hz on a 0.01 s
// grid) was a std::invalid_argument of the simulator naming neither the file nor the key.
TEST(RunScenario, AControlRateOffTheTimeGridNamesTheVesselFileAndKey) {
  VesselConfig v = calm_vessel();
  v.source = "my_vessel.toml";
  v.joystick.control_rate_hz = 3.0;
  try {
    run_scenario(surge_step(10.0, 12.0), v, 1);
    ADD_FAILURE() << "expected a core::InputError";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.where().file, "my_vessel.toml");
    EXPECT_EQ(e.where().column_name, "joystick.control_rate_hz");
    EXPECT_NE(std::string(e.what()).find("3 Hz"), std::string::npos) << e.what();
  }
  v.joystick.control_rate_hz = 4.0;  // 0.25 s: 25 steps
  EXPECT_NO_THROW(run_scenario(surge_step(10.0, 12.0), v, 1));
}

TEST(RunScenario, SameSeedBitIdenticalOtherSeedDifferent) {
  const VesselConfig v;
  const ScenarioRun a = run_scenario(rough(60.0), v, 11);
  const ScenarioRun b = run_scenario(rough(60.0), v, 11);
  const ScenarioRun c = run_scenario(rough(60.0), v, 12);
  EXPECT_TRUE(bit_identical(a.log, b.log));
  EXPECT_EQ(to_json(a.truth).dump(), to_json(b.truth).dump());
  // Another seed: every sensor channel differs (its noise and the weather it sees), and so do
  // the allocation's shaft speeds, thrusts and rudder angles (they depend on the inflow); the
  // joystick's lever and demand, which the scenario fixes, do not.
  ASSERT_EQ(a.log.channels().size(), c.log.channels().size());
  for (std::size_t k = 0; k < a.log.channels().size(); ++k) {
    const core::Channel& ca = a.log.channels()[k];
    const bool commanded = ca.name.starts_with("lever.") || ca.name == "command.surge" ||
                           ca.name == "command.sway" || ca.name == "command.yaw" ||
                           ca.name.starts_with("setpoint.");
    const bool same = std::memcmp(ca.values.data(), c.log.channels()[k].values.data(),
                                  a.log.size() * sizeof(double)) == 0;
    EXPECT_EQ(same, commanded) << ca.name;
  }
}

TEST(RunScenario, LogHasOneRowPerLogPeriodIncludingBothEnds) {
  const ScenarioRun run = run_scenario(surge_step(20.0, 30.0), calm_vessel(), 1);
  ASSERT_EQ(run.truth_log.size(), 301u);
  EXPECT_EQ(run.truth_log.time().front(), 0.0);
  EXPECT_EQ(run.truth_log.time().back(), 30.0);  // t = k·dt by multiplication: exact
  for (const char* name : {"north", "heading", "rpm.stb", "thrust.port", "power.stb", "r"}) {
    EXPECT_TRUE(run.truth_log.has(name)) << name;
  }
}

TEST(RunScenario, SteadySurgeMatchesThrustMapAndHullDamping) {
  VesselConfig v = calm_vessel();
  // Without rudder profile drag the surge balance is exactly thrust = hull damping (2.8).
  v.rudder.drag_zero = 0.0;
  const ScenarioRun run = run_scenario(surge_step(40.0, 900.0), v, 3);
  const auto& n = run.truth_log.values("rpm.stb");
  const auto& thrust = run.truth_log.values("thrust.stb");
  const auto& u = run.truth_log.values("u");
  const double c_fwd = v.propeller.rho * v.propeller.kt_forward * std::pow(v.propeller.diameter, 4);
  // Simulated thrust vs the analytic map (3.17), T = c·n|n|: same formula, so to rounding.
  EXPECT_NEAR(thrust.back(), c_fwd * n.back() * n.back(), 1e-9 * thrust.back());
  // A 40 % surge lever demands 0.4^e of max_surge_N (the lever curve); each propeller gives
  // half of it, reached in steady state.
  const double demand_N = std::pow(0.4, v.joystick.lever_exponent) * v.joystick.max_surge_N;
  EXPECT_NEAR(thrust.back(), 0.5 * demand_N, 1e-3 * thrust.back());
  // In still air the superstructure meets a head wind of −u: the speed solves (2.8) with the
  // air drag ½ρ_a·c_x·A_F·u² added to the quadratic damping. 890 s after the step is > 30
  // linearised time constants (≈ 25 s at this speed), so the transient is below 1e-6.
  const double a = v.hull.x_uu_Ns2_m2 + 0.5 * v.wind.rho_air * v.wind.cx * v.wind.frontal_area_m2;
  const double b = v.hull.x_u_Ns_m;
  const double expected = (-b + std::sqrt(b * b + 4.0 * a * 2.0 * thrust.back())) / (2.0 * a);
  EXPECT_NEAR(u.back(), expected, 1e-5 * expected);
}

TEST(RunScenario, TruthRecordsCommandsAndPropellerStepTimeConstants) {
  const ScenarioRun run = run_scenario(surge_step(80.0, 40.0), calm_vessel(), 1);
  ASSERT_EQ(run.truth.commands.size(), 1u);
  EXPECT_EQ(run.truth.commands[0].t_s, 10.0);
  // Both propellers step (port first), from the same model and, straight ahead, to the same
  // shaft speed up to rounding: the same truth to 1e-9 s.
  ASSERT_EQ(run.truth.propeller_steps.size(), 2u);
  const PropellerStepTruth& port = run.truth.propeller_steps[0];
  const PropellerStepTruth& step = run.truth.propeller_steps[1];
  EXPECT_EQ(port.thruster, "port");
  EXPECT_NEAR(port.shaft_speed.time_constant, step.shaft_speed.time_constant, 1e-9);
  EXPECT_NEAR(port.thrust.time_constant, step.thrust.time_constant, 1e-9);
  EXPECT_EQ(step.thruster, "stb");
  const double t_n = step.shaft_speed.time_constant;
  const double d_n = step.shaft_speed.dead_time;
  // DESIGN.md targets from tables 3.23–3.29: T_n 0.5–5.5 s, δ_n 1.2–3.3 s.
  EXPECT_GE(t_n, 0.5);
  EXPECT_LE(t_n, 5.5);
  EXPECT_GE(d_n, 1.2);
  EXPECT_LE(d_n, 3.3);
  // The logged shaft speed follows that truth: still at rest before step + dead time.
  const auto& n = run.truth_log.values("rpm.stb");
  const std::size_t before = 10 * 10 + 10;  // t = 11 s < 10 s + 1.3 s dead time
  EXPECT_EQ(n[before], 0.0);
  EXPECT_GT(n.back(), 0.9 * step.n_to_rps);
  EXPECT_GT(run.truth.time_constants.nomoto_3kn.Tr_s, 0.0);
}

TEST(RunScenario, SettlingStartsTheLogDriftingWithTheCurrent) {
  // A 0.2 m/s current along the bow, no wind or waves: without settling the log starts at rest
  // over ground; after 600 s of settling the vessel moves with the water, held back only by the
  // still air: X_u·(0.2 − u) = ½ρ_a·c_x·A_F·u² gives the steady u_ss. The relative speed
  // decays at least as fast as with the linear damping alone, T = (m − X_u̇)/X_u ≈ 97 s, so
  // u(0) lies in (u_ss − u_ss·e^(−600/T), u_ss): within 4·10⁻⁴ m/s below it.
  ScenarioSpec s = surge_step(80.0, 40.0);
  s.environment.current_speed_mps = 0.2;
  const VesselConfig v = calm_vessel();
  const ScenarioRun at_rest = run_scenario(s, v, 1);
  EXPECT_EQ(at_rest.truth_log.values("u").front(), 0.0);
  s.settle_s = 600.0;
  const ScenarioRun settled = run_scenario(s, v, 1);
  const double a = 0.5 * v.wind.rho_air * v.wind.cx * v.wind.frontal_area_m2;
  const double b = v.hull.x_u_Ns_m;
  const double u_ss = (-b + std::sqrt(b * b + 4.0 * a * b * 0.2)) / (2.0 * a);
  const double t_lin = (v.hull.mass_kg + v.hull.x_udot_kg) / b;
  const double u0 = settled.truth_log.values("u").front();
  EXPECT_LT(u0, u_ss);
  EXPECT_GT(u0, u_ss * (1.0 - std::exp(-600.0 / t_lin)));
  // Scenario time is kept: the same rows from t = 0, the command at its time, and the shaft
  // still at rest 1 s later (dead time 1.3 s).
  EXPECT_EQ(settled.truth_log.time(), at_rest.truth_log.time());  // to the bit: (k − k₀)·dt
  EXPECT_EQ(settled.log.time(), at_rest.log.time());
  ASSERT_EQ(settled.truth.commands.size(), 1u);
  EXPECT_EQ(settled.truth.commands[0].t_s, 10.0);
  EXPECT_EQ(settled.truth.propeller_steps[0].t_s, 10.0);
  EXPECT_EQ(settled.truth_log.values("rpm.stb")[10 * 10 + 10], 0.0);
  EXPECT_EQ(settled.truth.scenario.settle_s, 600.0);
}

TEST(RunScenario, SwayDemandMovesTheVesselToStarboard) {
  ScenarioSpec s;
  s.name = "sway";
  s.duration_s = 120.0;
  s.joystick = {{5.0, 0.0, 60.0, 0.0}};
  const ScenarioRun run = run_scenario(s, calm_vessel(), 1);
  EXPECT_GT(run.truth_log.values("east").back(), 2.0);
  EXPECT_GT(run.truth_log.values("thrust.tunnel").back(), 0.0);
  // The allocation met the demand (no unmet force or moment) throughout.
  for (const double unmet : run.truth.allocation_unmet_max) EXPECT_LT(unmet, 1.0);
}

TEST(RunScenario, StepLoadPushesTheVesselOnlyWhileOn) {
  ScenarioSpec s;
  s.name = "ice";
  s.duration_s = 120.0;
  s.loads = {{10.0, 60.0, 0.0, 20e3, 0.0}};  // 20 kN towards east from 10 s to 60 s
  const ScenarioRun run = run_scenario(s, calm_vessel(), 1);
  const auto& east = run.truth_log.values("east");
  const auto& v = run.truth_log.values("v");
  EXPECT_EQ(east[100], 0.0);    // nothing before the load (calm, no thrust)
  EXPECT_GT(v[600], 0.1);       // drifting east (sway at heading 0) when it switches off
  EXPECT_LT(v.back(), v[600]);  // decelerating after it is gone
  EXPECT_EQ(run.truth.scenario.loads.size(), 1u);
}

TEST(RunScenario, StarboardRudderTurnsToStarboardWithNomotoTruth) {
  ScenarioSpec s;
  s.name = "rudder";
  s.duration_s = 80.0;
  s.initial_surge_mps = 3.0;
  s.joystick = {{0.0, 51.0, 0.0, 0.0}};  // 26 % of full thrust (lever curve): ≈ 3 m/s
  s.rudder = {{10.0, 20.0, false}};
  const ScenarioRun run = run_scenario(s, calm_vessel(), 1);
  const auto& r = run.truth_log.values("r");
  EXPECT_NEAR(r[90], 0.0, 1e-6);  // before the rudder moves (command at 10 s + dead time)
  EXPECT_GT(r.back(), 0.005);     // steady starboard turn, > 0.3 °/s
  EXPECT_LT(run.truth_log.values("roll").back(), 0.0);  // heeling outwards, to port
  ASSERT_EQ(run.truth.rudder_steps.size(), 1u);
  const RudderStepTruth& step = run.truth.rudder_steps[0];
  EXPECT_NEAR(step.to_deg, 20.0, 1e-12);
  // Nomoto T_r at ≈ 6 kn: table 3.31 gives 2.9–3.0 s; the model's truth lies within ±0.5 s.
  ASSERT_TRUE(step.nomoto.has_value());
  EXPECT_NEAR(step.nomoto->Tr_s, 3.0, 0.5);
}

TEST(RunScenario, TruthJsonReadsBackAsTheRunsTruth) {
  ScenarioSpec s;
  s.name = "dp-hybrid";
  s.duration_s = 60.0;
  s.setpoints = {{0.0, 0.0, 0.0, 0.0, "hold"}, {-1.0, 3.0, 0.0, 0.0, "ahead"}};
  s.loads = {{10.0, 1e300, -2.0e4, 0.0, 0.0}};
  s.hybrid_integral = hybrid::IntegralJumpParams{};
  const ScenarioRun run = run_scenario(s, VesselConfig{}, 3);
  ASSERT_TRUE(run.truth.hybrid.has_value());
  EXPECT_FALSE(run.truth.hybrid->jump_times_s.empty());  // the load makes the rule jump
  ASSERT_EQ(run.truth.setpoints.size(), 2u);
  EXPECT_TRUE(run.truth.setpoints[0].t_reached_s.has_value());
  const auto dir = std::filesystem::temp_directory_path() / "dynpos_runner_truth_test";
  write_scenario_run(run, dir);
  const TrialTruth back = read_trial_truth(dir / "truth.json");
  EXPECT_EQ(to_json(back).dump(), to_json(run.truth).dump());
  EXPECT_EQ(back.hybrid->jump_times_s, run.truth.hybrid->jump_times_s);
  std::filesystem::remove_all(dir);
}

TEST(RunScenario, CsvRoundTripIsExact) {
  const ScenarioRun run = run_scenario(rough(20.0), VesselConfig{}, 5);
  const auto dir = std::filesystem::temp_directory_path() / "dynpos_runner_test";
  std::filesystem::create_directories(dir);
  const auto file = dir / "log.csv";
  io::write_csv(file, run.truth_log);
  const core::Log back = io::read_csv_all(file);
  ASSERT_EQ(back.size(), run.truth_log.size());
  for (const core::Channel& c : run.truth_log.channels()) {
    ASSERT_TRUE(back.has(c.name)) << c.name;
    const auto& b = back.values(c.name);
    for (std::size_t i = 0; i < c.values.size(); ++i) {
      // rps is read back as rps (SI); every other unit is already SI: exact round trip, and
      // a missing value (setpoints outside DP) stays missing.
      if (std::isnan(c.values[i])) {
        ASSERT_TRUE(std::isnan(b[i])) << c.name << " row " << i;
      } else {
        ASSERT_EQ(b[i], c.values[i]) << c.name << " row " << i;
      }
    }
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace dynpos::scenario
