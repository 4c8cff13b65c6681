#include "dynpos/model/allocation_bounds.hpp"

#include <gtest/gtest.h>

#include <array>

#include "dynpos/model/thrust_configuration.hpp"

namespace dynpos::model {
namespace {

using Vector5d = Eigen::Matrix<double, 5, 1>;
constexpr int kT1 = ThrustConfiguration::kThrustPort;
constexpr int kT2 = ThrustConfiguration::kThrustStb;
constexpr int kY1 = ThrustConfiguration::kRudderPort;
constexpr int kT3 = ThrustConfiguration::kTunnel;

// A box like Gunnerus' at rest [N]: thrust 72/52 kN ahead/astern, rudder 30 kN, tunnel 25 kN.
std::array<Vector5d, 2> box() {
  Vector5d lo, hi;
  lo << -52e3, -52e3, -30e3, -30e3, -25e3;
  hi << 72e3, 72e3, 30e3, 30e3, 25e3;
  return {lo, hi};
}

TEST(RudderCone, GrowsWithAheadThrustOnly) {
  const RudderCone cone{0.4, 1000.0};
  EXPECT_EQ(cone.limit(0.0), 1000.0);
  EXPECT_EQ(cone.limit(-5e4), 1000.0);  // astern: no slipstream over the rudder
  EXPECT_EQ(cone.limit(5e4), 0.4 * 5e4 + 1000.0);
  const auto [lo, hi] = cone.bounds(5e4, -30e3, 15e3);  // within the box
  EXPECT_EQ(lo, -21e3);
  EXPECT_EQ(hi, 15e3);
}

TEST(AllocationBox, WithoutRateLimitsOrRegionTheBoxIsKept) {
  const auto [lo, hi] =
      allocation_box(box(), Vector5d::Zero(), Vector5d::Constant(1e3), 0.0, {0, 0});
  EXPECT_EQ(lo, box()[0]);
  EXPECT_EQ(hi, box()[1]);
}

TEST(AllocationBox, RateLimitsTightenAroundThePreviousForces) {
  Vector5d previous = Vector5d::Zero();
  previous[kT1] = 10e3;
  previous[kT3] = 24.9e3;
  const auto [lo, hi] = allocation_box(box(), previous, Vector5d::Constant(1e3), 0.5, {0, 0});
  EXPECT_EQ(lo[kT1], 9.5e3);
  EXPECT_EQ(hi[kT1], 10.5e3);
  EXPECT_EQ(lo[kT3], 24.4e3);
  EXPECT_EQ(hi[kT3], 25e3);  // the box still bounds it
}

TEST(AllocationBox, ABoxThatMovedAwayWinsAtItsPointNearestThePrevious) {
  // The tunnel lost power with speed: the previous 40 kN is beyond the 25 kN box by more than
  // the rate allows.
  Vector5d previous = Vector5d::Zero();
  previous[kT3] = 40e3;
  const auto [lo, hi] = allocation_box(box(), previous, Vector5d::Constant(1e3), 0.1, {0, 0});
  EXPECT_EQ(lo[kT3], 25e3);
  EXPECT_EQ(hi[kT3], 25e3);
}

TEST(AllocationBox, SignRegionsLimitTheMainPropellers) {
  const auto [lo, hi] =
      allocation_box(box(), Vector5d::Zero(), Vector5d::Constant(1e3), 0.0, {1, -1});
  EXPECT_EQ(lo[kT1], 0.0);
  EXPECT_EQ(hi[kT1], 72e3);
  EXPECT_EQ(lo[kT2], -52e3);
  EXPECT_EQ(hi[kT2], 0.0);
  EXPECT_EQ(lo[kY1], -30e3);  // rudders and tunnel untouched
  // A rate box wholly astern in an ahead region collapses to its upper end, nearest 0.
  Vector5d previous = Vector5d::Zero();
  previous[kT1] = -20e3;
  const auto [lo2, hi2] = allocation_box(box(), previous, Vector5d::Constant(1e3), 1.0, {1, 0});
  EXPECT_EQ(lo2[kT1], -19e3);
  EXPECT_EQ(hi2[kT1], -19e3);
}

}  // namespace
}  // namespace dynpos::model
