#include "dynpos/sensors/mru.hpp"

#include <gtest/gtest.h>

namespace dynpos::sensors {
namespace {

MruParams noiseless(const Eigen::Vector3d& arm) {
  MruParams p;
  p.lever_arm_b = arm;
  p.angle_std_rad = p.rate_std_rad_s = p.accel_std_mps2 = 0.0;
  return p;
}

TEST(Mru, SteadyTurnGivesCentripetalAccelerationAtTheArm) {
  // Level hull turning at r about the origin (at rest): a point at x = 15 m forward feels
  // −r²·15 m along x (towards the centre of rotation), and nothing else.
  RigidBodyMotion m;
  m.omega_nb_b = {0.0, 0.0, 0.05};
  Mru mru(noiseless({15.0, 0.0, 0.0}), AccelerationConvention::kKinematic, 0.01, 1);
  const MruSample s = mru.measure(m);
  EXPECT_NEAR(s.accel_b.x(), -0.05 * 0.05 * 15.0, 1e-15);
  EXPECT_NEAR(s.accel_b.y(), 0.0, 1e-15);
  EXPECT_NEAR(s.accel_b.z(), 0.0, 1e-15);
  EXPECT_EQ(s.omega_b, m.omega_nb_b);
}

TEST(Mru, SpecificForceConventionAddsGravity) {
  RigidBodyMotion m;
  m.theta = {0.1, 0.0, 0.0};  // 0.1 rad roll at rest: gravity shows on the y axis
  Mru mru(noiseless(Eigen::Vector3d::Zero()), AccelerationConvention::kSpecificForce, 0.01, 1);
  const MruSample s = mru.measure(m);
  EXPECT_NEAR(s.accel_b.y(), -kGravity_mps2 * std::sin(0.1), 1e-12);
  EXPECT_NEAR(s.accel_b.z(), -kGravity_mps2 * std::cos(0.1), 1e-12);
  EXPECT_DOUBLE_EQ(s.roll, 0.1);
}

TEST(Mru, ConventionNamesRoundTrip) {
  for (auto c : {AccelerationConvention::kKinematic, AccelerationConvention::kSpecificForce}) {
    EXPECT_EQ(parse_acceleration_convention(to_string(c)), c);
  }
  EXPECT_FALSE(parse_acceleration_convention("gravity").has_value());
}

}  // namespace
}  // namespace dynpos::sensors
