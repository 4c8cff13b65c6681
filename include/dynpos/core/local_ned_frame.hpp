#pragma once
/// \file
/// The local NED frame (x north, y east, z down) about a geodetic origin on the WGS84
/// ellipsoid: the one place where geodetic coordinates and local metres are converted.
/// GeographicLib's LocalCartesian does the geodesy; its local frame is ENU (x east, y north,
/// z up), so (n, e, d) = (y, x, −z) and back (ned_from_enu, enu_from_ned).

#include <Eigen/Core>
#include <GeographicLib/LocalCartesian.hpp>

namespace dynpos::core {

/// ENU (east, north, up) [m] → NED [m]: (n, e, d) = (north, east, −up).
inline Eigen::Vector3d ned_from_enu(double east_m, double north_m, double up_m) {
  return {north_m, east_m, -up_m};
}

/// NED p_n [m] → ENU (east, north, up) [m]: (p_n.y, p_n.x, −p_n.z).
inline Eigen::Vector3d enu_from_ned(const Eigen::Vector3d& p_n) {
  return {p_n.y(), p_n.x(), -p_n.z()};
}

/// A point on or near the WGS84 ellipsoid.
struct GeodeticPoint {
  double lat_deg = 0.0;   ///< latitude [deg], + north, in [−90, 90]
  double lon_deg = 0.0;   ///< longitude [deg], + east
  double height_m = 0.0;  ///< ellipsoidal height [m]
};

/// The local NED frame whose origin is a geodetic point (WGS84, GeographicLib LocalCartesian).
class LocalNedFrame {
 public:
  /// The frame about origin (lat [deg], lon [deg], ellipsoidal height [m]).
  explicit LocalNedFrame(const GeodeticPoint& origin)
      : enu_(origin.lat_deg, origin.lon_deg, origin.height_m) {}

  /// Local NED [m] of a geodetic point: exact (no small-distance approximation).
  Eigen::Vector3d to_ned(const GeodeticPoint& point) const {
    double east = 0.0, north = 0.0, up = 0.0;
    enu_.Forward(point.lat_deg, point.lon_deg, point.height_m, east, north, up);
    return ned_from_enu(east, north, up);
  }

  /// The geodetic point at local NED p_n [m]; to_ned inverts it to ~1e-9 m.
  GeodeticPoint to_geodetic(const Eigen::Vector3d& p_n) const {
    const Eigen::Vector3d enu = enu_from_ned(p_n);
    GeodeticPoint point;
    enu_.Reverse(enu.x(), enu.y(), enu.z(), point.lat_deg, point.lon_deg, point.height_m);
    return point;
  }

 private:
  GeographicLib::LocalCartesian enu_;
};

}  // namespace dynpos::core
