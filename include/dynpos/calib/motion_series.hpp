#pragma once
/// \file
/// The vessel motion the lever-arm estimators run on (thesis ch. 4): attitude, angular rate and
/// linear velocity of the BODY frame, sample by sample, in SI. Built from a log through the
/// roles roll, pitch, heading, p, q, r, u, v, w.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "dynpos/core/log.hpp"

namespace dynpos::calib {

/// Motion samples on one time axis. Every vector has the length of `t_s`; every value is finite.
struct MotionSeries {
  std::vector<double> t_s;                   ///< strictly increasing [s]
  std::vector<Eigen::Vector3d> theta_rad;    ///< (roll φ, pitch θ, heading ψ), ZYX (2.4) [rad]
  std::vector<Eigen::Vector3d> omega_b_rps;  ///< (p, q, r) in BODY [rad/s]; empty if not asked
  std::vector<Eigen::Vector3d> v_b_mps;      ///< (u, v, w) in BODY [m/s]; empty if not asked

  std::size_t size() const noexcept { return t_s.size(); }
};

/// Which motion channels a caller needs.
struct MotionNeeds {
  bool angular_rate = true;  ///< p, q, r
  bool velocity = true;      ///< u, v, w
  /// w (heave speed) may be absent from the log; it is then taken as 0 and said so in
  /// MotionSeries notes. Low-speed DP logs rarely carry w.
  bool heave_optional = true;
};

/// The result of motion_from_log: the series and what was assumed on the way.
struct MotionFromLog {
  MotionSeries motion;
  std::size_t rows_skipped = 0;    ///< rows where a needed channel was missing (other rates)
  std::vector<std::string> notes;  ///< e.g. "w not logged: taken as 0"
};

/// Picks the rows of `log` where every needed channel is present (a mixed-rate log has blank
/// cells between the samples of slower sensors) and returns them in SI.
/// Throws core::InputError naming the missing role when a needed channel is not in the log, or
/// when fewer than two rows have all of them.
MotionFromLog motion_from_log(const core::Log& log, const MotionNeeds& needs = {});

}  // namespace dynpos::calib
