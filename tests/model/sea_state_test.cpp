#include "dynpos/model/sea_state.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace dynpos::model {
namespace {

TEST(Jonswap, IntegratesToHsSquaredOver16) {
  for (const double gamma : {1.0, 3.3, 5.0}) {
    const double hs = 2.0, tp = 7.0;
    double sum = 0.0;
    const double dw = 1e-4;
    for (double w = dw; w < 20.0; w += dw) sum += jonswap(w, hs, tp, gamma) * dw;
    // The DNV normalisation 1 − 0.287 ln γ is an approximation good to ≈ 1 % for γ ≤ 5.
    EXPECT_NEAR(sum, hs * hs / 16.0, 0.015 * hs * hs / 16.0) << "gamma " << gamma;
  }
}

TEST(Jonswap, PeaksAtTheePeakFrequency) {
  const double wp = 2.0 * M_PI / 8.0;
  EXPECT_GT(jonswap(wp, 2.0, 8.0), jonswap(0.9 * wp, 2.0, 8.0));
  EXPECT_GT(jonswap(wp, 2.0, 8.0), jonswap(1.1 * wp, 2.0, 8.0));
  EXPECT_EQ(jonswap(1.0, 0.0, 8.0), 0.0);
}

TEST(Discretise, ComponentVarianceMatchesTheSpectrumAndIsSeeded) {
  SeaStateParams sea;
  sea.hs_m = 2.0;
  sea.tp_s = 7.0;
  sea.components = 200;
  const auto a = discretise(sea, 42);
  const auto b = discretise(sea, 42);
  const auto c = discretise(sea, 43);
  ASSERT_EQ(a.size(), 200u);
  double variance = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    variance += 0.5 * a[i].amplitude * a[i].amplitude;
    EXPECT_EQ(a[i].phase, b[i].phase);
  }
  EXPECT_NE(a[0].phase, c[0].phase);
  // [0.5, 3]·ω_p holds ≈ 97 % of the JONSWAP energy; random in-bin frequencies add ≈ 2 %.
  EXPECT_NEAR(variance, 0.25, 0.06 * 0.25);
}

TEST(WaveMotion, DerivativesAreConsistentWithPosition) {
  SeaStateParams sea;
  sea.hs_m = 2.0;
  sea.tp_s = 7.0;
  const double dt = 0.01;
  WaveMotion waves(sea, WaveResponseParams{}, 7, dt);
  const WaveMotion6 m0 = waves.motion(0.3);
  waves.advance();
  const WaveMotion6 m1 = waves.motion(0.3);
  waves.advance();
  const WaveMotion6 m2 = waves.motion(0.3);
  for (int dof = 0; dof < 6; ++dof) {
    // Central differences over 2·dt: error ≈ ω²dt²/6 of the velocity amplitude (< 1e-3).
    const double v = (m2.position[dof] - m0.position[dof]) / (2 * dt);
    EXPECT_NEAR(v, m1.velocity[dof], 1e-3 * std::abs(m1.velocity[dof]) + 1e-9) << dof;
    const double a = (m2.velocity[dof] - m0.velocity[dof]) / (2 * dt);
    EXPECT_NEAR(a, m1.acceleration[dof], 1e-3 * std::abs(m1.acceleration[dof]) + 1e-9) << dof;
  }
}

