#pragma once
/// \file
/// The control origin's position along a log, as the analyses of a DP run read it: north/east
/// [m] (any offset) or lat/lon made local (log_source.hpp local_position), moved from the
/// antenna to the control origin by its lever arm (ident/control_origin.hpp) with the logged
/// roll and pitch when both are mapped.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "dynpos/analysis/log_source.hpp"
#include "dynpos/core/log.hpp"

namespace dynpos::analysis {

/// The position and heading of the control origin on the log's time axis (NaN: no sample).
struct ControlOriginTrack {
  std::vector<double> north_m;
  std::vector<double> east_m;
  std::vector<double> heading_rad;  ///< as logged; empty when the log has no heading
  std::string position;             ///< the roles read: "north/east" or "lat/lon"
  bool has_heading = false;         ///< a heading with a valid sample
  bool attitude = false;            ///< the arm was applied with the logged roll and pitch
};

/// The track of `log` (read from `source`) with the antenna's lever arm `arm_m` (x forward,
/// y starboard, z down; BODY) [m], if any. Throws core::InputError naming the log for no
/// position, an arm without a heading, and an arm's height without roll and pitch.
ControlOriginTrack control_origin_track(const LogSource& source, const core::Log& log,
                                        const std::optional<Eigen::Vector3d>& arm_m);

}  // namespace dynpos::analysis
