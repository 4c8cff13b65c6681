// The thrust from the actuators' feedback against the simulator's own force of the same
// actuators at rest in the water.

#include "dynpos/scenario/thrust_feedback.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "dynpos/core/angle.hpp"
#include "dynpos/scenario/vessel_plant.hpp"

namespace dynpos::scenario {
namespace {

using Plant = VesselPlant;

void expect_same_tau(const Eigen::Vector3d& got, const Eigen::Vector3d& want) {
  EXPECT_NEAR(got.x(), want.x(), 1e-9 * std::max(1.0, want.norm()));
  EXPECT_NEAR(got.y(), want.y(), 1e-9 * std::max(1.0, want.norm()));
  EXPECT_NEAR(got.z(), want.z(), 1e-9 * std::max(1.0, want.norm()));
}

model::ThrusterUnit unit(const char* name, model::UnitType type, double x_m, double y_m,
                         double ahead_N, double astern_N) {
  model::ThrusterUnit u;
  u.name = name;
  u.type = type;
  u.x_m = x_m;
  u.y_m = y_m;
  u.max_thrust_N = ahead_N;
  u.max_reverse_thrust_N = astern_N;
  return u;
}

TEST(ThrustFeedback, TheModelsUnitsGiveTheSimulatorsForceAtRest) {
  const VesselConfig vessel;  // the 2014 Gunnerus
  const ThrustFeedback feedback(vessel);
  ASSERT_EQ(feedback.channels().size(), 3u);
  EXPECT_EQ(feedback.channels()[0].angle_role, "rudder.port");
  EXPECT_EQ(feedback.channels()[2].thrust_role, "thrust.tunnel");
  EXPECT_EQ(feedback.channels()[2].angle_role, "");
  const Plant plant(vessel);
  // Ahead on one side, astern on the other (no slipstream over that rudder), both rudders over.
  for (const double heading : {0.0, 2.0}) {
    Eigen::VectorXd x = plant.initial_state(heading);
    x.segment<4>(Plant::kPort) = plant.propeller().steady_state(3.0);
    x.segment<4>(Plant::kStb) = plant.propeller().steady_state(-2.0);
    x[Plant::kRudderPort] = core::deg_to_rad(25.0);
    x[Plant::kRudderStb] = core::deg_to_rad(-10.0);
    x[Plant::kTunnel] = -8.0;
    const ActuatorState a = plant.actuators(x, Eigen::Vector2d::Zero());
    const std::vector<double> thrust{a.port.thrust, a.stb.thrust, a.tunnel.thrust};
    const std::vector<double> angle{x[Plant::kRudderPort], x[Plant::kRudderStb], 0.0};
    ASSERT_GT(std::abs(a.rudder_port.f_b.y()), 1e3);  // the rudder's force is in the test
    expect_same_tau(feedback.tau_b(thrust, angle), a.tau_b);
  }
}

TEST(ThrustFeedback, ALayoutsUnitsGiveTheSimulatorsForce) {
  VesselConfig vessel;
  model::ThrusterUnit azimuth = unit("az", model::UnitType::kAzimuth, -30.0, 4.0, 4e5, 0.0);
  azimuth.loss = {{0.0, 1.0}, {180.0, 0.8}};
  model::ThrusterUnit rudder =
      unit("main", model::UnitType::kPropellerRudder, -32.0, -4.0, 5e5, 3e5);
  rudder.rudder_lift_per_thrust = 0.4;
  rudder.rudder_max_force_N = 1.5e5;
  rudder.rudder_x_m = -34.0;
  const model::ThrusterUnit tunnel = unit("bow", model::UnitType::kTunnel, 35.0, 0.0, 1e5, 9e4);
  vessel.thrusters = {azimuth, rudder, tunnel};
  const ThrustFeedback feedback(vessel);
  ASSERT_EQ(feedback.channels().size(), 3u);
  EXPECT_EQ(feedback.channels()[0].angle_role, "azimuth.az");
  EXPECT_EQ(feedback.channels()[1].angle_role, "rudder.main");
  EXPECT_EQ(feedback.channels()[2].angle_role, "");
  const Plant plant(vessel);
  Eigen::VectorXd x = plant.initial_state(0.3);
  const double fraction[3] = {0.7, 0.5, -0.8}, angle[3] = {2.5, 0.3, 0.0};
  std::vector<double> thrust, angles;
  double n[3];
  for (int k = 0; k < 3; ++k) {
    n[k] = fraction[k] * plant.drives()[k].params().max_shaft_speed_rps;  // within its range
    x[Plant::kUnits + 2 * k] = n[k];
    x[Plant::kUnits + 2 * k + 1] = angle[k];
    // The logged thrust: the drive's thrust at the measured shaft speed (before any loss).
    thrust.push_back(plant.drives()[k].thrust_N(n[k]));
    angles.push_back(angle[k]);
  }
  const ActuatorState a = plant.actuators(x, Eigen::Vector2d::Zero());
  ASSERT_LT(a.units[0].thrust_N, thrust[0]);  // the azimuth's loss at 143° is in the test
  expect_same_tau(feedback.tau_b(thrust, angles), a.tau_b);
}

TEST(ThrustFeedback, RejectsAThrustPerUnitMissing) {
  const ThrustFeedback feedback(VesselConfig{});
  const std::vector<double> two{1.0, 2.0}, three{1.0, 2.0, 3.0};
  EXPECT_THROW((void)feedback.tau_b(two, three), std::invalid_argument);
  EXPECT_THROW((void)feedback.tau_b(three, two), std::invalid_argument);
}

}  // namespace
}  // namespace dynpos::scenario