TEST(WaveMotion, DerivativesIncludeTheTurnOfTheHull) {
  // Heading ψ(t) = ψ₀ + r₀t + ½ṙt² while the waves evolve: the velocity and acceleration
  // reported with (ψ̇, ψ̈) must be the derivatives of the position along that path.
  SeaStateParams sea;
  sea.hs_m = 2.0;
  sea.tp_s = 7.0;
  const double dt = 0.01, r0 = 0.05, r_dot = 0.004;
  const auto psi = [&](double t) { return 0.3 + r0 * t + 0.5 * r_dot * t * t; };
  WaveMotion waves(sea, WaveResponseParams{}, 7, dt);
  const WaveMotion6 m0 = waves.motion(psi(0.0), r0, r_dot);
  waves.advance();
  const WaveMotion6 m1 = waves.motion(psi(dt), r0 + r_dot * dt, r_dot);
  waves.advance();
  const WaveMotion6 m2 = waves.motion(psi(2 * dt), r0 + 2 * r_dot * dt, r_dot);
  for (int dof = 0; dof < 6; ++dof) {
    // Same central-difference bound as above; without the turn terms the error would be
    // r₀·|∂x/∂ψ| ≈ 5 % of the velocity, far outside it.
    const double v = (m2.position[dof] - m0.position[dof]) / (2 * dt);
    EXPECT_NEAR(v, m1.velocity[dof], 1e-3 * std::abs(m1.velocity[dof]) + 1e-9) << dof;
    const double a = (m2.velocity[dof] - m0.velocity[dof]) / (2 * dt);
    EXPECT_NEAR(a, m1.acceleration[dof], 1e-3 * std::abs(m1.acceleration[dof]) + 1e-9) << dof;
  }
}

TEST(WaveMotion, HeadSeasGiveNoSwayOrRollAndDriftScalesWithHsSquared) {
  SeaStateParams sea;
  sea.hs_m = 2.0;
  sea.from_rad = 0.0;  // from the north
  WaveMotion waves(sea, WaveResponseParams{}, 1, 0.1);
  for (int k = 0; k < 50; ++k, waves.advance()) {
    const WaveMotion6 m = waves.motion(0.0);  // heading north: head seas
    EXPECT_NEAR(m.position[1], 0.0, 1e-12);   // sin β = 0 up to rounding of π
    EXPECT_NEAR(m.position[3], 0.0, 1e-12);
  }
  SeaStateParams twice = sea;
  twice.hs_m = 4.0;
  const WaveMotion big(twice, WaveResponseParams{}, 1, 0.1);
  const double f1 = waves.drift_force_b(0.0).x();
  EXPECT_LT(f1, 0.0);  // head seas push the vessel astern
  EXPECT_NEAR(big.drift_force_b(0.0).x(), 4.0 * f1, 1e-9 * std::abs(f1));
}

// position_std is the σ of the sampled motion: over 4 h at 2 Hz (28 800 samples, hundreds of
// wave periods) the sample σ of each DOF is within 3 % of it (the components' frequencies are
// incommensurate, so the sample variance converges; 4 h leaves about 1 % of scatter).
TEST(WaveMotion, PositionStdIsTheSigmaOfTheSampledMotion) {
  SeaStateParams sea;
  sea.hs_m = 2.5;
  sea.tp_s = 8.0;
  sea.from_rad = 0.0;
  const double heading = 0.7;  // waves 40° off the bow: every DOF moves
  WaveMotion waves(sea, WaveResponseParams{}, 3, 0.5);
  const Eigen::Matrix<double, 6, 1> sigma = waves.position_std(heading);
  Eigen::Matrix<double, 6, 1> sum = Eigen::Matrix<double, 6, 1>::Zero(), sum2 = sum;
  constexpr int kSamples = 28800;
  for (int k = 0; k < kSamples; ++k, waves.advance()) {
    const Eigen::Matrix<double, 6, 1> x = waves.motion(heading).position;
    sum += x;
    sum2 += x.cwiseAbs2();
  }
  for (int dof = 0; dof < 6; ++dof) {
    const double mean = sum[dof] / kSamples;
    const double sample = std::sqrt(sum2[dof] / kSamples - mean * mean);
    EXPECT_GT(sigma[dof], 0.0) << dof;
    EXPECT_NEAR(sample, sigma[dof], 0.03 * sigma[dof]) << dof;
  }
  EXPECT_EQ(WaveMotion(SeaStateParams{}, WaveResponseParams{}, 1, 0.1).position_std(0.0).norm(),
            0.0);
}

// The unit-height response spectra of sea_state.hpp written out again: the wave amplitude's
// with the hull's short-wave attenuation 1/(1 + (Lk/2π)²)² in surge and sway, times k² in yaw.
double response_spectrum(const SeaStateParams& sea, double length_m, double omega, int dof) {
  const double k = omega * omega / 9.81;
  const double ratio = length_m * k / (2.0 * M_PI);
  const double a = 1.0 / (1.0 + ratio * ratio);
  return jonswap(omega, 1.0, sea.tp_s, sea.gamma) * a * a * (dof == 2 ? k * k : 1.0);
}

