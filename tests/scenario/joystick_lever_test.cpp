#include "dynpos/scenario/joystick_lever.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace dynpos::scenario {
namespace {

TEST(JoystickLever, LinearLeverIsTheDemand) {
  const Eigen::Vector3d f = lever_to_demand_fraction({40.0, -30.0, 25.0}, 1.0);
  EXPECT_DOUBLE_EQ(f.x(), 0.4);
  EXPECT_DOUBLE_EQ(f.y(), -0.3);
  EXPECT_DOUBLE_EQ(f.z(), 0.25);
}

TEST(JoystickLever, QuadraticLeverAlongAnAxisSquares) {
  // e = 2: p % along an axis demands (p/100)² of the maximum, with the lever's sign.
  EXPECT_NEAR(lever_to_demand_fraction({40.0, 0.0, 0.0}, 2.0).x(), 0.16, 1e-15);
  EXPECT_NEAR(lever_to_demand_fraction({0.0, -50.0, 0.0}, 2.0).y(), -0.25, 1e-15);
  EXPECT_NEAR(lever_to_demand_fraction({0.0, 0.0, -30.0}, 2.0).z(), -0.09, 1e-15);
  EXPECT_EQ(lever_to_demand_fraction({0.0, 0.0, 0.0}, 2.0), Eigen::Vector3d::Zero());
}

TEST(JoystickLever, HorizontalCurveKeepsTheLeverDirection) {
  for (double e : {1.0, 1.5, 2.0, 3.0}) {
    for (double deg = -180.0; deg < 180.0; deg += 15.0) {
      const double a = deg * M_PI / 180.0;
      const Eigen::Vector3d lever(60.0 * std::cos(a), 60.0 * std::sin(a), 0.0);
      const Eigen::Vector3d f = lever_to_demand_fraction(lever, e);
      // Parallel to the lever, magnitude 0.6^e.
      EXPECT_NEAR(f.x() * lever.y() - f.y() * lever.x(), 0.0, 1e-12) << e << " " << deg;
      EXPECT_GT(f.x() * lever.x() + f.y() * lever.y(), -1e-12);
      EXPECT_NEAR(std::hypot(f.x(), f.y()), std::pow(0.6, e), 1e-12) << e << " " << deg;
    }
  }
}

TEST(JoystickLever, FullDeflectionIsTheMaximumAndDemandsAreClamped) {
  EXPECT_DOUBLE_EQ(lever_to_demand_fraction({100.0, 0.0, -100.0}, 2.0).x(), 1.0);
  EXPECT_DOUBLE_EQ(lever_to_demand_fraction({100.0, 0.0, -100.0}, 2.0).z(), -1.0);
  // Both axes at full: the magnitude √2 would exceed each axis' maximum.
  const Eigen::Vector3d f = lever_to_demand_fraction({100.0, 100.0, 0.0}, 2.0);
  EXPECT_DOUBLE_EQ(f.x(), 1.0);
  EXPECT_DOUBLE_EQ(f.y(), 1.0);
}

TEST(JoystickLever, InverseAlongAnAxisRoundTrips) {
  for (double e : {1.0, 2.0, 2.5}) {
    for (double p : {-100.0, -52.5, -3.0, 0.0, 7.0, 30.9, 100.0}) {
      const double f = lever_to_demand_fraction({p, 0.0, 0.0}, e).x();
      EXPECT_NEAR(lever_pct_for_fraction(f, e), p, 1e-12) << e << " " << p;
    }
  }
}

}  // namespace
}  // namespace dynpos::scenario
