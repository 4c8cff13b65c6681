#include "dynpos/model/unit_drive.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dynpos/core/error.hpp"

namespace dynpos::model {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

ThrusterUnit azimuth(std::vector<AngleSector> forbidden = {}) {
  return thruster_unit("az", UnitType::kAzimuth, -13.0, -2.7, 55e3, 0.0, std::move(forbidden));
}

TEST(UnitDrive, RatedShaftSpeedGivesTheRatedThrustAheadAndAstern) {
  const UnitDrive tunnel(thruster_unit("t", UnitType::kTunnel, 12.5, 0.0, 25e3, 22.5e3));
  const double n_max = tunnel.params().max_shaft_speed_rps;
  EXPECT_NEAR(tunnel.thrust_N(n_max), 25e3, 1e-6);
  EXPECT_NEAR(tunnel.thrust_N(-n_max), -22.5e3, 1e-6);
  // The inverse, and a demand beyond the rating held at the largest shaft speed.
  EXPECT_NEAR(tunnel.thrust_N(tunnel.shaft_speed_for(10e3)), 10e3, 1e-6);
  EXPECT_NEAR(tunnel.thrust_N(tunnel.shaft_speed_for(-7e3)), -7e3, 1e-6);
  EXPECT_DOUBLE_EQ(tunnel.shaft_speed_for(1e6), n_max);
}

TEST(UnitDrive, DefaultsScaleFromTheRatingAsTheGunnerusTunnel) {
  // A 25 kN unit at 25 kPa thrust loading has the Gunnerus tunnel's size and speed (D = 1.2 m,
  // 5.42 rps; tunnel_thruster.hpp) within 10 %, and so its 1 s time constant.
  const UnitDriveParams p = drive_params(thruster_unit("t", UnitType::kTunnel, 0, 0, 25e3));
  EXPECT_NEAR(p.diameter_m, 1.2, 0.12);
  EXPECT_NEAR(p.max_shaft_speed_rps, 5.42, 0.54);
  EXPECT_NEAR(p.time_constant_s, 1.0, 0.1);
  // A larger unit turns slower.
  const UnitDriveParams big = drive_params(thruster_unit("m", UnitType::kAzimuth, 0, 0, 300e3));
  EXPECT_LT(big.max_shaft_speed_rps, p.max_shaft_speed_rps);
  EXPECT_GT(big.time_constant_s, p.time_constant_s);
  // A time constant given in the file is kept.
  ThrusterUnit given = azimuth();
  given.time_constant_s = 2.5;
  EXPECT_DOUBLE_EQ(drive_params(given).time_constant_s, 2.5);
}

TEST(UnitDrive, ShaftFollowsItsCommandWithinTheRateLimit) {
  const UnitDrive d(azimuth());
  const UnitDriveParams& p = d.params();
  EXPECT_DOUBLE_EQ(d.shaft_acceleration(0.0, p.max_shaft_speed_rps), p.rate_limit_rps2);
  EXPECT_NEAR(d.shaft_acceleration(1.0, 1.01), 0.01 / p.time_constant_s, 1e-12);
  // A command beyond the rating is held at it.
  EXPECT_DOUBLE_EQ(d.shaft_acceleration(p.max_shaft_speed_rps, 10.0 * p.max_shaft_speed_rps), 0.0);
}

TEST(UnitDrive, AnAzimuthSlewsAtItsRateTheShortWayWhenItIsClear) {
  const UnitDrive d(azimuth());
  EXPECT_DOUBLE_EQ(d.angle_rate(0.0, 90.0 * kDeg), 10.0 * kDeg);
  EXPECT_DOUBLE_EQ(d.angle_rate(0.0, 270.0 * kDeg), -10.0 * kDeg);  // −90° is shorter
  EXPECT_NEAR(d.angle_rate(0.0, 1.0 * kDeg), 2.0 * kDeg, 1e-12);    // inside the rate limit
  // Angles a whole turn apart are one direction.
  EXPECT_NEAR(d.angle_rate(4.0 * std::numbers::pi, 0.0), 0.0, 1e-12);
}

TEST(UnitDrive, AnAzimuthTurnsTheLongWayRoundAForbiddenSector) {
  const UnitDrive d(azimuth({{75.0, 105.0}}));
  // 0° → 180°: the short way (either, π) and clockwise cross 75–105°; it turns anticlockwise.
  EXPECT_LT(d.angle_rate(0.0, 170.0 * kDeg), 0.0);
  EXPECT_GT(d.angle_rate(170.0 * kDeg, 0.0), 0.0);
  // From the sector's edge away from it, and past it on the clear side, the short way.
  EXPECT_LT(d.angle_rate(75.0 * kDeg, 40.0 * kDeg), 0.0);
  EXPECT_GT(d.angle_rate(105.0 * kDeg, 140.0 * kDeg), 0.0);
  // A sector across ahead: 300° → 60° goes the long way round, by 180° (a 240° turn).
  const UnitDrive across(azimuth({{350.0, 10.0}}));
  EXPECT_LT(across.angle_rate(300.0 * kDeg, 60.0 * kDeg), 0.0);
  EXPECT_GT(across.angle_rate(60.0 * kDeg, 300.0 * kDeg), 0.0);
}

TEST(UnitDrive, TheReachableDirectionsStopAtAForbiddenSector) {
  const UnitDrive d(azimuth({{75.0, 105.0}}));
  // From 60°: a quarter turn back, 15° on to the sector.
  const auto arc = d.reachable(60.0 * kDeg, 90.0 * kDeg);
  ASSERT_TRUE(arc.has_value());
  EXPECT_NEAR(arc->from_rad, -30.0 * kDeg, 1e-12);
  EXPECT_NEAR(arc->span_rad, 105.0 * kDeg, 1e-12);
  // At most a quarter turn each way; none inside the sector; none for a tunnel.
  EXPECT_NEAR(d.reachable(200.0 * kDeg, 10.0)->span_rad, std::numbers::pi, 1e-12);
  EXPECT_FALSE(d.reachable(90.0 * kDeg, 0.5).has_value());
  EXPECT_FALSE(UnitDrive(thruster_unit("t", UnitType::kTunnel, 0, 0, 1e4)).reachable(0.0, 0.5));
  // The turn from one edge of the sector to the other is the long way round.
  EXPECT_NEAR(d.turn_rad(75.0 * kDeg, 105.0 * kDeg), -330.0 * kDeg, 1e-12);
  EXPECT_NEAR(d.turn_rad(60.0 * kDeg, 30.0 * kDeg), -30.0 * kDeg, 1e-12);
}

TEST(UnitDrive, WithBothWaysBlockedTheShortWayIsTaken) {
  // Sectors on both beams; from ahead to astern both ways cross one: the short way (through
  // the sector, the thrust cut by the control task meanwhile), and it is reported blocked.
  const UnitDrive d(azimuth({{80.0, 100.0}, {260.0, 280.0}}));
  EXPECT_NEAR(std::abs(d.turn_rad(0.0, 170.0 * kDeg)), 170.0 * kDeg, 1e-12);
  EXPECT_TRUE(d.short_way_blocked(0.0, 170.0 * kDeg));
  // Within one gap: clear.
  EXPECT_NEAR(d.turn_rad(10.0 * kDeg, 60.0 * kDeg), 50.0 * kDeg, 1e-12);
  EXPECT_FALSE(d.short_way_blocked(10.0 * kDeg, 60.0 * kDeg));
  // One sector: the short way blocked, the long way taken.
  const UnitDrive one(azimuth({{75.0, 105.0}}));
  EXPECT_TRUE(one.short_way_blocked(60.0 * kDeg, 120.0 * kDeg));
  EXPECT_NEAR(one.turn_rad(60.0 * kDeg, 120.0 * kDeg), -300.0 * kDeg, 1e-12);
}

TEST(UnitDrive, ForceAndMomentFollowTheDirectionAndPosition) {
  const UnitDrive d(azimuth());
  const double n = d.shaft_speed_for(40e3);
  const UnitOutput o = d.outputs(n, 90.0 * kDeg);  // thrust to starboard at (−13, −2.7)
  EXPECT_NEAR(o.tau_b.x(), 0.0, 1e-9);
  EXPECT_NEAR(o.tau_b.y(), 40e3, 1e-6);
  EXPECT_NEAR(o.tau_b.z(), -13.0 * 40e3, 1e-5);  // N = x·F_y − y·F_x (2.2)
  const UnitOutput ahead = d.outputs(n, 0.0);
  EXPECT_NEAR(ahead.tau_b.z(), 2.7 * 40e3, 1e-5);
  EXPECT_GT(o.power_W, 0.0);
  // A lost unit makes no force.
  EXPECT_EQ(d.outputs(n, 0.0, 0.0).tau_b, Eigen::Vector3d::Zero());
}

TEST(UnitDrive, AnAzimuthsThrustIsCutByItsLossFactorThere) {
  ThrusterUnit u = azimuth();
  u.loss = {{0.0, 1.0}, {80.0, 1.0}, {90.0, 0.5}, {100.0, 1.0}};
  const UnitDrive d(u);
  const double n = d.shaft_speed_for(40e3);
  EXPECT_NEAR(d.outputs(n, 90.0 * kDeg).thrust_N, 20e3, 1e-6);
  EXPECT_NEAR(d.outputs(n, 85.0 * kDeg).thrust_N, 30e3, 1e-6);
  EXPECT_NEAR(d.outputs(n, 180.0 * kDeg).thrust_N, 40e3, 1e-6);
}

TEST(UnitDrive, ARudderSpansTheAllocationsConeAtHardOver) {
  ThrusterUnit u = thruster_unit("pr", UnitType::kPropellerRudder, -13.0, 2.7, 73e3);
  u.rudder_lift_per_thrust = 0.65;
  u.rudder_x_m = -14.5;
  const UnitDrive d(u);
  const double n = d.shaft_speed_for(50e3);
  const double hard_over = d.params().max_rudder_rad;
  const UnitOutput o = d.outputs(n, hard_over);
  EXPECT_NEAR(o.rudder_force_N, 0.65 * 50e3, 1e-6);
  EXPECT_NEAR(o.tau_b.z(), -14.5 * o.rudder_force_N - 2.7 * 50e3, 1e-4);
  // The angle for a force inside the cone gives that force.
  const double delta = d.rudder_angle_for(10e3, 50e3);
  EXPECT_NEAR(d.outputs(n, delta).rudder_force_N, 10e3, 1e-6);
  EXPECT_DOUBLE_EQ(d.rudder_angle_for(1e9, 50e3), hard_over);
  EXPECT_DOUBLE_EQ(d.angle_rate(0.0, 1.0), d.params().rudder_rate_rad_s);
}

TEST(UnitDrive, ABadUnitIsRefused) {
  ThrusterUnit u = azimuth();
  u.dead_time_s = -1.0;
  EXPECT_THROW(UnitDrive{u}, core::InputError);
  u = azimuth();
  u.time_constant_s = 0.0;
  EXPECT_THROW(UnitDrive{u}, core::InputError);
}

}  // namespace
}  // namespace dynpos::model
