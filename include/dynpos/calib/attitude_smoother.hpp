#pragma once
/// \file
/// The attitude of an MRU and gyro compass with their white noise removed: the Euler rates
/// Θ̇ = T(Θ)·ω of the gyros are integrated, and the difference to the measured attitude, which
/// holds the measurement noise, the gyro bias and the integration drift, is low-passed by a
/// centred moving average (a complementary filter run without phase lag). The measured angles'
/// noise then averages over the window while the rate gyros carry the motion inside it.

#include <Eigen/Core>
#include <vector>

#include "dynpos/calib/imu_series.hpp"

namespace dynpos::calib {

struct SmoothedAttitude {
  std::vector<Eigen::Vector3d> theta_rad;  ///< (φ, θ, ψ) per sample of the series [rad]
  /// The bias of the Euler rates of the gyros against the measured angles (the slope of their
  /// difference, least squares) [rad/s]; it does not enter theta_rad.
  Eigen::Vector3d euler_rate_bias_rps = Eigen::Vector3d::Zero();
};

/// Smooths the attitude of `imu` over `window_s` [s] (> 0; a window of one sample returns the
/// measured angles). The series needs ≥ 2 samples.
SmoothedAttitude smooth_attitude(const ImuSeries& imu, double window_s);

}  // namespace dynpos::calib
