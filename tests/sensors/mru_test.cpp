#include "dynpos/sensors/mru.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace dynpos::sensors {
namespace {

MruParams noiseless(const Eigen::Vector3d& arm) {
  MruParams p;
  p.lever_arm_b = arm;
  p.angle_std_rad = p.rate_std_rad_s = p.accel_std_mps2 = 0.0;
  return p;
}

TEST(Mru, SteadyTurnGivesCentripetalAccelerationAtTheArm) {
  // Level hull turning at r about the origin (at rest): a point at x = 15 m forward feels
  // −r²·15 m along x (towards the centre of rotation), and nothing else.
  RigidBodyMotion m;
  m.omega_nb_b = {0.0, 0.0, 0.05};
  Mru mru(noiseless({15.0, 0.0, 0.0}), AccelerationConvention::kKinematic, 0.01, 1);
  const MruSample s = mru.measure(m);
  EXPECT_NEAR(s.accel_b.x(), -0.05 * 0.05 * 15.0, 1e-15);
  EXPECT_NEAR(s.accel_b.y(), 0.0, 1e-15);
  EXPECT_NEAR(s.accel_b.z(), 0.0, 1e-15);
  EXPECT_EQ(s.omega_b, m.omega_nb_b);
}

TEST(Mru, SpecificForceConventionAddsGravity) {
  RigidBodyMotion m;
  m.theta = {0.1, 0.0, 0.0};  // 0.1 rad roll at rest: gravity shows on the y axis
  Mru mru(noiseless(Eigen::Vector3d::Zero()), AccelerationConvention::kSpecificForce, 0.01, 1);
  const MruSample s = mru.measure(m);
  EXPECT_NEAR(s.accel_b.y(), -kGravity_mps2 * std::sin(0.1), 1e-12);
  EXPECT_NEAR(s.accel_b.z(), -kGravity_mps2 * std::cos(0.1), 1e-12);
  EXPECT_DOUBLE_EQ(s.roll, 0.1);
}

TEST(Mru, AngleAndRateBiasesAreSlowGaussMarkovErrors) {
  // Biases only (no white noise), σ = 0.05° roll/pitch and 0.01 °/s rates, T = 20 s, sampled at
  // 100 Hz for 4000 s (200 time constants, about 100 independent values): the sample std has a
  // relative standard error of about 7 %, so it must lie within ±25 % of σ. A bias is slow: the
  // change per sample has std σ·√(2(1 − e^(−dt/T))) = 0.032σ (white noise would give 1.41σ).
  MruParams p = noiseless(Eigen::Vector3d::Zero());
  p.angle_bias_std_rad = core::deg_to_rad(0.05);
  p.rate_bias_std_rad_s = core::deg_to_rad(0.01);
  p.angle_bias_time_constant_s = p.rate_bias_time_constant_s = 20.0;
  Mru mru(p, AccelerationConvention::kKinematic, 0.01, 3);
  const RigidBodyMotion m;  // at rest and level: every reading is the error
  std::vector<std::array<double, 5>> e;
  for (int k = 0; k < 400000; ++k) {
    const MruSample s = mru.measure(m);
    e.push_back({s.roll, s.pitch, s.omega_b.x(), s.omega_b.y(), s.omega_b.z()});
  }
  for (std::size_t j = 0; j < 5; ++j) {
    const double sigma = j < 2 ? p.angle_bias_std_rad : p.rate_bias_std_rad_s;
    double sum = 0.0, sum2 = 0.0, step2 = 0.0;
    for (std::size_t k = 0; k < e.size(); ++k) {
      sum += e[k][j];
      sum2 += e[k][j] * e[k][j];
      if (k > 0) step2 += (e[k][j] - e[k - 1][j]) * (e[k][j] - e[k - 1][j]);
    }
    const double n = static_cast<double>(e.size());
    const double std = std::sqrt(sum2 / n - (sum / n) * (sum / n));
    EXPECT_NEAR(std / sigma, 1.0, 0.25) << "channel " << j;
    EXPECT_LT(std::sqrt(step2 / (n - 1.0)), 0.05 * sigma) << "channel " << j;
  }
  // Zero σ draws nothing: the biases leave a noise-free MRU exact.
  Mru exact(noiseless(Eigen::Vector3d::Zero()), AccelerationConvention::kKinematic, 0.01, 3);
  const MruSample s = exact.measure(m);
  EXPECT_EQ(s.roll, 0.0);
  EXPECT_EQ(s.omega_b, Eigen::Vector3d::Zero());
}

TEST(Mru, ConventionNamesRoundTrip) {
  for (auto c : {AccelerationConvention::kKinematic, AccelerationConvention::kSpecificForce}) {
    EXPECT_EQ(parse_acceleration_convention(to_string(c)), c);
  }
  EXPECT_FALSE(parse_acceleration_convention("gravity").has_value());
}

}  // namespace
}  // namespace dynpos::sensors
