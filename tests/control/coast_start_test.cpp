#include "dynpos/control/coast_start.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace dynpos::control {
namespace {

constexpr double kDt = 0.1;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const Eigen::Vector3d kOmega0 = Eigen::Vector3d::Constant(2.0 * std::numbers::pi / 8.0);
const Eigen::Vector3d kMeasured(0.0, 0.0, 0.0);

TEST(CoastStart, ALostPositionStartsItsVelocityAndBiasFromTheirMeans) {
  CoastStart coast(kOmega0);
  const Eigen::Vector3d nu_mean(0.1, -0.2, 0.01), bias_mean(2e4, -1e4, 5e5);
  // A wave at ω₀ of the means' size on top: a first-order low-pass of time constant 2π/ω₀
  // keeps 1/√(1 + 4π²) = 0.157 of it.
  double worst_share = 0.0;
  Eigen::Vector3d nu, bias;
  for (int k = 0; k < 3000; ++k) {
    const double wave = std::sin(kOmega0.x() * k * kDt);
    nu = nu_mean * (1.0 + wave);
    bias = bias_mean * (1.0 + wave);
    coast.start_if_lost(kMeasured, nu, bias);
    coast.track(nu, bias, kDt);
  }
  Eigen::Vector3d nu_start = nu, bias_start = bias;
  const Eigen::Vector3d nu_before = nu, bias_before = bias;
  coast.start_if_lost(Eigen::Vector3d(kNaN, kNaN, 0.0), nu_start, bias_start);
  for (int i = 0; i < 2; ++i) {
    worst_share = std::max(worst_share, std::abs(nu_start[i] / nu_mean[i] - 1.0));
    worst_share = std::max(worst_share, std::abs(bias_start[i] / bias_mean[i] - 1.0));
  }
  EXPECT_LT(worst_share, 0.16);
  // The heading is still measured: r and b_ψ are left as they are.
  EXPECT_EQ(nu_start.z(), nu_before.z());
  EXPECT_EQ(bias_start.z(), bias_before.z());
}

TEST(CoastStart, OnlyTheStepThatLosesAMeasurementStartsFromTheMeans) {
  CoastStart coast(kOmega0);
  Eigen::Vector3d nu(1.0, 2.0, 3.0), bias(4.0, 5.0, 6.0);
  for (int k = 0; k < 3000; ++k) coast.track(nu, bias, kDt);  // 37 time constants
  const Eigen::Vector3d lost_heading(0.0, 0.0, kNaN);
  Eigen::Vector3d nu_coast(7.0, 8.0, 9.0), bias_coast(10.0, 11.0, 12.0);
  coast.start_if_lost(lost_heading, nu_coast, bias_coast);
  EXPECT_TRUE(nu_coast.isApprox(Eigen::Vector3d(7.0, 8.0, 3.0), 1e-12));  // r from its mean
  EXPECT_TRUE(bias_coast.isApprox(Eigen::Vector3d(10.0, 11.0, 6.0), 1e-12));
  // While it stays lost the coast goes on from wherever the observer has got to, and the
  // heading's means do not follow it.
  nu_coast.z() = 30.0;
  coast.track(nu_coast, bias_coast, kDt);
  coast.start_if_lost(lost_heading, nu_coast, bias_coast);
  EXPECT_EQ(nu_coast.z(), 30.0);
  // Back, then lost again: the mean held through the loss.
  coast.start_if_lost(kMeasured, nu_coast, bias_coast);
  coast.start_if_lost(lost_heading, nu_coast, bias_coast);
  EXPECT_NEAR(nu_coast.z(), 3.0, 1e-12);
}

// A filter that takes each 1 Hz fix once steps on no position between fixes: with the loss
// declared after 5 s those steps are not a loss, a longer gap is.
TEST(CoastStart, GapsBetweenFixesAreNotALossBeyondTheTimeGiven) {
  CoastStart coast(kOmega0, 5.0);
  const Eigen::Vector3d mean(0.3, 0.4, 0.0), fix(0.0, 0.0, 0.0), gap(kNaN, kNaN, 0.0);
  Eigen::Vector3d nu, bias;
  for (int k = 0; k < 3000; ++k) {
    nu = bias = mean;
    const Eigen::Vector3d& y = k % 10 == 0 ? fix : gap;
    coast.start_if_lost(y, nu, bias);
    EXPECT_EQ(nu, mean) << k;  // never reset
    coast.track(nu, bias, kDt);
  }
  // A fix, then 10 s without one; the estimate coasts a little off the means.
  coast.start_if_lost(fix, nu, bias);
  coast.track(nu, bias, kDt);
  const Eigen::Vector3d coasting = mean + Eigen::Vector3d(0.01, 0.01, 0.0);
  int resets = 0;
  for (int k = 1; k <= 100; ++k) {
    nu = bias = coasting;
    coast.start_if_lost(gap, nu, bias);
    if (nu != coasting) {
      ++resets;
      EXPECT_NEAR(k * kDt, 5.0, 0.05) << "lost 5 s after the fix";
      // The means followed the coasting estimate until then: 5 s of an 8 s time constant.
      EXPECT_NEAR(nu.x(), 0.3, 0.01);
      EXPECT_LT(nu.x(), coasting.x());
    }
    coast.track(nu, bias, kDt);
  }
  EXPECT_EQ(resets, 1);
  EXPECT_THROW(CoastStart(kOmega0, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace dynpos::control