TEST(ResponseSpectrum, PeaksNearTheWavesInSurgeAndSwayAndAboveThemInYaw) {
  SeaStateParams sea;
  sea.tp_s = 8.0;
  const double wp = 2.0 * M_PI / sea.tp_s;
  const Eigen::Vector3d peak = response_peak_frequency(sea, WaveResponseParams{});
  // The attenuation pulls the amplitude's peak a little below ω_p; k² pushes the yaw's above.
  EXPECT_NEAR(peak.x(), wp, 0.02 * wp);
  EXPECT_EQ(peak.y(), peak.x());
  EXPECT_GT(peak.z(), peak.x());
  for (int dof = 0; dof < 3; ++dof) {
    const double s = response_spectrum(sea, 31.25, peak[dof], dof);
    EXPECT_GT(s, response_spectrum(sea, 31.25, 0.97 * peak[dof], dof)) << dof;
    EXPECT_GT(s, response_spectrum(sea, 31.25, 1.03 * peak[dof], dof)) << dof;
  }
}

TEST(ResponseSpectrum, VarianceSharesAreTheSpectrumNearestEachComponent) {
  SeaStateParams sea;
  sea.tp_s = 8.0;
  const WaveResponseParams hull;
  const std::vector<double> ratios{1.0, 1.5, 2.0};
  const Eigen::MatrixXd shares = response_variance_shares(sea, hull, ratios);
  ASSERT_EQ(shares.rows(), 3);
  ASSERT_EQ(shares.cols(), 3);
  const Eigen::Vector3d peak = response_peak_frequency(sea, hull);
  const double wp = 2.0 * M_PI / sea.tp_s;
  for (int dof = 0; dof < 3; ++dof) {
    EXPECT_NEAR(shares.row(dof).sum(), 1.0, 1e-12) << dof;
    // Integrated again, finer, over the sea's band [0.5, 3] ω_p, split at the geometric means
    // √1.5 and √3 of the components' frequencies.
    Eigen::Vector3d band = Eigen::Vector3d::Zero();
    const double lo = 0.5 * wp, hi = 3.0 * wp, dw = (hi - lo) / 40000.0;
    for (double w = lo + 0.5 * dw; w < hi; w += dw) {
      const int c = w < std::sqrt(1.5) * peak[dof] ? 0 : w < std::sqrt(3.0) * peak[dof] ? 1 : 2;
      band[c] += response_spectrum(sea, hull.length_m, w, dof) * dw;
    }
    band /= band.sum();
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(shares(dof, c), band[c], 2e-3) << dof << " " << c;
  }
  // Yaw weighs short waves by k²: more of its variance lies in the upper components.
  EXPECT_GT(shares(2, 1) + shares(2, 2), 2.0 * (shares(0, 1) + shares(0, 2)));
  EXPECT_GT(shares(0, 0), 0.8);
  // One component takes it all.
  const Eigen::MatrixXd one = response_variance_shares(sea, hull, {1.0});
  EXPECT_TRUE(one.isApprox(Eigen::MatrixXd::Ones(3, 1)));
}

TEST(ResponseSpectrum, VarianceSharesNeedRatiosFromOneUp) {
  const SeaStateParams sea;
  const WaveResponseParams hull;
  EXPECT_THROW(response_variance_shares(sea, hull, {}), std::invalid_argument);
  EXPECT_THROW(response_variance_shares(sea, hull, {1.5, 2.0}), std::invalid_argument);
  EXPECT_THROW(response_variance_shares(sea, hull, {1.0, 2.0, 2.0}), std::invalid_argument);
}

TEST(WaveMotion, CalmSeaHasNoMotion) {
  WaveMotion waves(SeaStateParams{}, WaveResponseParams{}, 1, 0.1);
  EXPECT_TRUE(waves.components().empty());
  EXPECT_EQ(waves.motion(1.0).position.norm(), 0.0);
}

}  // namespace
}  // namespace dynpos::model
