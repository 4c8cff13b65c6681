#include "dynpos/core/circular_stats.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "dynpos/core/angle.hpp"
#include "matchers.hpp"

namespace dynpos::core {
namespace {

using testing::AnglesNear;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kEps = std::numeric_limits<double>::epsilon();

std::vector<double> degrees(std::initializer_list<double> values_deg) {
  std::vector<double> out;
  for (double d : values_deg) out.push_back(deg_to_rad(d));
  return out;
}

// Deterministic offsets [rad] in [−0.1, 0.1], deliberately not symmetric about their mean.
std::vector<double> small_offsets() {
  return {0.031, -0.087, 0.1, -0.012, 0.055, -0.1, 0.002, 0.073, -0.049, -0.066, 0.018, 0.09};
}

TEST(CircularStats, HeadingsEitherSideOfNorthAverageToNorth) {
  const CircularStats s = circular_stats(degrees({359.0, 1.0}));
  ASSERT_TRUE(s.mean_rad.has_value());
  // sin(359°) and sin(1°) cancel to the rounding of 359° in radians, ≈ 1e-15.
  EXPECT_TRUE(AnglesNear(*s.mean_rad, 0.0, 1e-14));
  EXPECT_EQ(s.count, 2u);
  // Two samples ±1°: R̄ = cos 1°, σ = √(−2 ln cos 1°) ≈ 1° (closed form; ln cos rounds at eps).
  EXPECT_NEAR(s.resultant_length, std::cos(deg_to_rad(1.0)), 1e-15);
  EXPECT_NEAR(*s.std_rad, std::sqrt(-2.0 * std::log(std::cos(deg_to_rad(1.0)))), 1e-12);
}

TEST(CircularStats, SymmetricPairMatchesClosedForm) {
  const double alpha = deg_to_rad(30.0);
  const CircularStats s = circular_stats(std::vector<double>{1.0 + alpha, 1.0 - alpha});
  ASSERT_TRUE(s.mean_rad.has_value());
  // Closed form: mean 1, R̄ = cos α, σ = √(−2 ln cos α); sums of two unit terms round at eps.
  EXPECT_NEAR(*s.mean_rad, 1.0, 4 * kEps);
  EXPECT_NEAR(s.resultant_length, std::cos(alpha), 4 * kEps);
  EXPECT_NEAR(*s.std_rad, std::sqrt(-2.0 * std::log(std::cos(alpha))), 1e-14);  // ln near 1
}

TEST(CircularStats, MeanIsInvariantToAddingTwoPi) {
  std::vector<double> angles = small_offsets();
  for (double& a : angles) a += deg_to_rad(178.0);  // a cluster straddling ±π
  const CircularStats base = circular_stats(angles);
  ASSERT_TRUE(base.mean_rad.has_value());
  std::vector<double> shifted = angles;
  const int turns[] = {1, -1, 5, 0, -3, 2, 100, -7, 0, 1, -1, 4};
  for (std::size_t i = 0; i < shifted.size(); ++i) shifted[i] += turns[i] * kTwoPi;
  const CircularStats moved = circular_stats(shifted);
  ASSERT_TRUE(moved.mean_rad.has_value());
  // cos/sin of an angle shifted by 100 turns round at eps·|a| ≈ 1.4e-13 rad.
  EXPECT_TRUE(AnglesNear(*moved.mean_rad, *base.mean_rad, 1e-12));
  EXPECT_NEAR(*moved.std_rad, *base.std_rad, 1e-12);  // same: σ moves by as much as the angles
  EXPECT_GT(*base.mean_rad, -kPi);
  EXPECT_LE(*base.mean_rad, kPi);
}

TEST(CircularStats, SmallSpreadMatchesLinearStatistics) {
  // Straddle north, where a plain mean of [0, 2π) headings is nonsense.
  const double centre = 0.02;
  std::vector<double> unwrapped;
  std::vector<double> headings;  // as a compass would log them, in [0, 2π)
  for (double d : small_offsets()) {
    unwrapped.push_back(centre + d);
    headings.push_back(wrap_2pi(centre + d));
  }
  const double n = static_cast<double>(unwrapped.size());
  const double lin_mean = std::accumulate(unwrapped.begin(), unwrapped.end(), 0.0) / n;
  double ss = 0.0;
  for (double a : unwrapped) ss += (a - lin_mean) * (a - lin_mean);
  const double lin_std = std::sqrt(ss / n);  // population (1/N), as the circular σ

  const CircularStats s = circular_stats(headings);
  ASSERT_TRUE(s.mean_rad.has_value());
  // Σ sin(θᵢ − θ̄) = 0 vs Σ(θᵢ − m) = 0 differ by the cubic term: |θ̄ − m| ≤ max|d|³/6 ≈ 1.7e-4.
  EXPECT_NEAR(*s.mean_rad, lin_mean, 2e-4);
  // σ² − s² ≈ −m₄/12 + s⁴/4 with |d| ≤ 0.1: |σ/s − 1| ≤ (0.01/12 + 0.01/4)/2 ≈ 0.17 %.
  EXPECT_NEAR(*s.std_rad / lin_std, 1.0, 0.005);
  // The plain mean of the logged headings is about π away: the reason for circular statistics.
  const double plain = std::accumulate(headings.begin(), headings.end(), 0.0) / n;
  EXPECT_GT(std::abs(angle_diff(plain, lin_mean)), 1.0);
}

TEST(CircularStats, TinySpreadKeepsFullPrecision) {
  // ±1e-9 rad: 1 − R̄ = 5e-19 is below eps, so R̄ itself rounds to 1; σ must still be 1e-9.
  const CircularStats s = circular_stats(std::vector<double>{2.0 + 1e-9, 2.0 - 1e-9});
  ASSERT_TRUE(s.std_rad.has_value());
  // Offsets from the mean are differences of ≈ 2 rad numbers, exact to eps·2 ≈ 4e-16 of 1e-9.
  EXPECT_NEAR(*s.std_rad, 1e-9, 1e-15);
}

TEST(CircularStats, SingleSample) {
  const CircularStats s = circular_stats(std::vector<double>{-kPi});
  ASSERT_TRUE(s.mean_rad.has_value());
  EXPECT_EQ(*s.mean_rad, kPi);  // −π is reported as π
  EXPECT_EQ(*s.std_rad, 0.0);
  EXPECT_EQ(s.resultant_length, 1.0);
}

TEST(CircularStats, MissingSamplesAreSkipped) {
  const std::vector<double> clean = degrees({350.0, 5.0, 12.0});
  const std::vector<double> gappy{kNaN, clean[0], kNaN, kNaN, clean[1], clean[2], kNaN};
  const CircularStats a = circular_stats(clean);
  const CircularStats b = circular_stats(gappy);
  EXPECT_EQ(b.count, 3u);
  // The same sums in the same order: bit-identical.
  EXPECT_EQ(a.mean_rad, b.mean_rad);
  EXPECT_EQ(a.std_rad, b.std_rad);
  EXPECT_EQ(a.resultant_length, b.resultant_length);
}

TEST(CircularStats, EmptyOrAllMissingHasNoMeanAndNoStd) {
  for (const std::vector<double>& input :
       {std::vector<double>{}, std::vector<double>{kNaN, kNaN}}) {
    const CircularStats s = circular_stats(input);
    EXPECT_EQ(s.count, 0u);
    EXPECT_FALSE(s.mean_rad.has_value());
    EXPECT_FALSE(s.std_rad.has_value());
    EXPECT_EQ(s.resultant_length, 0.0);
  }
  EXPECT_FALSE(circular_mean(std::vector<double>{}).has_value());
}

TEST(CircularStats, EvenSpreadHasNoMeanDirection) {
  const CircularStats s = circular_stats(degrees({0.0, 90.0, 180.0, 270.0}));
  EXPECT_EQ(s.count, 4u);
  EXPECT_FALSE(s.mean_rad.has_value());
  EXPECT_LT(s.resultant_length, kMinResultantLength);
  ASSERT_TRUE(s.std_rad.has_value());
  EXPECT_GT(*s.std_rad, 5.0);  // R̄ ≲ 1e-9 gives σ ≥ √(2·ln 1e9) ≈ 6.4 rad
}

TEST(CircularStats, IntegerWeightsEqualRepeatedSamples) {
  const std::vector<double> angles = degrees({10.0, 100.0, 340.0});
  const std::vector<double> weights{1.0, 3.0, 2.0};
  const std::vector<double> repeated = degrees({10.0, 100.0, 100.0, 100.0, 340.0, 340.0});
  const CircularStats w = circular_stats(angles, weights);
  const CircularStats r = circular_stats(repeated);
  ASSERT_TRUE(w.mean_rad.has_value() && r.mean_rad.has_value());
  // Same sums grouped differently: a few eps.
  EXPECT_TRUE(AnglesNear(*w.mean_rad, *r.mean_rad, 1e-14));
  EXPECT_NEAR(*w.std_rad, *r.std_rad, 1e-14);
  EXPECT_DOUBLE_EQ(w.weight_sum, 6.0);
  EXPECT_EQ(w.count, 3u);
}

TEST(CircularStats, WeightedKnownValue) {
  const CircularStats s = circular_stats(degrees({0.0, 90.0}), std::vector<double>{1.0, 3.0});
  ASSERT_TRUE(s.mean_rad.has_value());
  EXPECT_NEAR(*s.mean_rad, std::atan2(3.0, 1.0), 1e-15);          // closed form; cos 90° ≈ 6e-17
  EXPECT_NEAR(s.resultant_length, std::sqrt(10.0) / 4.0, 1e-15);  // |(1, 3)|/4, eps-level sums
}

TEST(CircularStats, WeightValidationAndMissingWeights) {
  const std::vector<double> angles{0.1, 0.2, 0.3};
  EXPECT_THROW(circular_stats(angles, std::vector<double>{1.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(circular_stats(angles, std::vector<double>{1.0, -1.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(circular_stats(angles, std::vector<double>{1.0, INFINITY, 1.0}),
               std::invalid_argument);
  const CircularStats s = circular_stats(angles, std::vector<double>{1.0, kNaN, 1.0});
  EXPECT_EQ(s.count, 2u);
  ASSERT_TRUE(s.mean_rad.has_value());
  EXPECT_NEAR(*s.mean_rad, 0.2, 4 * kEps);  // symmetric pair 0.1, 0.3: mean 0.2 to eps
  const CircularStats zero = circular_stats(angles, std::vector<double>{0.0, 0.0, 0.0});
  EXPECT_FALSE(zero.mean_rad.has_value());
  EXPECT_FALSE(zero.std_rad.has_value());
}

}  // namespace
}  // namespace dynpos::core
