#include "dynpos/control/reference_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace dynpos::control {
namespace {

TEST(ReferenceModel, StepConvergesWithoutOvershootAndRespectsTheSpeedLimit) {
  ReferenceModel model(ReferenceModelParams{}, Eigen::Vector3d::Zero());
  const Eigen::Vector3d setpoint(50.0, -20.0, 0.0);
  double max_north = 0.0, max_speed = 0.0;
  for (int k = 0; k < 6000; ++k) {  // 600 s at 10 Hz
    model.step(setpoint, 0.1);
    const DpReference r = model.reference();
    max_north = std::max(max_north, r.eta_d.x());
    max_speed = std::max(max_speed, std::abs(r.eta_d_dot.x()));
  }
  const DpReference r = model.reference();
  EXPECT_NEAR(r.eta_d.x(), 50.0, 1e-3);
  EXPECT_NEAR(r.eta_d.y(), -20.0, 1e-3);
  // Critically damped: no overshoot beyond rounding (1 mm).
  EXPECT_LE(max_north, 50.0 + 1e-3);
  EXPECT_LE(max_speed, 0.5 + 1e-12);
  EXPECT_GT(max_speed, 0.45);  // a 50 m change is sailed at (nearly) the limit
}

TEST(ReferenceModel, AtRestOnlyWhileNoSetpointChangeIsUnderWay) {
  ReferenceModel model(ReferenceModelParams{}, Eigen::Vector3d::Zero());
  EXPECT_TRUE(model.at_rest(0.01));               // starts at rest
  const Eigen::Vector3d setpoint(0.0, 0.0, 0.5);  // a 29° heading change
  int first_rest = -1;
  for (int k = 1; k <= 3000; ++k) {  // 300 s at 10 Hz
    model.step(setpoint, 0.1);
    const bool rest = model.at_rest(0.01);
    if (k >= 20 && k <= 150) {
      // Under way: the third-order filter starts with zero rate and acceleration, so |ψ̇_d|
      // passes 1 % of its limit after ≈ √(2·0.01·0.035/(ω³·0.5)) = 1.65 s.
      EXPECT_FALSE(rest) << k;
    }
    if (k > 20 && rest && first_rest < 0) first_rest = k;
    if (first_rest > 0) {
      EXPECT_TRUE(rest) << k;  // critically damped: stays at rest once there
    }
    // At rest means |ψ̇_d| within 1 % of the 0.035 rad/s limit.
    EXPECT_EQ(rest, std::abs(model.reference().eta_d_dot.z()) <= 0.01 * 0.035) << k;
  }
  ASSERT_GT(first_rest, 0);
  std::printf("at rest after %.1f s\n", first_rest * 0.1);
  EXPECT_GT(first_rest, 150);  // the change takes well over 15 s at 2 deg/s
}

TEST(ReferenceModel, HeadingTakesTheShortWayRound) {
  ReferenceModel model(ReferenceModelParams{}, Eigen::Vector3d(0, 0, 3.0));
  for (int k = 0; k < 3000; ++k) model.step(Eigen::Vector3d(0, 0, -3.0), 0.1);
  // From 3.0 rad to −3.0 rad is 0.28 rad through ±π, not 6 rad back through 0.
  EXPECT_NEAR(std::abs(model.reference().eta_d.z()), 3.0, 1e-3);
  EXPECT_LT(model.reference().eta_d.z(), 0.0);
}

TEST(OperatingCircle, ReachedOnlyInsideTheCircleWithTheHeading) {
  const OperatingCircle circle;
  const Eigen::Vector3d sp(50, 0, 0);
  EXPECT_TRUE(circle.reached(Eigen::Vector3d(48.6, 1.4, 0.01), sp));  // 1.98 m away
  EXPECT_FALSE(circle.reached(Eigen::Vector3d(48.5, 1.5, 0.0), sp));  // 2.12 m away
  EXPECT_FALSE(circle.reached(Eigen::Vector3d(50, 0, 0.05), sp));     // 2.9° off
}

}  // namespace
}  // namespace dynpos::control
