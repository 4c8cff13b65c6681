#include "dynpos/scenario/trial_environment.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dynpos/core/angle.hpp"
#include "dynpos/scenario/vessel_plant.hpp"

namespace dynpos::scenario {
namespace {

using Plant = VesselPlant;

// A vessel whose weather does not vary: the environment's inputs have closed forms.
VesselConfig steady_vessel() {
  VesselConfig v;
  v.bias.std.setZero();
  v.current.speed_std_mps = 0.0;
  v.current.dir_std_rad = 0.0;
  v.wind.gust_std_fraction = 0.0;
  v.wind.dir_std_rad = 0.0;
  return v;
}

ScenarioSpec spec() {
  ScenarioSpec s;
  s.duration_s = 20.0;
  s.dt_s = 0.01;
  s.log_rate_hz = 10.0;
  s.settle_s = 2.0;
  s.environment.current_speed_mps = 0.5;
  s.environment.current_to_deg = 90.0;
  s.environment.wind_speed_mps = 10.0;
  s.environment.wind_from_deg = 0.0;
  s.environment.hs_m = 1.5;
  s.environment.tp_s = 7.0;
  s.loads = {{5.0, 8.0, -2.0e4, 1.0e4, 3.0e3}};
  return s;
}

TEST(TrialEnvironment, WritesCurrentWindDriftAndLoadsIntoTheHeldInput) {
  const VesselConfig vessel = steady_vessel();
  const TrialClock clock(spec());
  TrialEnvironment env(spec(), vessel, 1, clock);
  const Plant plant(vessel);
  const Eigen::VectorXd x = plant.initial_state(0.0);  // at rest, heading north
  Eigen::VectorXd u = Eigen::VectorXd::Constant(Plant::kInputSize, -1.0);
  const sim::Tick k_load = 200 + 600;  // scenario t = 6 s, inside the load's [5, 8) s
  for (sim::Tick k = 0; k <= k_load; ++k) env.step(k, x, u);
  // Current flowing east at its mean speed (no variation).
  EXPECT_NEAR(u[Plant::kCurrentNed], 0.0, 1e-12);
  EXPECT_NEAR(u[Plant::kCurrentNed + 1], 0.5, 1e-12);
  // Head wind and head sea at rest: the force is the wind's plus the mean drift, both astern.
  const Eigen::Vector3d expected =
      env.wind().force_b(0.0, Eigen::Vector2d::Zero()) + env.waves().drift_force_b(0.0);
  EXPECT_EQ(Eigen::Vector3d(u.segment<3>(Plant::kTauEnvBody)), expected);
  EXPECT_LT(expected.x(), 0.0);
  // No bias: the NED force is the load, switched on at scenario time 5 s.
  EXPECT_EQ(Eigen::Vector3d(u.segment<3>(Plant::kForceNed)), Eigen::Vector3d(-2.0e4, 1.0e4, 3.0e3));
  EXPECT_EQ(env.load_n(9.0), Eigen::Vector3d::Zero());
  // The actuator commands are not the environment's.
  EXPECT_EQ(u[Plant::kCmdPort], -1.0);
}

TEST(TrialEnvironment, WavesMoveOnTheLoggersTicksOnly) {
  const VesselConfig vessel = steady_vessel();
  const ScenarioSpec s = spec();
  const TrialClock clock(s);
  TrialEnvironment env(s, vessel, 3, clock);
  // The generator on its own: sample n of the log grid after n advances.
  model::SeaStateParams sea;
  sea.hs_m = s.environment.hs_m;
  sea.tp_s = s.environment.tp_s;
  sea.from_rad = core::deg_to_rad(s.environment.wave_from_deg);
  sea.components = s.environment.wave_components;
  model::WaveMotion reference(sea, vessel.waves, 3, clock.log_period_s());
  const Plant plant(vessel);
  const Eigen::VectorXd x = plant.initial_state(0.0);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(Plant::kInputSize);
  int samples = 0;
  for (sim::Tick k = 0; k <= 200 + 150; ++k) {
    env.step(k, x, u);
    if (!clock.logs_at(k)) continue;
    if (samples++ > 0) reference.advance();
    ASSERT_EQ(env.waves().motion(0.3).position, reference.motion(0.3).position) << k;
  }
  EXPECT_EQ(samples, 16);  // t = 0, 0.1, …, 1.5 s; none while settling
}

TEST(TrialEnvironment, SameSeedSameWeatherOtherSeedOther) {
  const VesselConfig vessel;  // with gusts, current variation and bias
  const ScenarioSpec s = spec();
  const TrialClock clock(s);
  TrialEnvironment a(s, vessel, 7, clock), b(s, vessel, 7, clock), c(s, vessel, 8, clock);
  const Plant plant(vessel);
  const Eigen::VectorXd x = plant.initial_state(0.0);
  Eigen::VectorXd ua = Eigen::VectorXd::Zero(Plant::kInputSize), ub = ua, uc = ua;
  for (sim::Tick k = 0; k < 500; ++k) {
    a.step(k, x, ua);
    b.step(k, x, ub);
    c.step(k, x, uc);
  }
  EXPECT_EQ(ua, ub);
  EXPECT_NE(ua, uc);
}

}  // namespace
}  // namespace dynpos::scenario
