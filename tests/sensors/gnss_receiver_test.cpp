#include "dynpos/sensors/gnss_receiver.hpp"

#include <gtest/gtest.h>

#include <GeographicLib/Geodesic.hpp>
#include <cmath>

namespace dynpos::sensors {
namespace {

GnssParams noiseless(const Eigen::Vector3d& arm) {
  GnssParams p;
  p.lever_arm_b = arm;
  p.horizontal_std_m = p.vertical_std_m = 0.0;
  return p;
}

TEST(GnssReceiver, AntennaOverTheOriginReportsTheOrigin) {
  const GeodeticOrigin o;
  GnssReceiver rx(noiseless(Eigen::Vector3d::Zero()), o, 1.0, 1);
  const GnssFix fix = rx.measure(RigidBodyMotion{});
  EXPECT_NEAR(fix.lat_deg, o.lat_deg, 1e-12);
  EXPECT_NEAR(fix.lon_deg, o.lon_deg, 1e-12);
  EXPECT_NEAR(fix.height_m, o.height_m, 1e-9);
}

TEST(GnssReceiver, LeverArmAndHeadingPlaceTheAntenna) {
  // Heading 90°: the arm (1, 2, −13) points east 1 m, south 2 m, up 13 m.
  RigidBodyMotion m;
  m.p_n = {100.0, -50.0, 0.0};
  m.theta = {0.0, 0.0, M_PI / 2};
  GnssReceiver rx(noiseless({1.0, 2.0, -13.0}), GeodeticOrigin{}, 1.0, 1);
  const GnssFix fix = rx.measure(m);
  EXPECT_LT((fix.p_n - Eigen::Vector3d(98.0, -49.0, -13.0)).norm(), 1e-9);
  // The geodetic fix maps back to the same local point (GeographicLib round trip, ~1e-9 m).
  EXPECT_LT((rx.to_local_n(fix.lat_deg, fix.lon_deg, fix.height_m) - fix.p_n).norm(), 1e-6);
  // Up 13 m: ellipsoidal height grows by 13 m (plus the Earth's curvature over 110 m, ~1 mm).
  EXPECT_NEAR(fix.height_m, GeodeticOrigin{}.height_m + 13.0, 2e-3);
  // 98 m north and 49 m west of the origin on the ellipsoid: the geodesic distance agrees.
  double s12 = 0;
  GeographicLib::Geodesic::WGS84().Inverse(GeodeticOrigin{}.lat_deg, GeodeticOrigin{}.lon_deg,
                                           fix.lat_deg, fix.lon_deg, s12);
  EXPECT_NEAR(s12, std::hypot(98.0, 49.0), 0.01);  // height and curvature effects < 1 cm
}

TEST(GnssReceiver, NoiseHasTheConfiguredHorizontalAndVerticalStd) {
  GnssParams p;
  p.horizontal_std_m = 0.015;
  p.vertical_std_m = 0.03;
  GnssReceiver rx(p, GeodeticOrigin{}, 1.0, 5);
  const int n = 10000;
  Eigen::Vector3d sum2 = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i) sum2 += rx.measure(RigidBodyMotion{}).p_n.cwiseAbs2();
  const Eigen::Vector3d std_dev = (sum2 / n).cwiseSqrt();
  // Relative std of a sample std with n = 10⁴ is 0.7 %; 5 % tolerance is > 7σ.
  EXPECT_NEAR(std_dev.x(), 0.015, 0.05 * 0.015);
  EXPECT_NEAR(std_dev.y(), 0.015, 0.05 * 0.015);
  EXPECT_NEAR(std_dev.z(), 0.03, 0.05 * 0.03);
}

TEST(GnssReceiver, DifferentSeedsGiveDifferentNoise) {
  GnssReceiver a(GnssParams{}, GeodeticOrigin{}, 1.0, 1), b(GnssParams{}, GeodeticOrigin{}, 1.0, 2);
  EXPECT_NE(a.measure(RigidBodyMotion{}).p_n, b.measure(RigidBodyMotion{}).p_n);
}

}  // namespace
}  // namespace dynpos::sensors
