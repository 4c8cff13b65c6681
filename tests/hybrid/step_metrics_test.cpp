#include "dynpos/hybrid/step_metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace dynpos::hybrid {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(SettlingTime, ExponentialDecayMatchesClosedForm) {
  // e(t) = e^{−(t − 5)/τ} after a unit step at 5 s; within 5 % from 5 + τ·ln 20.
  const double tau = 2.0, dt = 1e-3;
  std::vector<double> t, ratio;
  for (int k = 0; k <= 30000; ++k) {
    t.push_back(k * dt);
    const double e = t.back() < 5.0 ? 0.0 : std::exp(-(t.back() - 5.0) / tau);
    ratio.push_back(e / 0.05);
  }
  const auto settle = settling_time(t, ratio, 5.0, 1e9);
  ASSERT_TRUE(settle.has_value());
  // On a grid of dt the first sample inside the band is at most one dt late.
  EXPECT_NEAR(*settle, tau * std::log(20.0), dt);
}

TEST(SettlingTime, WindowEndsAtTheNextStep) {
  std::vector<double> t = {0, 1, 2, 3, 4, 5, 6};
  std::vector<double> ratio = {3, 2, 0.5, 2, 0.5, 0.5, 0.5};
  // Window [0, 6): samples 0..5; the last time outside is t = 3, so settled from t = 4.
  EXPECT_DOUBLE_EQ(settling_time(t, ratio, 0.0, 6.0).value(), 4.0);
  // Window [0, 4): ends outside the band (t = 3): not settled.
  EXPECT_FALSE(settling_time(t, ratio, 0.0, 4.0).has_value());
  // Window [4, ∞): inside from its first sample.
  EXPECT_DOUBLE_EQ(settling_time(t, ratio, 4.0, 1e9).value(), 0.0);
  // An empty window and a NaN at the end.
  EXPECT_FALSE(settling_time(t, ratio, 10.0, 20.0).has_value());
  ratio.back() = kNaN;
  EXPECT_FALSE(settling_time(t, ratio, 4.0, 1e9).has_value());
}

TEST(IntegralAbsError, TrapezoidOfSine) {
  // ∫₀^{2π} |sin t| dt = 4; the trapezoidal error with h = 2π/20000 is ~h²/12·∫|f″| ≈ 3e-8.
  std::vector<double> t, e;
  const int n = 20000;
  for (int k = 0; k <= n; ++k) {
    t.push_back(2.0 * std::numbers::pi * k / n);
    e.push_back(std::sin(t.back()));
  }
  EXPECT_NEAR(integral_abs_error(t, e), 4.0, 1e-6);
  EXPECT_EQ(integral_abs_error(std::vector<double>{1.0}, std::vector<double>{5.0}), 0.0);
  e[3] = kNaN;
  EXPECT_TRUE(std::isnan(integral_abs_error(t, e)));
}

TEST(PeakAbs, LargestMagnitude) {
  EXPECT_EQ(peak_abs(std::vector<double>{1.0, -7.0, 3.0}), 7.0);
  EXPECT_TRUE(std::isnan(peak_abs(std::vector<double>{})));
  EXPECT_TRUE(std::isnan(peak_abs(std::vector<double>{1.0, kNaN})));
}

TEST(StepBandScale, EachDofByItsOwnStepAndUnmovedDofsByTheLargest) {
  // The DP bias step (5.91): (3000 N, 2000 N, 1000 N·m); a step in north only.
  EXPECT_EQ(step_band_scale(Eigen::Vector3d(3000.0, -2000.0, 1000.0)),
            Eigen::Vector3d(3000.0, 2000.0, 1000.0));
  EXPECT_EQ(step_band_scale(Eigen::Vector3d(0.0, -2000.0, 0.0)),
            Eigen::Vector3d(2000.0, 2000.0, 2000.0));
  EXPECT_EQ(step_band_scale(Eigen::Matrix<double, 1, 1>(-50.0))(0), 50.0);
}

TEST(BandRatio, LargestErrorOverItsBand) {
  const Eigen::Vector3d scale(3000.0, 2000.0, 1000.0);
  // 5 % bands: 150, 100, 50. The yaw error 60 is 1.2 bands, the others inside.
  EXPECT_DOUBLE_EQ(band_ratio(Eigen::Vector3d(-140.0, 20.0, 60.0), scale, 0.05), 1.2);
  EXPECT_LE(band_ratio(Eigen::Vector3d(150.0, -100.0, 50.0), scale, 0.05), 1.0 + 1e-15);
  EXPECT_EQ(band_ratio(Eigen::Vector3d::Zero().eval(), scale, 0.05), 0.0);
}

TEST(StepResidual, FractionOfTheStepLeftWithUnmovedDofsOnTheBandScale) {
  const Eigen::Vector3d delta(0.0, 2000.0, 0.0);
  const Eigen::Vector3d scale = step_band_scale(delta);
  // Sway: 100 of 2000 left; north moved 300 by a step of none, judged on the 2000 scale.
  EXPECT_DOUBLE_EQ(step_residual(Eigen::Vector3d(300.0, -100.0, 0.0), delta, scale), 0.15);
  EXPECT_DOUBLE_EQ(step_residual(Eigen::Vector3d(0.0, -100.0, 0.0), delta, scale), 0.05);
  EXPECT_EQ(step_residual(Eigen::Vector3d::Zero().eval(), delta, scale), 0.0);
}

}  // namespace
}  // namespace dynpos::hybrid
