#include "dynpos/scenario/vessel_sample.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dynpos/core/angle.hpp"

namespace dynpos::scenario {
namespace {

using Plant = VesselPlant;
using model::Hull;

ScenarioSpec calm_spec() {
  ScenarioSpec s;
  s.duration_s = 10.0;
  return s;
}

TEST(VesselSampler, CalmWaterSampleIsThePlantsLowFrequencyState) {
  const VesselConfig vessel;
  const Plant plant(vessel);
  const ScenarioSpec spec = calm_spec();  // no waves, no wind, no current
  const TrialClock clock(spec);
  TrialEnvironment env(spec, vessel, 1, clock);
  Eigen::VectorXd x = plant.initial_state(core::deg_to_rad(30.0));
  x[Plant::kHull + Hull::kNorth] = 12.0;
  x[Plant::kHull + Hull::kEast] = -4.0;
  x[Plant::kHull + Hull::kSurge] = 2.0;
  x[Plant::kRudderPort] = 0.1;
  x[Plant::kRudderStb] = -0.2;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(Plant::kInputSize);
  env.step(0, x, u);
  u.segment<2>(Plant::kCurrentNed) = Eigen::Vector2d(0.25, 0.0);  // a current, held in u
  VesselSampler sampler(plant, env);
  const VesselSample& s = sampler.sample(0.0, x, u);
  EXPECT_EQ(s.motion.p_n, Eigen::Vector3d(12.0, -4.0, 0.0));
  EXPECT_NEAR(s.motion.theta.z(), core::deg_to_rad(30.0), 1e-15);
  EXPECT_NEAR(s.motion.v_b().x(), 2.0, 1e-12);
  EXPECT_NEAR(s.motion.v_b().y(), 0.0, 1e-12);
  EXPECT_EQ(s.rudder_rad[0], 0.1);
  EXPECT_EQ(s.rudder_rad[1], -0.2);
  EXPECT_EQ(s.current_n, Eigen::Vector2d(0.25, 0.0));
  // The actuators' outputs are the plant's at this state and current.
  const ActuatorState a = plant.actuators(x, s.current_n);
  EXPECT_EQ(s.thrust_N[0], a.port.thrust);
  EXPECT_EQ(s.power_W[2], a.tunnel.power);
  EXPECT_EQ(s.shaft_speed_rps[1], a.stb.shaft_speed);
  EXPECT_EQ(s.wind_speed_mps, 0.0);
  EXPECT_EQ(s.load_n, Eigen::Vector3d::Zero());
}

TEST(VesselSampler, WavesAddTheirMotionAndWindDirectionIsWrapped) {
  const VesselConfig vessel;
  const Plant plant(vessel);
  ScenarioSpec spec = calm_spec();
  spec.environment.hs_m = 2.0;
  spec.environment.wind_speed_mps = 8.0;
  spec.environment.wind_from_deg = -10.0;  // 350°
  spec.loads = {{0.0, 1e300, 1.0e4, 0.0, 0.0}};
  const TrialClock clock(spec);
  TrialEnvironment env(spec, vessel, 1, clock);
  const Eigen::VectorXd x = plant.initial_state(0.0);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(Plant::kInputSize);
  env.step(0, x, u);
  VesselSampler sampler(plant, env);
  const VesselSample& s = sampler.sample(0.0, x, u);
  EXPECT_GT(s.motion.p_n.norm(), 0.0);  // the hull at rest still moves with the waves
  EXPECT_GE(s.wind_from_rad, 0.0);
  EXPECT_LT(s.wind_from_rad, 2.0 * M_PI);
  EXPECT_EQ(s.wind_speed_mps, env.wind().speed_mps());
  EXPECT_EQ(s.load_n, Eigen::Vector3d(1.0e4, 0.0, 0.0));
}

}  // namespace
}  // namespace dynpos::scenario
