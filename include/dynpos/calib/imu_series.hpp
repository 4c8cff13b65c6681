#pragma once
/// \file
/// What a vessel logger holds of its motion reference unit (MRU/IMU) and gyro compass: roll and
/// pitch, BODY angular rates and accelerations at the unit's own place, and the heading, on the
/// unit's time axis in SI. The input of the logger-only lever-arm estimator (ins_arms.hpp).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "dynpos/calib/mru_observer.hpp"
#include "dynpos/core/log.hpp"

namespace dynpos::calib {

/// One MRU and the heading, sample by sample. Every vector has the length of `t_s`.
struct ImuSeries {
  std::string name;                           ///< role prefix of the unit, "mru1"
  MruAccel accel = MruAccel::kKinematic;      ///< what accel_b_mps2 holds
  std::vector<double> t_s;                    ///< strictly increasing [s]
  std::vector<Eigen::Vector3d> theta_rad;     ///< (φ, θ, ψ) ZYX (2.4); ψ unwrapped [rad]
  std::vector<Eigen::Vector3d> omega_b_rps;   ///< (p, q, r) [rad/s]
  std::vector<Eigen::Vector3d> accel_b_mps2;  ///< at the unit, BODY axes [m/s²]
  /// Median spacing of the heading's own samples [s] (0.1 for a 10 Hz gyro, 1 s for HDT in a
  /// GNSS capture): between them the heading is interpolated and misses the yaw motion.
  double heading_spacing_s = 0.0;
  std::vector<std::string> notes;  ///< what was assumed on the way

  std::size_t size() const noexcept { return t_s.size(); }
};

/// The unit NAME of `log`: roles NAME.roll, NAME.pitch, NAME.p, NAME.q, NAME.r, NAME.ax,
/// NAME.ay, NAME.az on the rows where all are present, and `heading` (any rate) interpolated
/// linearly onto them (unwrapped); rows outside the heading's samples are dropped. Throws
/// core::InputError naming a missing role, or when fewer than 100 rows remain.
ImuSeries imu_from_log(const core::Log& log, const std::string& name, MruAccel accel);

/// The MRU prefixes mruK of `log` that carry every role imu_from_log() needs but the heading,
/// in K order.
std::vector<std::string> imu_names(const core::Log& log);

/// The MRU prefixes mruK of `log` with all of mruK.ax, mruK.ay, mruK.az, in K order.
std::vector<std::string> mru_accel_names(const core::Log& log);

/// The per-sample white-noise σ of each axis of a uniformly sampled series, from second
/// differences: for white noise var(x[i+1] − 2x[i] + x[i−1]) = 6σ², while a ship's motion
/// (below 2 Hz) barely shows in them at a logger's 10–100 Hz. Robust (median absolute
/// deviation), so a few spikes do not count. Zero for fewer than 3 samples.
Eigen::Vector3d white_noise_std(const std::vector<Eigen::Vector3d>& x);

}  // namespace dynpos::calib
