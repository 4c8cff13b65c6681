#pragma once
/// \file
/// A GNSS gap in a logged DP run bridged on a logged MRU, as the DP system's inertial bridge
/// does in the loop (control/inertial_position.hpp): `dynpos estimate` gives its observer the
/// bridge's position over every row of a gap longer than max_hold_s (from its first row; shorter
/// gaps are the observer's to hold or coast through), instead of letting it coast on its model.
///
/// The bridge runs at the MRU's point P, whose horizontal acceleration in NED is the MRU's
/// reading turned by its logged attitude, (R(Θ) a_b)_NE. With the attitude right gravity has no
/// horizontal part there, in either convention (kinematic acceleration or specific force); an
/// attitude error δ leaks g·δ into it (0.1°: 0.017 m/s², 8 m in 30 s), which the filter's bias
/// learns from the fixes, and a gross one (an angle in the wrong unit, another sensor's
/// attitude) shows in the readings' means turned into NED: horizontally far from the ≈ 0 of a
/// vessel over a log, downwards from both 0 (kinematic) and −g (specific force); the caller
/// checks them. Each fix of the control origin is moved
/// to P by the MRU's lever arm r (BODY): p_P = p + (R(Θ) r)_NE, and the bridged position back by
/// the same arm at the row's attitude. The samples are taken as values at their times: over each
/// interval between rows the filter predicts on the mean of the acceleration at its ends (linear
/// between samples at most max_hold_s apart), then corrects on the row's fix. An attitude angle
/// or an acceleration older than max_hold_s is missing, which ends the bridge.

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "dynpos/control/inertial_position.hpp"

namespace dynpos::analysis {

/// The log's rows on one increasing time axis (SI; NaN: no sample).
struct BridgeSeries {
  std::vector<double> t_s;
  std::vector<double> north_m, east_m;  ///< the control origin's fixes (NED) [m]
  std::vector<double> heading_rad, roll_rad, pitch_rad;
  std::vector<Eigen::Vector3d> accel_b;  ///< the MRU's reading (x, y, z) BODY [m/s²]
};

/// The fixes with the bridged gaps filled.
struct BridgedTrack {
  std::vector<double> north_m, east_m;  ///< the control origin's [m]
  std::size_t bridged_rows = 0;         ///< rows given the bridge's position
  double longest_gap_bridged_s = 0.0;   ///< the longest gap bridged, fix to fix [s]
  /// |mean of the MRU's horizontal acceleration (NED)| over the log's samples [m/s²]: ≈ 0 for
  /// a vessel over minutes; far from it, the attitude does not fit the readings.
  double mean_horizontal_accel_mps2 = 0.0;
  /// The mean of its down component [m/s²]: ≈ 0 for kinematic readings, ≈ −g for specific force.
  double mean_down_accel_mps2 = 0.0;
};

/// Bridges `series` on an MRU at lever arm `arm_b` (x forward, y starboard, z down; BODY from
/// the control origin) [m] with `tuning` (see the file comment); rows outside the gaps longer
/// than max_hold_s keep their own value. Throws std::invalid_argument for series of unequal
/// lengths, a time that does not increase, or a bad tuning.
BridgedTrack bridge_gnss_gaps(const BridgeSeries& series, const Eigen::Vector3d& arm_b,
                              const control::InertialPositionTuning& tuning, double max_hold_s);

}  // namespace dynpos::analysis
