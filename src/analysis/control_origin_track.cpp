#include "dynpos/analysis/control_origin_track.hpp"

#include <algorithm>
#include <cmath>

#include "dynpos/core/samples.hpp"
#include "dynpos/ident/control_origin.hpp"

namespace dynpos::analysis {

ControlOriginTrack control_origin_track(const LogSource& source, const core::Log& log,
                                        const std::optional<Eigen::Vector3d>& arm_m) {
  std::optional<ident::LocalPositions> p = local_position(log);
  if (!p) {
    throw source.error("north/east", "no position in the log",
                       "map north and east in metres (any offset, e.g. UTM: --col "
                       "north=gnss1.north --col east=gnss1.east) or lat and lon");
  }
  ControlOriginTrack track;
  track.position = log.has("north") && log.has("east") ? "north/east" : "lat/lon";
  track.north_m = std::move(p->north_m);
  track.east_m = std::move(p->east_m);
  track.heading_rad = values_or_empty(log, "heading");
  track.has_heading = core::has_valid_sample(track.heading_rad);
  if (!arm_m) return track;
  if (!track.has_heading) {
    throw source.error("heading", "the lever arm (--arm) needs the heading",
                       "map heading (--col heading=COLUMN)");
  }
  const Eigen::Vector3d& arm = *arm_m;
  std::vector<double> roll = values_or_empty(log, "roll"), pitch = values_or_empty(log, "pitch");
  track.attitude = core::has_valid_sample(roll) && core::has_valid_sample(pitch);
  if (arm.z() != 0.0 && !track.attitude) {
    throw source.error("roll/pitch", "the arm's height (--arm X,Y,Z) needs roll and pitch",
                       "map roll and pitch (e.g. --col roll=mru1.roll --col "
                       "pitch=mru1.pitch), or give the horizontal arm X,Y alone");
  }
  if (!track.attitude) roll.clear(), pitch.clear();
  ident::move_to_control_origin(track.north_m, track.east_m, track.heading_rad, roll, pitch,
                                {arm.x(), arm.y(), arm.z()});
  return track;
}

}  // namespace dynpos::analysis
