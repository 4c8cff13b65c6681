#include "dynpos/calib/attitude_smoother.hpp"

#include <algorithm>
#include <stdexcept>

#include "dynpos/core/rotation.hpp"

namespace dynpos::calib {
namespace {

using Vec3 = Eigen::Vector3d;

// Centred moving average of x over ±half_s [s] (the window is cut at the ends), by prefix sums.
std::vector<Vec3> moving_average(const std::vector<double>& t, const std::vector<Vec3>& x,
                                 double half_s) {
  const std::size_t n = t.size();
  std::vector<Vec3> sum(n + 1, Vec3::Zero());
  for (std::size_t i = 0; i < n; ++i) sum[i + 1] = sum[i] + x[i];
  std::vector<Vec3> out(n);
  std::size_t lo = 0, hi = 0;  // the window [lo, hi)
  for (std::size_t i = 0; i < n; ++i) {
    while (t[lo] < t[i] - half_s) ++lo;
    while (hi < n && t[hi] <= t[i] + half_s) ++hi;
    out[i] = (sum[hi] - sum[lo]) / static_cast<double>(hi - lo);
  }
  return out;
}

}  // namespace

SmoothedAttitude smooth_attitude(const ImuSeries& imu, double window_s) {
  if (!(window_s > 0.0)) throw std::invalid_argument("smooth_attitude: window_s must be > 0");
  const std::size_t n = imu.size();
  if (n < 2) throw std::invalid_argument("smooth_attitude: fewer than 2 samples");
  // Θ_g: the Euler rates integrated (trapezoid) from the first measured attitude.
  std::vector<Vec3> rate(n), gyro(n), diff(n);
  for (std::size_t i = 0; i < n; ++i)
    rate[i] =
        core::euler_rate_matrix(imu.theta_rad[i][0], imu.theta_rad[i][1]) * imu.omega_b_rps[i];
  gyro[0] = imu.theta_rad[0];
  for (std::size_t i = 1; i < n; ++i)
    gyro[i] = gyro[i - 1] + 0.5 * (rate[i] + rate[i - 1]) * (imu.t_s[i] - imu.t_s[i - 1]);
  for (std::size_t i = 0; i < n; ++i) diff[i] = imu.theta_rad[i] - gyro[i];
  SmoothedAttitude out;
  const std::vector<Vec3> low = moving_average(imu.t_s, diff, 0.5 * window_s);
  out.theta_rad.resize(n);
  for (std::size_t i = 0; i < n; ++i) out.theta_rad[i] = gyro[i] + low[i];
  // The drift of Θ_g against the measurement: slope of diff over time, least squares.
  double tm = 0.0;
  for (double t : imu.t_s) tm += t / static_cast<double>(n);
  Vec3 dm = Vec3::Zero();
  for (const Vec3& d : diff) dm += d / static_cast<double>(n);
  double stt = 0.0;
  Vec3 std_ = Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    stt += (imu.t_s[i] - tm) * (imu.t_s[i] - tm);
    std_ += (imu.t_s[i] - tm) * (diff[i] - dm);
  }
  if (stt > 0.0) out.euler_rate_bias_rps = -std_ / stt;
  return out;
}

}  // namespace dynpos::calib
