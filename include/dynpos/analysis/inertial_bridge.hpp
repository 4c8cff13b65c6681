#pragma once
/// \file
/// A GNSS gap in a logged DP run bridged on a logged MRU, as the DP system's inertial bridge
/// does in the loop (control/inertial_position.hpp): `dynpos estimate` gives its observer the
/// bridge's position where the log's last fix is older than max_hold_s, instead of letting it
/// coast on its model.
///
/// The bridge runs at the MRU's point P, whose horizontal acceleration in NED is the MRU's
/// reading turned by its logged attitude, (R(Θ) a_b)_NE; in either convention (kinematic
/// acceleration or specific force) gravity has no horizontal part there. Each fix of the control
/// origin is moved to P by the MRU's lever arm r (BODY): p_P = p + (R(Θ) r)_NE, and the bridged
/// position back by the same arm at the row's attitude. Row by row in time order, the filter
/// predicts over the row's interval on the last acceleration before it (held), then corrects on
/// the row's fix.

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
  double longest_gap_bridged_s = 0.0;   ///< the longest run of them, from the fix before [s]
};

/// Bridges `series` on an MRU at lever arm `arm_b` (x forward, y starboard, z down; BODY from
/// the control origin) [m] with `tuning` (see the file comment); rows whose last fix is at most
/// max_hold_s old keep their own value. Throws std::invalid_argument for series of unequal
/// lengths or a bad tuning.
BridgedTrack bridge_gnss_gaps(const BridgeSeries& series, const Eigen::Vector3d& arm_b,
                              const control::InertialPositionTuning& tuning, double max_hold_s);

}  // namespace dynpos::analysis
