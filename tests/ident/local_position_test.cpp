#include "dynpos/ident/local_position.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dynpos/core/error.hpp"

namespace dynpos::ident {
namespace {

constexpr double kRad = std::numbers::pi / 180.0;

TEST(LocalPosition, OriginAtFirstFixAndMetresAlongTheAxes) {
  // At 63.44° N one arc-minute of latitude is M·π/10800 = 1857.8 m on WGS84 (meridian radius
  // of curvature M = a(1 − e²)/(1 − e² sin²φ)^{3/2} = 6386.6 km there), and one arc-minute of
  // longitude is N cos φ·π/10800 = 831.9 m (N = a/√(1 − e² sin²φ) = 6395.3 km). Tolerance
  // 0.5 m: the tangent plane departs from the ellipsoid by ~0.1 m over these distances.
  const std::vector<double> lat = {std::nan(""), 63.44 * kRad, (63.44 + 1.0 / 60.0) * kRad,
                                   63.44 * kRad};
  const std::vector<double> lon = {10.35 * kRad, 10.35 * kRad, 10.35 * kRad,
                                   (10.35 + 1.0 / 60.0) * kRad};
  const LocalPositions p = local_north_east(lat, lon);
  EXPECT_TRUE(std::isnan(p.north_m[0]));
  EXPECT_NEAR(p.north_m[1], 0.0, 1e-9);
  EXPECT_NEAR(p.east_m[1], 0.0, 1e-9);
  EXPECT_NEAR(p.north_m[2], 1857.8, 0.5);
  EXPECT_NEAR(p.east_m[2], 0.0, 1e-6);
  EXPECT_NEAR(p.east_m[3], 831.9, 0.5);
}

TEST(LocalPosition, LatitudeInDegreesReadAsRadiansIsAnError) {
  EXPECT_THROW(local_north_east({63.44}, {10.35}), core::InputError);
  EXPECT_THROW(local_north_east({0.1, 0.2}, {0.1}), core::InputError);
}

}  // namespace
}  // namespace dynpos::ident
