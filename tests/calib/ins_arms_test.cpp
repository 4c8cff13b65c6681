// The logger-only arm estimator (ins_arms.hpp) on exact kinematics: a vessel turning at a
// changing rate while it rolls, pitches and heaves, the MRU's accelerations a = Rᵀ·P̈ computed
// from the analytic motion, and fixes z = P(t − δ) + R(t − δ)·d. Without noise the estimate
// must return the arms, the offset and the bias; the options and data problems are checked.

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "dynpos/calib/ins_arms.hpp"
#include "dynpos/core/rotation.hpp"

namespace dynpos::calib {
namespace {

using Vec3 = Eigen::Vector3d;

// Θ(t) = (φ, θ, ψ) with its rate, and the MRU point P(t) with its acceleration.
struct Motion {
  static Vec3 theta(double t) {
    return {0.04 * std::sin(0.9 * t), 0.02 * std::sin(1.1 * t + 0.3),
            0.3 * std::sin(2.0 * M_PI * t / 150.0) + 0.02 * t};
  }
  static Vec3 theta_dot(double t) {
    return {0.036 * std::cos(0.9 * t), 0.022 * std::cos(1.1 * t + 0.3),
            0.3 * 2.0 * M_PI / 150.0 * std::cos(2.0 * M_PI * t / 150.0) + 0.02};
  }
  static Vec3 p(double t) {
    return {100.0 * std::sin(0.01 * t) + 0.2 * std::sin(0.7 * t),
            80.0 * (1.0 - std::cos(0.012 * t)), 0.4 * std::sin(0.8 * t + 1.0)};
  }
  static Vec3 p_ddot(double t) {
    return {-0.01 * std::sin(0.01 * t) - 0.098 * std::sin(0.7 * t),
            80.0 * 0.000144 * std::cos(0.012 * t), -0.256 * std::sin(0.8 * t + 1.0)};
  }
  static Eigen::Matrix3d R(double t) {
    const Vec3 th = theta(t);
    return core::R_nb_zyx(th[0], th[1], th[2]);
  }
};

ImuSeries imu_series(double duration_s, double rate_hz, const Vec3& bias_b) {
  ImuSeries imu;
  imu.name = "mru1";
  const auto n = static_cast<std::size_t>(duration_s * rate_hz) + 1;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / rate_hz;
    const Vec3 th = Motion::theta(t);
    imu.t_s.push_back(t);
    imu.theta_rad.push_back(th);
    imu.omega_b_rps.push_back(core::euler_rate_matrix_inverse(th[0], th[1]) * Motion::theta_dot(t));
    imu.accel_b_mps2.push_back(Motion::R(t).transpose() * Motion::p_ddot(t) + bias_b);
  }
  return imu;
}

GnssSeries antenna(const std::string& name, const Vec3& d_b, double delay_s, double from_s,
                   double to_s, double rate_hz) {
  GnssSeries g;
  g.name = name;
  for (double t = from_s; t <= to_s; t += 1.0 / rate_hz) {
    g.t_s.push_back(t);
    g.p_n_m.push_back(Motion::p(t - delay_s) + Motion::R(t - delay_s) * d_b);
  }
  return g;
}

const Vec3 kArm1(0.5, -0.6, -9.5), kArm2(1.9, 0.7, -9.2);

TEST(InsArms, ExactKinematicsGiveTheArmsOffsetAndBias) {
  const Vec3 bias(0.003, -0.002, 0.001);
  const ImuSeries imu = imu_series(300.0, 100.0, bias);
  const std::vector<GnssSeries> gnss = {antenna("gnss1", kArm1, 0.15, 2.0, 298.0, 2.0),
                                        antenna("gnss2", kArm2, 0.15, 2.0, 298.0, 2.0)};
  const InsArmResult r = estimate_ins_arms(imu, gnss);
  ASSERT_EQ(r.status, core::Status::kOk) << r.message;
  EXPECT_EQ(r.reference, "mru1");
  ASSERT_EQ(r.arms.size(), 2U);
  // 1 mm: what is left is the attitude smoother's and the integration's O(dt²) error.
  EXPECT_LT((r.arms[0].l_b_m - kArm1).cwiseAbs().maxCoeff(), 1e-3) << r.arms[0].l_b_m.transpose();
  EXPECT_LT((r.arms[1].l_b_m - kArm2).cwiseAbs().maxCoeff(), 1e-3) << r.arms[1].l_b_m.transpose();
  EXPECT_TRUE(r.time_offset_estimated);
  EXPECT_NEAR(r.time_offset_s, 0.15, 1e-3);
  EXPECT_LT((r.accel_bias_b_mps2 - bias).cwiseAbs().maxCoeff(), 1e-4);
  EXPECT_EQ(r.fixes, 2U * 593U);
  for (const ArmEstimate& a : r.arms)
    for (const Determinacy d : a.determinacy) EXPECT_EQ(d, Determinacy::kWell);
  EXPECT_TRUE(r.advice.empty());
}

TEST(InsArms, AGivenImuArmPutsEveryArmFromTheControlOrigin) {
  const ImuSeries imu = imu_series(200.0, 50.0, Vec3::Zero());
  const std::vector<GnssSeries> gnss = {antenna("gnss1", kArm1, 0.0, 2.0, 198.0, 1.0)};
  InsArmOptions o;
  o.estimate_time_offset = false;
  const InsArmResult from_imu = estimate_ins_arms(imu, gnss, o);
  o.imu_arm_b_m = Vec3(0.358, 0.804, -4.321);
  const InsArmResult from_co = estimate_ins_arms(imu, gnss, o);
  ASSERT_EQ(from_co.status, core::Status::kOk);
  EXPECT_EQ(from_co.reference, "co");
  EXPECT_FALSE(from_co.time_offset_estimated);
  EXPECT_TRUE(std::isnan(from_co.time_offset_std_s));
  EXPECT_LT((from_co.arms[0].l_b_m - from_imu.arms[0].l_b_m - *o.imu_arm_b_m).norm(), 1e-9);
  EXPECT_LT((from_imu.arms[0].l_b_m - kArm1).cwiseAbs().maxCoeff(), 2e-3);
}

TEST(InsArms, FixesOutsideTheMruTimeAreAFailureWithAMessage) {
  const ImuSeries imu = imu_series(20.0, 100.0, Vec3::Zero());
  const std::vector<GnssSeries> gnss = {antenna("gnss1", kArm1, 0.0, 30.0, 60.0, 1.0)};
  const InsArmResult r = estimate_ins_arms(imu, gnss);
  EXPECT_EQ(r.status, core::Status::kFailed);
  EXPECT_NE(r.message.find("0 fixes lie inside the MRU's time"), std::string::npos) << r.message;
}

TEST(InsArms, OptionsOutOfRangeThrow) {
  InsArmOptions o;
  o.max_time_offset_s = 0.0;
  EXPECT_THROW(o.validate(), std::invalid_argument);
  o = {};
  o.time_offset_s = 2.0;  // beyond the default bound of 1 s while estimated
  EXPECT_THROW(o.validate(), std::invalid_argument);
  o = {};
  o.trace_probes = 0;
  EXPECT_THROW(o.validate(), std::invalid_argument);
  o = {};
  o.accel_bias_prior_std_mps2 = 0.0;
  EXPECT_THROW(o.validate(), std::invalid_argument);
  EXPECT_NO_THROW(InsArmOptions{}.validate());
}

}  // namespace
}  // namespace dynpos::calib
