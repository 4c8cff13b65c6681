#include "dynpos/core/angle.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "matchers.hpp"

namespace dynpos::core {
namespace {

using testing::AnglesNear;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// Identity, tiny, generic, near-wrap and large angles [rad].
constexpr std::array kAngles{
    0.0,     -0.0,     1e-300,      -1e-12,       0.5,    -2.0,        3.0,
    kPi,     -kPi,     kPi - 1e-15, -kPi + 1e-15, kTwoPi, -kTwoPi,     kTwoPi - 1e-15,
    3 * kPi, -3 * kPi, 100.0,       -100.0,       1e6,    -1e6 + 0.25, 12345.6789 * kTwoPi};

TEST(WrapPi, LandsInHalfOpenRangeAndIsIdempotent) {
  for (double a : kAngles) {
    SCOPED_TRACE(a);
    const double w = wrap_pi(a);
    EXPECT_GT(w, -kPi);
    EXPECT_LE(w, kPi);
    EXPECT_EQ(wrap_pi(w), w);  // exact: std::remainder leaves values in (−π, π] unchanged
    // Same direction. The remainder is exact; only this check's own w − a rounds, by eps·|a|.
    const double tol = 4 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(a));
    EXPECT_TRUE(AnglesNear(w, a, tol));
  }
}

TEST(WrapPi, PlusAndMinusPiBothGivePlusPi) {
  EXPECT_EQ(wrap_pi(kPi), kPi);
  EXPECT_EQ(wrap_pi(-kPi), kPi);
  // 3·kPi and −5·kPi round, so they land within eps·|a| of ±π (either side); as directions they
  // are π.
  EXPECT_TRUE(AnglesNear(wrap_pi(3 * kPi), kPi, 16 * std::numeric_limits<double>::epsilon()));
  EXPECT_TRUE(AnglesNear(wrap_pi(-5 * kPi), kPi, 16 * std::numeric_limits<double>::epsilon()));
}

TEST(WrapPi, LargeMultiplesOfTwoPiGiveZero) {
  for (int k : {1, -1, 2, 7, -100, 1000}) {
    SCOPED_TRACE(k);
    // k·2π + 0.25 rounds by eps·|k|·2π ≤ 1.4e-12 for |k| ≤ 1000; the remainder adds nothing.
    const double tol = 2 * std::numeric_limits<double>::epsilon() * std::abs(k) * kTwoPi;
    EXPECT_NEAR(wrap_pi(k * kTwoPi + 0.25), 0.25, tol);
    EXPECT_NEAR(wrap_pi(k * kTwoPi), 0.0, tol);
  }
}

TEST(Wrap2Pi, LandsInHalfOpenRangeAndIsIdempotent) {
  for (double a : kAngles) {
    SCOPED_TRACE(a);
    const double w = wrap_2pi(a);
    EXPECT_GE(w, 0.0);
    EXPECT_LT(w, kTwoPi);
    EXPECT_FALSE(std::signbit(w));
    EXPECT_EQ(wrap_2pi(w), w);  // exact: std::fmod leaves [0, 2π) unchanged
    // Same direction: fmod is exact, adding 2π rounds once, and this check's w − a rounds by
    // eps·|a|.
    const double tol = 8 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(a));
    EXPECT_TRUE(AnglesNear(w, a, tol));
  }
}

TEST(Wrap2Pi, KnownValues) {
  EXPECT_EQ(wrap_2pi(-kPi), kPi);
  EXPECT_EQ(wrap_2pi(kPi), kPi);
  EXPECT_EQ(wrap_2pi(kTwoPi), 0.0);
  EXPECT_EQ(wrap_2pi(-1e-300), 0.0);  // 2π − 1e-300 rounds to 2π, which is 0
  EXPECT_NEAR(wrap_2pi(deg_to_rad(-90.0)), deg_to_rad(270.0), 1e-15);  // one rounding of 2π
}

TEST(AngleDiff, IsTheShortWayRound) {
  // 1° − 359° is +2°, not −358°; one rounding each in deg_to_rad and the subtraction.
  EXPECT_NEAR(angle_diff(deg_to_rad(1.0), deg_to_rad(359.0)), deg_to_rad(2.0), 1e-15);
  EXPECT_NEAR(angle_diff(deg_to_rad(359.0), deg_to_rad(1.0)), deg_to_rad(-2.0), 1e-15);  // same
  EXPECT_EQ(angle_diff(0.3, 0.3), 0.0);
  EXPECT_EQ(angle_diff(kPi, 0.0), kPi);
  EXPECT_EQ(angle_diff(0.0, kPi), kPi);  // −π is reported as π
}

TEST(Angle, MissingAndNonFiniteGiveNaN) {
  EXPECT_TRUE(std::isnan(wrap_pi(kNaN)));
  EXPECT_TRUE(std::isnan(wrap_2pi(kNaN)));
  EXPECT_TRUE(std::isnan(angle_diff(kNaN, 1.0)));
  EXPECT_TRUE(std::isnan(angle_diff(1.0, kNaN)));
  EXPECT_TRUE(std::isnan(wrap_pi(kInf)));
  EXPECT_TRUE(std::isnan(wrap_2pi(-kInf)));
  EXPECT_TRUE(std::isnan(deg_to_rad(kNaN)));
}

TEST(Angle, DegreeConversionRoundTrips) {
  static_assert(deg_to_rad(180.0) == kPi);
  static_assert(rad_to_deg(kPi) == 180.0);
  for (double d : {0.0, 1.0, -45.0, 90.0, 359.999, 1e5}) {
    SCOPED_TRACE(d);
    // Two multiplications, one rounding each: 2 eps relative.
    EXPECT_NEAR(rad_to_deg(deg_to_rad(d)), d,
                2 * std::numeric_limits<double>::epsilon() * std::abs(d));
  }
}

}  // namespace
}  // namespace dynpos::core
