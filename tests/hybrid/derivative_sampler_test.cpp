#include "dynpos/hybrid/derivative_sampler.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace dynpos::hybrid {
namespace {

TEST(DerivativeSampler, NoiseFreeRampGivesItsSlope) {
  DerivativeSampler s(2, 0.03, 0.0, sim::Rng(1));
  EXPECT_FALSE(s.sample(0.0, Eigen::Vector2d(1.0, -2.0)));  // one sample: no estimate yet
  EXPECT_TRUE(std::isnan(s.older_sample_time()));
  for (int k = 1; k < 10; ++k) {
    const double t = 0.03 * k;
    ASSERT_TRUE(s.sample(t, Eigen::Vector2d(1.0 + 3.0 * t, -2.0 - 0.5 * t)));
    // (y_k − y_{k−1})/T_s of a ramp is its slope up to the rounding of numbers ≈ 1: 1e-12.
    EXPECT_NEAR(s.estimate()(0), 3.0, 1e-12);
    EXPECT_NEAR(s.estimate()(1), -0.5, 1e-12);
    EXPECT_DOUBLE_EQ(s.older_sample_time(), 0.03 * (k - 1));
  }
}

TEST(DerivativeSampler, MeasuredSpacingDividesByTheTimeBetweenTheSamples) {
  // Samples every 10 ticks of 0.01 s: t_k − t_{k−10} is 0.1 s only up to rounding, and the
  // measured spacing divides by exactly that difference, the nominal one by T_s.
  DerivativeSampler nominal(1, 0.1, 0.0, sim::Rng(1));
  DerivativeSampler measured(1, 0.1, 0.0, sim::Rng(1), SampleSpacing::kMeasured);
  bool spacing_rounded = false;
  for (int k = 0; k <= 300; k += 10) {
    const double t = 0.01 * k;
    const Eigen::VectorXd y = Eigen::VectorXd::Constant(1, 1.0 + 0.5 * k);
    const bool ready = nominal.sample(t, y);
    ASSERT_EQ(measured.sample(t, y), ready);
    if (!ready) continue;
    const double t_prev = 0.01 * (k - 10);
    EXPECT_EQ(measured.estimate()(0), 5.0 / (t - t_prev));
    EXPECT_EQ(nominal.estimate()(0), 5.0 / 0.1);
    EXPECT_EQ(measured.older_sample_time(), t_prev);
    spacing_rounded = spacing_rounded || t - t_prev != 0.1;
  }
  EXPECT_TRUE(spacing_rounded);  // the two differ somewhere, so the test tells them apart
}

TEST(DerivativeSampler, NoiseHasTheStdOfItsPower) {
  // Power 0.1 at T_s = 0.03 s: σ = √(0.1/0.03) ≈ 1.826 (the first-order case study).
  DerivativeSampler s(1, 0.03, 0.1, sim::Rng(7, "test"));
  EXPECT_NEAR(s.noise_std(), std::sqrt(0.1 / 0.03), 1e-15);
  const int n = 40000;
  double sum = 0.0, sum2 = 0.0;
  s.sample(0.0, Eigen::VectorXd::Zero(1));
  for (int k = 1; k <= n; ++k) {
    s.sample(0.03 * k, Eigen::VectorXd::Zero(1));
    sum += s.estimate()(0);
    sum2 += s.estimate()(0) * s.estimate()(0);
  }
  const double mean = sum / n;
  const double std_dev = std::sqrt(sum2 / n - mean * mean);
  // Standard errors for n = 40000: mean σ/√n ≈ 0.009, std σ/√(2n) ≈ 0.0065; 5 standard errors.
  EXPECT_NEAR(mean, 0.0, 0.05);
  EXPECT_NEAR(std_dev, s.noise_std(), 0.035);
}

TEST(DerivativeSampler, SameSeedSameNumbers) {
  DerivativeSampler a(3, 0.03, 20.0, sim::Rng(5, "x"));
  DerivativeSampler b(3, 0.03, 20.0, sim::Rng(5, "x"));
  DerivativeSampler c(3, 0.03, 20.0, sim::Rng(6, "x"));
  bool differs = false;
  for (int k = 0; k < 20; ++k) {
    const Eigen::Vector3d y(k, 2.0 * k, -k);
    a.sample(0.03 * k, y);
    b.sample(0.03 * k, y);
    c.sample(0.03 * k, y);
    EXPECT_EQ(a.estimate(), b.estimate());
    differs = differs || a.estimate() != c.estimate();
  }
  EXPECT_TRUE(differs);
}

TEST(DerivativeSampler, RejectsBadArguments) {
  EXPECT_THROW(DerivativeSampler(0, 0.03, 0.0, sim::Rng(1)), std::invalid_argument);
  EXPECT_THROW(DerivativeSampler(1, 0.0, 0.0, sim::Rng(1)), std::invalid_argument);
  EXPECT_THROW(DerivativeSampler(1, 0.03, -1.0, sim::Rng(1)), std::invalid_argument);
  DerivativeSampler s(2, 0.03, 0.0, sim::Rng(1));
  EXPECT_THROW(s.sample(0.0, Eigen::Vector3d::Zero()), std::invalid_argument);
}

}  // namespace
}  // namespace dynpos::hybrid
