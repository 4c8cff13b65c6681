// The MRU series of a log, its noise level from second differences, the attitude smoother and
// the integrals of the accelerations (imu_series.hpp, attitude_smoother.hpp,
// ins_preintegration.hpp) against exact figures.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "dynpos/calib/attitude_smoother.hpp"
#include "dynpos/calib/imu_series.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/core/rotation.hpp"
#include "ins_preintegration.hpp"

namespace dynpos::calib {
namespace {

using Vec3 = Eigen::Vector3d;

// An MRU at 100 Hz and a gyro compass at 10 Hz (blank cells between its samples).
core::Log mixed_log(std::size_t n) {
  std::vector<double> t(n), heading(n, core::kMissing);
  for (std::size_t i = 0; i < n; ++i) t[i] = 0.01 * static_cast<double>(i);
  core::Log log(t);
  for (const char* f : {"roll", "pitch", "p", "q", "r", "ax", "ay", "az"})
    log.add_channel(std::string("mru1.") + f, "", std::vector<double>(n, 0.1));
  for (std::size_t i = 0; i < n; i += 10) heading[i] = 3.1 + 0.001 * static_cast<double>(i);
  log.add_channel("heading", "rad", heading);
  return log;
}

TEST(ImuSeries, ReadsTheMruAndInterpolatesTheHeadingUnwrapped) {
  const core::Log log = mixed_log(1001);
  const ImuSeries imu = imu_from_log(log, "mru1", MruAccel::kSpecificForce);
  ASSERT_EQ(imu.size(), 1001U);
  EXPECT_EQ(imu.accel, MruAccel::kSpecificForce);
  // Heading 3.1 + 0.001·i crosses π at i ≈ 42 and stays continuous (no 2π jump).
  EXPECT_NEAR(imu.theta_rad[505][2], 3.1 + 0.505, 1e-12);
  EXPECT_DOUBLE_EQ(imu.accel_b_mps2[7][2], 0.1);
  EXPECT_EQ(imu_names(log), std::vector<std::string>{"mru1"});
  EXPECT_EQ(mru_accel_names(log), std::vector<std::string>{"mru1"});
}

TEST(ImuSeries, AMissingRoleOrTooFewRowsIsAnInputError) {
  core::Log log = mixed_log(1001);
  try {
    imu_from_log(log, "mru2", MruAccel::kKinematic);
    FAIL() << "mru2 is not in the log";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.where().column_name, "mru2.roll");
  }
  EXPECT_THROW(imu_from_log(mixed_log(50), "mru1", MruAccel::kKinematic), core::InputError);
}

TEST(ImuSeries, WhiteNoiseLevelFromSecondDifferencesIgnoresTheShipMotion) {
  std::mt19937_64 rng(4);
  std::normal_distribution<double> n01;
  std::vector<Vec3> a(20000);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double t = 0.01 * static_cast<double>(i);
    a[i] = Vec3(0.5 * std::sin(0.9 * t), 0.3 * std::cos(0.6 * t), 0.0) +
           Vec3(0.01 * n01(rng), 0.02 * n01(rng), 0.005 * n01(rng));
  }
  const Vec3 s = white_noise_std(a);
  // 20 000 samples: the robust estimate's own scatter is about 1.5 %.
  EXPECT_NEAR(s[0], 0.01, 0.0005);
  EXPECT_NEAR(s[1], 0.02, 0.001);
  EXPECT_NEAR(s[2], 0.005, 0.00025);
}

TEST(AttitudeSmoother, RemovesAnglesNoiseAndKeepsTheMotion) {
  ImuSeries imu;
  std::mt19937_64 rng(9);
  std::normal_distribution<double> n01;
  for (int i = 0; i <= 30000; ++i) {
    const double t = 0.01 * i;
    imu.t_s.push_back(t);
    // Roll oscillating, level pitch, a constant turn; the gyros read p 0.001 rad/s high.
    const double roll = 0.05 * std::sin(0.7 * t);
    const Vec3 euler_rate(0.035 * std::cos(0.7 * t), 0.0, 0.03);
    imu.omega_b_rps.push_back(core::euler_rate_matrix_inverse(roll, 0.0) * euler_rate +
                              Vec3(0.001, 0.0, 0.0));
    imu.theta_rad.emplace_back(0.05 * std::sin(0.7 * t) + 3.5e-4 * n01(rng), 3.5e-4 * n01(rng),
                               0.03 * t + 8.7e-4 * n01(rng));
  }
  const SmoothedAttitude s = smooth_attitude(imu, 1.0);
  double worst = 0.0;
  for (int i = 200; i <= 29800; ++i) {
    const double t = 0.01 * i;
    const Vec3 truth(0.05 * std::sin(0.7 * t), 0.0, 0.03 * t);
    worst =
        std::max(worst, (s.theta_rad[static_cast<std::size_t>(i)] - truth).cwiseAbs().maxCoeff());
  }
  // White noise of 0.02°, 0.02° and 0.05° averaged over 100 samples: ≈ 0.005° σ; 5σ bound.
  EXPECT_LT(worst, 4.5e-4);
  // The gyro's roll rate reads 0.001 rad/s too high: its bias against the angles.
  EXPECT_NEAR(s.euler_rate_bias_rps[0], 0.001, 1e-5);
  EXPECT_NEAR(s.euler_rate_bias_rps[2], 0.0, 1e-5);
}

TEST(InsPreintegration, ExactForAccelerationsLinearBetweenSamples) {
  // Level, heading 0 (R = I), a(t) = (1 + 0.5t, −2, 0.3t) sampled at 10 Hz, kinematic.
  ImuSeries imu;
  std::vector<Vec3> theta;
  for (int i = 0; i <= 100; ++i) {
    const double t = 0.1 * i;
    imu.t_s.push_back(t);
    imu.accel_b_mps2.emplace_back(1.0 + 0.5 * t, -2.0, 0.3 * t);
    imu.omega_b_rps.emplace_back(0.0, 0.0, 0.0);
    theta.emplace_back(0.0, 0.0, 0.0);
  }
  const detail::InsPreintegration ins(imu, theta, 9.81);
  const double a = 2.03, s = 7.77, h = s - a;
  const detail::InsDelta d = ins.delta(a, s);
  // ∫ₐˢ a dτ and ∫ₐˢ (s − τ)·a dτ for a = c₀ + c₁τ.
  auto v = [](double c0, double c1, double a, double s) {
    return c0 * (s - a) + 0.5 * c1 * (s * s - a * a);
  };
  auto p = [](double c0, double c1, double a, double s) {
    const double h = s - a;
    return c0 * h * h / 2.0 + c1 * (a * h * h / 2.0 + h * h * h / 6.0);
  };
  EXPECT_NEAR(d.dv[0], v(1.0, 0.5, a, s), 1e-12);
  EXPECT_NEAR(d.dv[1], v(-2.0, 0.0, a, s), 1e-12);
  EXPECT_NEAR(d.dp[0], p(1.0, 0.5, a, s), 1e-11);
  EXPECT_NEAR(d.dp[2], p(0.0, 0.3, a, s), 1e-11);
  EXPECT_NEAR(d.Mv(0, 0), h, 1e-12);
  EXPECT_NEAR(d.Mp(1, 1), h * h / 2.0, 1e-12);
  EXPECT_NEAR(d.Mp(0, 1), 0.0, 1e-15);
  // Backwards gives the same integrals negated for the velocity.
  EXPECT_NEAR(ins.delta(s, a).dv[0], -d.dv[0], 1e-12);
}

}  // namespace
}  // namespace dynpos::calib
