#include "dynpos/ident/local_position.hpp"

#include <cmath>
#include <numbers>
#include <optional>

#include "dynpos/core/error.hpp"
#include "dynpos/core/local_ned_frame.hpp"

namespace dynpos::ident {

LocalPositions local_north_east(const std::vector<double>& lat_rad,
                                const std::vector<double>& lon_rad) {
  if (lat_rad.size() != lon_rad.size()) {
    throw core::InputError({{}, {}, {}, "lat/lon"}, "latitude and longitude lengths differ");
  }
  constexpr double kDeg = 180.0 / std::numbers::pi;
  LocalPositions out;
  out.north_m.assign(lat_rad.size(), std::nan(""));
  out.east_m.assign(lat_rad.size(), std::nan(""));
  std::optional<core::LocalNedFrame> plane;
  for (std::size_t i = 0; i < lat_rad.size(); ++i) {
    if (std::isnan(lat_rad[i]) || std::isnan(lon_rad[i])) continue;
    if (std::abs(lat_rad[i]) > std::numbers::pi / 2.0) {
      throw core::InputError({{}, i + 1, {}, "lat"},
                             "latitude " + std::to_string(lat_rad[i] * kDeg) + "° is outside ±90°",
                             "check the unit of lat (deg or rad) with --unit lat=deg");
    }
    const core::GeodeticPoint fix{lat_rad[i] * kDeg, lon_rad[i] * kDeg, 0.0};
    if (!plane) plane.emplace(fix);
    const Eigen::Vector3d p_n = plane->to_ned(fix);
    out.north_m[i] = p_n.x();
    out.east_m[i] = p_n.y();
  }
  return out;
}

}  // namespace dynpos::ident
