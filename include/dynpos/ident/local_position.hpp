#pragma once
/// \file
/// Geodetic fixes (latitude, longitude) as north/east metres in a local tangent plane, so that
/// position statistics can be taken on logs that carry lat/lon instead of a projected position.

#include <vector>

namespace dynpos::ident {

/// North/east [m] of each fix in the local NED frame (core::LocalNedFrame, WGS84)
/// whose origin is the first fix with both coordinates valid, at zero height. NaN stays NaN.
struct LocalPositions {
  std::vector<double> north_m;
  std::vector<double> east_m;
};
/// lat_rad and lon_rad of equal length [rad]. Throws core::InputError if the lengths differ or a
/// valid latitude is outside [−π/2, π/2].
LocalPositions local_north_east(const std::vector<double>& lat_rad,
                                const std::vector<double>& lon_rad);

}  // namespace dynpos::ident
