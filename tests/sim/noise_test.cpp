#include "dynpos/sim/noise.hpp"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "dynpos/sim/sim_time.hpp"

namespace dynpos::sim {
namespace {

// Statistical checks use 5 standard errors: a fresh seed would fail with probability ~6e-7,
// and with the fixed seeds here the outcome is deterministic.
constexpr double kSigmas = 5.0;

double mean(const std::vector<double>& x) {
  double s = 0.0;
  for (double v : x) s += v;
  return s / static_cast<double>(x.size());
}

double std_dev(const std::vector<double>& x) {
  const double m = mean(x);
  double s = 0.0;
  for (double v : x) s += (v - m) * (v - m);
  return std::sqrt(s / static_cast<double>(x.size() - 1));
}

// Sample autocorrelation at lag m.
double autocorrelation(const std::vector<double>& x, std::size_t lag) {
  const double m = mean(x);
  double num = 0.0;
  double den = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    den += (x[i] - m) * (x[i] - m);
    if (i + lag < x.size()) num += (x[i] - m) * (x[i + lag] - m);
  }
  return num / den;
}

TEST(WhiteNoise, SampleMeanAndStdMatch) {
  const double sigma = 0.5;
  WhiteNoise noise(sigma, Rng(11, "gnss.north"));
  constexpr std::size_t kN = 200000;
  std::vector<double> x(kN);
  for (double& v : x) v = noise.sample();
  const double n = static_cast<double>(kN);
  // Standard errors of the mean σ/√N and of the std σ/√(2N) for independent Gaussian samples.
  EXPECT_NEAR(mean(x), 0.0, kSigmas * sigma / std::sqrt(n));
  EXPECT_NEAR(std_dev(x), sigma, kSigmas * sigma / std::sqrt(2.0 * n));
  // Independent samples: lag-1 autocorrelation ~ N(0, 1/N).
  EXPECT_NEAR(autocorrelation(x, 1), 0.0, kSigmas / std::sqrt(n));
  EXPECT_THROW(WhiteNoise(-1.0, Rng(1)), std::invalid_argument);
  EXPECT_DOUBLE_EQ(discrete_std_from_psd(0.1, 0.01), std::sqrt(10.0));
  EXPECT_THROW((void)discrete_std_from_psd(0.1, 0.0), std::invalid_argument);
}

TEST(GaussMarkov, ExactDiscretisationCoefficients) {
  const double t = 50.0;
  const double sigma = 3.0;
  const double dt = 0.01;
  const GaussMarkov b = GaussMarkov::with_stationary_std(t, sigma, dt, Rng(1));
  EXPECT_DOUBLE_EQ(b.phi(), std::exp(-dt / t));
  // The library forms 1 − e^{−2dt/T} by expm1; the direct form here cancels and loses about
  // log₁₀(T/2dt) ≈ 3.4 digits, so agreement to 1e-12 relative is what to expect.
  EXPECT_NEAR(b.step_std() / (sigma * std::sqrt(1.0 - std::exp(-2.0 * dt / t))), 1.0, 1e-12);
  // The stationary variance is a fixed point of Var ← φ²·Var + s².
  EXPECT_DOUBLE_EQ(b.phi() * b.phi() * sigma * sigma + b.step_std() * b.step_std(), sigma * sigma);
  // The same process given by its driving intensity q = σ·√(2/T).
  const GaussMarkov c =
      GaussMarkov::with_noise_intensity(t, sigma * std::sqrt(2.0 / t), dt, Rng(1));
  EXPECT_DOUBLE_EQ(c.stationary_std(), sigma);
  EXPECT_DOUBLE_EQ(c.step_std(), b.step_std());
}

TEST(GaussMarkov, RandomWalkIsTheLimitOfLargeTimeConstant) {
  const double q = 0.2;
  const double dt = 0.1;
  const GaussMarkov walk = GaussMarkov::random_walk(q, dt, Rng(1));
  EXPECT_EQ(walk.phi(), 1.0);
  EXPECT_DOUBLE_EQ(walk.step_std(), q * std::sqrt(dt));
  EXPECT_TRUE(std::isinf(walk.stationary_std()));
  // T = 10⁹ s: φ = 1 − 1e-10 and the increment std differs from q·√dt by a relative dt/(2T).
  const GaussMarkov slow = GaussMarkov::with_noise_intensity(1e9, q, dt, Rng(1));
  EXPECT_NEAR(slow.phi(), 1.0, 1e-9);
  EXPECT_NEAR(slow.step_std() / walk.step_std(), 1.0, 1e-9);
  GaussMarkov stepped = GaussMarkov::random_walk(q, dt, Rng(5));
  EXPECT_THROW(stepped.reset_stationary(), std::logic_error);
  EXPECT_THROW((void)GaussMarkov::with_stationary_std(std::numeric_limits<double>::infinity(), 1.0,
                                                      dt, Rng(1)),
               std::invalid_argument);
  // Increments b_{k+1} − b_k are independent N(0, q²·dt).
  constexpr std::size_t kN = 100000;
  std::vector<double> increments(kN);
  for (double& d : increments) {
    const double before = stepped.value();
    d = stepped.step() - before;
  }
  const double s = q * std::sqrt(dt);
  EXPECT_NEAR(std_dev(increments), s, kSigmas * s / std::sqrt(2.0 * kN));
}

TEST(GaussMarkov, StationaryStdAndCorrelationTime) {
  const double t = 1.0;
  const double sigma = 2.0;
  const double dt = 0.1;
  GaussMarkov b = GaussMarkov::with_stationary_std(t, sigma, dt, Rng(2024, "wave.drift"));
  b.reset_stationary();
  constexpr std::size_t kN = 1000000;
  std::vector<double> x(kN);
  for (double& v : x) v = b.step();
  const double n = static_cast<double>(kN);
  const double phi = std::exp(-dt / t);
  const double phi2 = phi * phi;
  // Correlated samples (AR(1)): the std's relative standard error is √((1 + φ²)/(1 − φ²)/(2N)),
  // about 0.22 % here.
  const double std_rel_se = std::sqrt((1.0 + phi2) / (1.0 - phi2) / (2.0 * n));
  EXPECT_NEAR(std_dev(x) / sigma, 1.0, kSigmas * std_rel_se);
  // The mean's standard error is σ·√((1 + φ)/(1 − φ)/N).
  EXPECT_NEAR(mean(x), 0.0, kSigmas * sigma * std::sqrt((1.0 + phi) / (1.0 - phi) / n));
  // Lag-1 autocorrelation is φ = e^{−dt/T} with standard error √((1 − φ²)/N); the correlation
  // time T̂ = −dt/ln ρ̂ has standard error se(ρ̂)·dt/(ρ·ln²ρ) by the delta method (~0.5 %).
  const double rho1 = autocorrelation(x, 1);
  const double rho1_se = std::sqrt((1.0 - phi2) / n);
  EXPECT_NEAR(rho1, phi, kSigmas * rho1_se);
  const double t_hat = -dt / std::log(rho1);
  const double t_se = rho1_se * dt / (phi * std::log(phi) * std::log(phi));
  EXPECT_NEAR(t_hat, t, kSigmas * t_se);
  // At lag m = T/dt the autocorrelation is e^{−1}; Bartlett's formula for AR(1) gives its
  // variance ((1 + φ²)(1 − φ^{2m})/(1 − φ²) − 2m·φ^{2m})/N.
  const std::size_t m = 10;
  const double phi2m = std::pow(phi, 2.0 * m);
  const double rho_m_se = std::sqrt(
      ((1.0 + phi2) * (1.0 - phi2m) / (1.0 - phi2) - 2.0 * static_cast<double>(m) * phi2m) / n);
  EXPECT_NEAR(autocorrelation(x, m), std::exp(-1.0), kSigmas * rho_m_se);
}

TEST(GaussMarkov, SeedsAndStreamsGiveReproducibleDistinctSequences) {
  const auto draw = [](Rng rng) {
    GaussMarkov b = GaussMarkov::with_stationary_std(5.0, 1.0, 0.1, rng);
    std::vector<double> x(1000);
    for (double& v : x) v = b.step();
    return x;
  };
  EXPECT_EQ(draw(Rng(7, "current")), draw(Rng(7, "current")));
  EXPECT_NE(draw(Rng(7, "current")), draw(Rng(8, "current")));
  EXPECT_NE(draw(Rng(7, "current")), draw(Rng(7, "wind")));
  // Streams do not interfere: drawing from one source leaves another's numbers unchanged.
  Rng wind(7, "wind");
  for (int i = 0; i < 100; ++i) (void)wind.normal();
  EXPECT_EQ(draw(Rng(7, "current")), draw(Rng(7, "current")));
}

TEST(Quantize, RoundsToTheNearestMultiple) {
  struct Case {
    double value;
    double resolution;
    double expected;
  };
  const Case cases[] = {
      {0.0, 0.5, 0.0},    {1.26, 0.5, 1.5},  {-1.26, 0.5, -1.5}, {0.25, 0.5, 0.5},
      {-0.25, 0.5, -0.5}, {1.24, 0.5, 1.0},  {3.7, 0.0, 3.7},    {1234.5678, 1.0, 1235.0},
      {1e-9, 0.01, 0.0},  {-7.0, 2.0, -8.0},
  };
  for (const Case& c : cases) {
    EXPECT_DOUBLE_EQ(quantize(c.value, c.resolution), c.expected) << c.value << " " << c.resolution;
    // Idempotent: a quantised value is already on the grid.
    EXPECT_DOUBLE_EQ(quantize(quantize(c.value, c.resolution), c.resolution), c.expected);
  }
  EXPECT_TRUE(std::isnan(quantize(std::numeric_limits<double>::quiet_NaN(), 0.1)));
  EXPECT_THROW((void)quantize(1.0, -0.1), std::invalid_argument);
}

TEST(DelayLine, DelaysByAnIntegerNumberOfTicks) {
  const TimeGrid grid(0.01);
  const auto delay = static_cast<std::size_t>(grid.ticks(0.03, "gnss delay"));
  DelayLine<double> line(delay, std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(line.delay(), 3u);
  std::vector<double> out;
  for (int k = 1; k <= 8; ++k) out.push_back(line.push(k));
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(std::isnan(out[k])) << "missing until filled";
  for (int k = 3; k < 8; ++k) EXPECT_EQ(out[k], k - 2);

  DelayLine<double> none(0, -1.0);
  EXPECT_EQ(none.push(5.0), 5.0);

  DelayLine<Eigen::Vector3d> vectors(1, Eigen::Vector3d::Zero());
  EXPECT_EQ(vectors.push(Eigen::Vector3d(1, 2, 3)), Eigen::Vector3d::Zero());
  EXPECT_EQ(vectors.push(Eigen::Vector3d(4, 5, 6)), Eigen::Vector3d(1, 2, 3));
}

}  // namespace
}  // namespace dynpos::sim
