#include "dynpos/core/local_ned_frame.hpp"

#include <gtest/gtest.h>
#include <GeographicLib/Geodesic.hpp>

#include <cmath>

namespace dynpos::core {
namespace {

constexpr GeodeticPoint kOrigin{63.44, 10.35, 39.5};
constexpr double kEarthRadius_m = 6.371e6;

TEST(LocalNedFrame, EnuAndNedSwapNorthEastAndFlipTheVertical) {
  const Eigen::Vector3d p_n = ned_from_enu(1.0, 2.0, 3.0);
  EXPECT_EQ(p_n, Eigen::Vector3d(2.0, 1.0, -3.0));
  EXPECT_EQ(enu_from_ned(p_n), Eigen::Vector3d(1.0, 2.0, 3.0));
}

TEST(LocalNedFrame, TheOriginIsZero) {
  const LocalNedFrame frame(kOrigin);
  EXPECT_LT(frame.to_ned(kOrigin).norm(), 1e-9);
}

// Points 1 km away along a geodesic on the ellipsoid (GeographicLib's Direct problem,
// independent of the local frame), from an origin on the ellipsoid, lie along that azimuth;
// the vertical drop is the Earth's curvature s²/(2R) ≈ 7.8 cm (R differs from the local radii
// by < 0.5 %, hence the 1 mm bound); the chord is shorter than the arc by s³/(24R²) < 1 µm.
TEST(LocalNedFrame, AxesPointNorthEastDown) {
  const GeodeticPoint origin{kOrigin.lat_deg, kOrigin.lon_deg, 0.0};
  const LocalNedFrame frame(origin);
  const double s = 1000.0;
  const double drop = s * s / (2.0 * kEarthRadius_m);
  for (const double azimuth_deg : {0.0, 90.0, 180.0, -90.0}) {
    GeodeticPoint p = origin;
    GeographicLib::Geodesic::WGS84().Direct(origin.lat_deg, origin.lon_deg, azimuth_deg, s,
                                            p.lat_deg, p.lon_deg);
    const Eigen::Vector3d p_n = frame.to_ned(p);
    const double a = azimuth_deg * std::acos(-1.0) / 180.0;
    SCOPED_TRACE(azimuth_deg);
    EXPECT_NEAR(p_n.x(), s * std::cos(a), 1e-3);
    EXPECT_NEAR(p_n.y(), s * std::sin(a), 1e-3);
    EXPECT_NEAR(p_n.z(), drop, 1e-3);
  }
}

TEST(LocalNedFrame, ToGeodeticInvertsToNed) {
  const LocalNedFrame frame(kOrigin);
  for (const Eigen::Vector3d& p_n :
       {Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(120.0, -35.5, -14.0),
        Eigen::Vector3d(-5000.0, 2500.0, 3.0)}) {
    const GeodeticPoint g = frame.to_geodetic(p_n);
    EXPECT_LT((frame.to_ned(g) - p_n).norm(), 1e-8);  // round trip: nanometres
  }
  // Up is a smaller down and a larger height.
  EXPECT_NEAR(frame.to_geodetic(Eigen::Vector3d(0.0, 0.0, -10.0)).height_m, kOrigin.height_m + 10.0,
              1e-9);
}

}  // namespace
}  // namespace dynpos::core
