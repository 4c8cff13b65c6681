#include "dynpos/analysis/inertial_bridge.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "dynpos/core/rotation.hpp"

namespace dynpos::analysis {
namespace {

constexpr double kDt = 0.1;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const Eigen::Vector3d kArm(3.0, -1.0, -4.0);  // the MRU from the control origin (BODY) [m]

// A vessel under DP: wave motion of the MRU's point P in N and E on a slow drift, the heading
// swinging through 20°, roll and pitch at the waves.
double heading(double t) { return 0.3 + 0.17 * std::sin(0.05 * t); }
double roll(double t) { return 0.05 * std::sin(0.9 * t); }
double pitch(double t) { return 0.02 * std::cos(0.7 * t); }
Eigen::Vector2d point_position(double t) {
  return {0.5 * std::sin(0.8 * t) + 0.02 * t, 0.3 * std::cos(1.1 * t) - 0.01 * t};
}
Eigen::Vector2d point_accel(double t) {
  return {-0.32 * std::sin(0.8 * t), -0.363 * std::cos(1.1 * t)};
}
Eigen::Matrix3d attitude(double t) { return core::R_nb_zyx(roll(t), pitch(t), heading(t)); }
// The control origin: P less the arm turned by the attitude.
Eigen::Vector2d origin(double t) { return point_position(t) - (attitude(t) * kArm).head<2>(); }

// Rows at 10 Hz for 200 s, fixes at 1 Hz except over [100, 130) s. The MRU's sample at t is P's
// acceleration at t as specific force: in BODY, with gravity in it.
BridgeSeries series() {
  BridgeSeries s;
  for (int k = 0; k <= 2000; ++k) {
    const double t = k * kDt;
    s.t_s.push_back(t);
    const bool fix = k % 10 == 0 && !(t >= 100.0 && t < 130.0);
    s.north_m.push_back(fix ? origin(t).x() : kNaN);
    s.east_m.push_back(fix ? origin(t).y() : kNaN);
    s.heading_rad.push_back(heading(t));
    s.roll_rad.push_back(roll(t));
    s.pitch_rad.push_back(pitch(t));
    const Eigen::Vector2d a_n = point_accel(t);
    const Eigen::Vector3d f_n(a_n.x(), a_n.y(), -9.81);
    s.accel_b.push_back(attitude(t).transpose() * f_n);
  }
  return s;
}

control::InertialPositionTuning tuning() {
  control::InertialPositionTuning t;
  t.accel_bias_std_mps2 = 0.0;
  return t;
}

TEST(InertialBridge, FillsAGapLongerThanTheHoldAtTheControlOrigin) {
  const BridgeSeries s = series();
  const BridgedTrack b = bridge_gnss_gaps(s, kArm, tuning(), 5.0);
  // The gap runs from the fix of 99 s to that of 130 s: longer than the hold, so each of its
  // rows is bridged, from its first.
  EXPECT_EQ(b.bridged_rows, 309u);  // 99.1 … 129.9 s
  EXPECT_NEAR(b.longest_gap_bridged_s, 31.0, 1e-9);
  double worst_m = 0.0;
  for (std::size_t i = 0; i < s.t_s.size(); ++i) {
    const double t = s.t_s[i];
    if (!std::isnan(s.north_m[i])) {
      EXPECT_EQ(b.north_m[i], s.north_m[i]);  // a fix is kept
    } else if (t > 99.0 + 1e-9 && t < 130.0) {
      ASSERT_FALSE(std::isnan(b.north_m[i])) << t;
      worst_m = std::max(worst_m, (Eigen::Vector2d(b.north_m[i], b.east_m[i]) - origin(t)).norm());
    } else {
      EXPECT_TRUE(std::isnan(b.north_m[i]) && std::isnan(b.east_m[i])) << t;  // a 1 s gap
    }
  }
  // With exact fixes and accelerations only the trapezoid on the samples at each interval's
  // ends (its velocity error dt²/12 times the jerk, 2.2e-4 m/s at 0.26 m/s³, is what the
  // 1 Hz fixes leave at the loss: 6.6 mm in 30 s) and the velocity's convergence remain; the
  // attitude moves the 5 m arm by up to 0.9 m, which a wrong turn would leave.
  EXPECT_LT(worst_m, 0.02);
  // The levelled readings' means: P's wave motion averages out; gravity is all down.
  EXPECT_LT(b.mean_horizontal_accel_mps2, 0.01);
  EXPECT_NEAR(b.mean_down_accel_mps2, -9.81, 1e-9);
}

TEST(InertialBridge, AStaleAccelerationEndsTheBridge) {
  // The MRU stops at 110 s, within the gap: its last sample is not held through the rest of it.
  BridgeSeries s = series();
  for (std::size_t i = 1100; i < s.t_s.size(); ++i) {
    s.accel_b[i] = Eigen::Vector3d::Constant(kNaN);
  }
  const BridgedTrack b = bridge_gnss_gaps(s, kArm, tuning(), 5.0);
  EXPECT_EQ(b.bridged_rows, 109u);  // 99.1 … 109.9 s
  EXPECT_FALSE(std::isnan(b.north_m[1099]));
  EXPECT_TRUE(std::isnan(b.north_m[1100]));
  EXPECT_TRUE(std::isnan(b.north_m[1299]));
}

TEST(InertialBridge, AWrongAttitudeShowsInTheMeans) {
  // Roll read in degrees as radians (57 times the true angle) and a 3° heel: the readings
  // turned by it leave gravity off the down axis.
  BridgeSeries s = series();
  for (double& r : s.roll_rad) r = r * 180.0 / 3.141592653589793 + 0.05;
  const BridgedTrack b = bridge_gnss_gaps(s, kArm, tuning(), 5.0);
  EXPECT_GT(std::min(std::abs(b.mean_down_accel_mps2), std::abs(b.mean_down_accel_mps2 + 9.81)),
            0.5);
}

TEST(InertialBridge, TheArmMatters) {
  // The same series bridged as if the MRU sat at the control origin: off by the arm, turned.
  const BridgeSeries s = series();
  const BridgedTrack b = bridge_gnss_gaps(s, Eigen::Vector3d::Zero(), tuning(), 5.0);
  const std::size_t i = 1299;  // 129.9 s
  ASSERT_NEAR(s.t_s[i], 129.9, 1e-9);
  // The turned arm moves by |(R(129.9 s) − R(99 s)) r| over the gap (0.46 m here), and its
  // turning rate is in P's velocity: a bridge that leaves the arm out misses at least half of
  // that (measured 0.84 m, against under 2 cm with it).
  const double arm_moved_m = ((attitude(129.9) - attitude(99.0)) * kArm).head<2>().norm();
  EXPECT_GT(arm_moved_m, 0.4);
  EXPECT_GT((Eigen::Vector2d(b.north_m[i], b.east_m[i]) - origin(s.t_s[i])).norm(),
            0.5 * arm_moved_m);
}

TEST(InertialBridge, NoBridgeWithoutTheAttitude) {
  BridgeSeries s = series();
  for (double& r : s.roll_rad) r = kNaN;
  const BridgedTrack b = bridge_gnss_gaps(s, kArm, tuning(), 5.0);
  EXPECT_EQ(b.bridged_rows, 0u);
  for (std::size_t i = 0; i < s.t_s.size(); ++i) {
    EXPECT_EQ(std::isnan(b.north_m[i]), std::isnan(s.north_m[i]));
  }
}

TEST(InertialBridge, RejectsSeriesOfUnequalLengths) {
  BridgeSeries s = series();
  s.accel_b.pop_back();
  EXPECT_THROW(bridge_gnss_gaps(s, kArm, tuning(), 5.0), std::invalid_argument);
  s = series();
  s.pitch_rad.pop_back();
  EXPECT_THROW(bridge_gnss_gaps(s, kArm, tuning(), 5.0), std::invalid_argument);
  s = series();
  s.t_s[10] = s.t_s[9];
  EXPECT_THROW(bridge_gnss_gaps(s, kArm, tuning(), 5.0), std::invalid_argument);
}

}  // namespace
}  // namespace dynpos::analysis
