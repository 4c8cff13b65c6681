// The exact thrust region (capability/thrust_region.hpp) against analytic limits: the
// propellers' rated thrust, the rudder cone, lost actuators.

#include "dynpos/capability/thrust_region.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "dynpos/core/error.hpp"
#include "dynpos/scenario/vessel_config.hpp"
#include "gunnerus_allocator.hpp"

namespace dynpos::capability {
namespace {

using testing::gunnerus_allocator;

TEST(ThrustRegion, PureSurgeIsHeldUpToBothPropellersFullAhead) {
  const ThrustLimits limits = thrust_limits(gunnerus_allocator(), 0.0);
  const double full = limits.hi_N(0) + limits.hi_N(1);  // both propellers at rated thrust
  const Eigen::Vector3d just_held = Eigen::Vector3d::UnitX() * full * (1.0 - 1e-9);
  const auto at = attain(limits, just_held);
  ASSERT_TRUE(at.has_value());
  EXPECT_TRUE(at->at_limit[0] && at->at_limit[1]);
  const Eigen::Vector3d met = limits.B * at->forces_N;
  EXPECT_NEAR((met - just_held).norm(), 0.0, 1e-6);
  const Eigen::Vector3d too_much = Eigen::Vector3d::UnitX() * full * 1.001;
  EXPECT_FALSE(attain(limits, too_much).has_value());
}

TEST(ThrustRegion, EveryForceOfAnAllocationWithinTheLimitsIsAttainable) {
  const ThrustLimits limits = thrust_limits(gunnerus_allocator(), 0.0);
  // Half of every limit, rudders within the cone of their propeller's thrust.
  Eigen::Matrix<double, 5, 1> f;
  f << 0.5 * limits.hi_N(0), -0.5 * std::abs(limits.lo_N(1)), 0.3 * limits.cone.kappa * f(0), 0.0,
      0.5 * limits.lo_N(4);
  EXPECT_TRUE(attain(limits, limits.B * f).has_value());
  EXPECT_TRUE(attain(limits, Eigen::Vector3d::Zero()).has_value());
}

TEST(ThrustRegion, ALostActuatorGivesNothingAndTheRuddersLiftOnlyInSlipstream) {
  // Without the tunnel a side force at rest needs rudder lift, i.e. one propeller ahead (its
  // rudder in the slipstream) and the other astern to cancel the surge force.
  const ThrustLimits lost = thrust_limits(gunnerus_allocator({"tunnel"}), 0.0);
  const Eigen::Vector3d sway = Eigen::Vector3d::UnitY() * 5000.0;
  const auto a = attain(lost, sway);
  ASSERT_TRUE(a.has_value());
  EXPECT_EQ(a->forces_N(4), 0.0);
  const Eigen::Matrix<double, 5, 1> f = a->forces_N;
  for (int i = 0; i < 2; ++i) {  // a rudder's side force within its propeller's cone
    EXPECT_LE(std::abs(f(2 + i)), lost.cone.kappa * std::max(f(i), 0.0) + 1e-6);
  }
  EXPECT_GT(std::abs(f(2)) + std::abs(f(3)), 1000.0);
  EXPECT_LT(f(0) * f(1), 0.0);  // one ahead, one astern
  // With both propellers lost too, nothing pushes sideways.
  const ThrustLimits none = thrust_limits(gunnerus_allocator({"tunnel", "port", "stb"}), 0.0);
  EXPECT_FALSE(attain(none, sway).has_value());
  EXPECT_THROW(gunnerus_allocator({"bow"}), core::InputError);
}

}  // namespace
}  // namespace dynpos::capability
