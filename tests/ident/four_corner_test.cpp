#include "dynpos/ident/four_corner.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "dynpos/core/error.hpp"

namespace dynpos::ident {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kPi = std::numbers::pi;

// A 4-corner box at 10 Hz, GNSS-like position at 1 Hz (NaN between): hold 0–60 s at (0, 0),
// heading 0; ahead to (50, 0) at 0.5 m/s over 60–160 s; hold to 200 s; crab to port to
// (50, −50) over 200–300 s; hold to 340 s; astern to (0, −50) over 340–440 s while turning to
// −90° at 0.9°/s; hold to 480 s; back to (0, 0) (astern in the −90° frame) over 480–580 s; hold
// to 640 s. Setpoints change at 60, 200, 340 and 480 s (the operator waits 40 s after each
// arrival). Port thruster: 10 kN and 50 kW throughout; tunnel: thrust only, −4 kN.
FourCornerInput box(bool with_setpoints = true) {
  struct Waypoint {
    double t, n, e, psi_deg;
  };
  const std::vector<Waypoint> wp = {{0, 0, 0, 0},       {60, 0, 0, 0},      {160, 50, 0, 0},
                                    {200, 50, 0, 0},    {300, 50, -50, 0},  {340, 50, -50, 0},
                                    {440, 0, -50, -90}, {480, 0, -50, -90}, {580, 0, 0, -90},
                                    {640, 0, 0, -90}};
  const std::vector<Waypoint> sp = {
      {0, 0, 0, 0}, {60, 50, 0, 0}, {200, 50, -50, 0}, {340, 0, -50, -90}, {480, 0, 0, -90}};
  FourCornerInput in;
  std::vector<double> thrust_port, power_port, thrust_tunnel;
  for (int i = 0; i <= 6400; ++i) {
    const double t = 0.1 * i;
    std::size_t k = 0;
    while (k + 2 < wp.size() && wp[k + 1].t <= t) ++k;
    const Waypoint& a = wp[k];
    const Waypoint& b = wp[k + 1];
    const double f = std::clamp((t - a.t) / (b.t - a.t), 0.0, 1.0);
    const bool gnss_epoch = i % 10 == 0;
    in.t_s.push_back(t);
    in.north_m.push_back(gnss_epoch ? a.n + f * (b.n - a.n) : kNaN);
    in.east_m.push_back(gnss_epoch ? a.e + f * (b.e - a.e) : kNaN);
    in.heading_rad.push_back((a.psi_deg + f * (b.psi_deg - a.psi_deg)) * kPi / 180.0);
    if (with_setpoints) {
      std::size_t s = 0;
      while (s + 1 < sp.size() && sp[s + 1].t <= t) ++s;
      in.setpoint_north_m.push_back(sp[s].n);
      in.setpoint_east_m.push_back(sp[s].e);
      in.setpoint_heading_rad.push_back(sp[s].psi_deg * kPi / 180.0);
    }
    thrust_port.push_back(10e3);
    power_port.push_back(50e3);
    thrust_tunnel.push_back(-4e3);
  }
  in.thrusters.push_back({"port", thrust_port, power_port});
  in.thrusters.push_back({"tunnel", thrust_tunnel, {}});
  return in;
}

// A circle of 2.25 m: the vessel crosses it between two 1 Hz epochs (at 155.5 s on the first
// leg), so the first epoch inside is unambiguous (156 s) whatever the rounding.
FourCornerOptions circle() {
  FourCornerOptions o;
  o.radius_m = 2.25;
  return o;
}

TEST(FourCorner, LegsFromSetpointsEndInTheOperatingCircle) {
  const FourCornerResult r = analyse_four_corner(box(), circle());
  EXPECT_EQ(r.segmentation, "setpoints");
  ASSERT_EQ(r.legs.size(), 4u);
  // Each leg starts at its setpoint change. It ends at the first 1 Hz position sample inside
  // the 2.25 m circle with the heading within 2°, both averaged over ±5 s (the wave filter;
  // linear motion is unchanged by it until the window reaches the corner). 2.25 m before the
  // corner at 0.5 m/s is 4.5 s early: the epoch 4 s before (at 156 s the average over 151–161 s
  // is 47.95 m north, inside). The third leg ends on its heading: at 439 s the average over
  // 434–444 s is −88.4° (inside), at 438 s −87.8° (not yet).
  const double starts[] = {60.0, 200.0, 340.0, 480.0};
  const double ends[] = {156.0, 296.0, 439.0, 576.0};
  for (std::size_t k = 0; k < 4; ++k) {
    SCOPED_TRACE(k);
    EXPECT_NEAR(r.legs[k].t_start_s, starts[k], 1e-9);
    EXPECT_NEAR(r.legs[k].t_end_s, ends[k], 1e-9);
    EXPECT_NEAR(r.legs[k].duration_s, ends[k] - starts[k], 1e-9);
    EXPECT_TRUE(r.legs[k].reached);
  }
  EXPECT_EQ(r.legs[0].name, "ahead 50 m");
  EXPECT_EQ(r.legs[1].name, "crab to port 50 m");
  EXPECT_EQ(r.legs[2].name, "astern 50 m, heading change -90°");
  EXPECT_EQ(r.legs[3].name, "astern 50 m");  // +50 m east with the bow to the west
  // Constant 10 kN and 50 kW: accumulated thrust and energy are duration × value (trapezoid
  // rule on a constant is exact up to rounding); the tunnel's −4 kN counts as |T|.
  const Leg& leg = r.legs[0];
  ASSERT_EQ(leg.thrusters.size(), 2u);
  EXPECT_NEAR(*leg.thrusters[0].accumulated_thrust_Ns, 10e3 * 96.0, 1e-6);
  EXPECT_NEAR(*leg.thrusters[0].energy_J, 50e3 * 96.0, 1e-6);
  EXPECT_NEAR(*leg.thrusters[1].accumulated_thrust_Ns, 4e3 * 96.0, 1e-6);
  EXPECT_FALSE(leg.thrusters[1].energy_J);  // no power channel: missing, not 0
  EXPECT_NEAR(*leg.total_accumulated_thrust_Ns, 14e3 * 96.0, 1e-6);
  EXPECT_FALSE(leg.total_energy_J);  // a thruster's energy is missing, so is the total
  // Total: the sum of the legs (the 40 s waits are not legs).
  const double sum = 96.0 + 96.0 + 99.0 + 96.0;
  EXPECT_NEAR(r.total.duration_s, sum, 1e-9);
  EXPECT_NEAR(r.total.t_start_s, 60.0, 1e-9);
  EXPECT_NEAR(r.total.t_end_s, 576.0, 1e-9);
  EXPECT_NEAR(*r.total.thrusters[0].accumulated_thrust_Ns, 10e3 * sum, 1e-6);
  EXPECT_NEAR(*r.total.thrusters[0].energy_J, 50e3 * sum, 1e-6);
  EXPECT_NEAR(*r.total.thrusters[0].mean_abs_thrust_N, 10e3, 1e-9);
  EXPECT_FALSE(r.total.thrusters[1].energy_J);
  EXPECT_FALSE(r.total.total_energy_J);
}

TEST(FourCorner, TheWaveFilterKeepsTheCircleTestOnTheLowFrequencyMotion) {
  // Wave-frequency motion of 0.8 m amplitude and 6 s period on the position: a 10 s mean leaves
  // 0.8·|sin(πW/P)|/(πW/P) ≈ 0.13 m, a shift of ≈ 0.3 s at 0.5 m/s, so each leg still ends at
  // the epoch of the calm case; without the filter the 0.8 m moves some crossings by seconds.
  FourCornerInput in = box();
  for (std::size_t i = 0; i < in.t_s.size(); ++i) {
    const double wave = 0.8 * std::sin(2.0 * kPi * in.t_s[i] / 6.0 + 0.3);
    if (!std::isnan(in.north_m[i])) in.north_m[i] += wave;
    if (!std::isnan(in.east_m[i])) in.east_m[i] += wave;
  }
  const FourCornerResult calm = analyse_four_corner(box(), circle());
  const FourCornerResult filtered = analyse_four_corner(in, circle());
  FourCornerOptions raw = circle();
  raw.wave_filter_s = 0.0;
  const FourCornerResult unfiltered = analyse_four_corner(in, raw);
  ASSERT_EQ(filtered.legs.size(), 4u);
  ASSERT_EQ(unfiltered.legs.size(), 4u);
  double worst_unfiltered = 0.0;
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(filtered.legs[k].t_end_s, calm.legs[k].t_end_s, 1e-9) << k;
    worst_unfiltered =
        std::max(worst_unfiltered, std::abs(unfiltered.legs[k].t_end_s - calm.legs[k].t_end_s));
  }
  EXPECT_GE(worst_unfiltered, 1.0);
}

TEST(FourCorner, AnAntennaPositionIsMovedToTheControlOrigin) {
  // The box logged by an antenna 0.2 m forward and 0.6 m to port: p = p_CO + R(ψ)·l. With the
  // arm given, the legs are those of the control origin exactly (up to rounding).
  FourCornerInput in = box();
  const double x = 0.2, y = -0.6;
  for (std::size_t i = 0; i < in.t_s.size(); ++i) {
    const double psi = in.heading_rad[i];
    if (std::isnan(in.north_m[i])) continue;
    in.north_m[i] += std::cos(psi) * x - std::sin(psi) * y;
    in.east_m[i] += std::sin(psi) * x + std::cos(psi) * y;
  }
  const FourCornerResult calm = analyse_four_corner(box(), circle());
  const FourCornerResult at_antenna = analyse_four_corner(in, circle());
  in.arm_x_m = x;
  in.arm_y_m = y;
  const FourCornerResult moved = analyse_four_corner(in, circle());
  ASSERT_EQ(moved.legs.size(), 4u);
  bool antenna_differs = false;
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(moved.legs[k].t_end_s, calm.legs[k].t_end_s, 1e-9) << k;
    antenna_differs = antenna_differs || at_antenna.legs[k].t_end_s != calm.legs[k].t_end_s;
  }
  EXPECT_TRUE(antenna_differs);  // the crab to port reaches its circle 1 s early at the antenna
}

TEST(FourCorner, ALegNotReachedEndsAtTheNextSetpoint) {
  FourCornerInput in = box();
  // Move the second setpoint 10 m further to port: the vessel stops 10 m short, never inside.
  for (std::size_t i = 0; i < in.t_s.size(); ++i) {
    if (in.t_s[i] >= 200.0 && in.t_s[i] < 340.0) in.setpoint_east_m[i] = -60.0;
  }
  const FourCornerResult r = analyse_four_corner(in, circle());
  ASSERT_EQ(r.legs.size(), 4u);
  EXPECT_FALSE(r.legs[1].reached);
  EXPECT_NEAR(r.legs[1].t_end_s, 340.0, 1e-9);
  EXPECT_EQ(r.legs[1].name, "crab to port 60 m");
  EXPECT_FALSE(r.total.reached);
}

TEST(FourCorner, LegsFromTheTrackWithoutSetpoints) {
  const FourCornerResult r = analyse_four_corner(box(false));
  EXPECT_EQ(r.segmentation, "track");
  ASSERT_EQ(r.legs.size(), 4u);
  // Speed from differences over ±5 s: at 0.5 m/s a sample is "moving" (> 0.1 m/s) once more
  // than 2 s of motion lie in its 10 s span, so a leg opens at the epoch 2 s before the motion
  // starts and closes 2 s after it ends; at exactly 2 s the speed is 0.1 m/s and rounding
  // decides, hence ±1 s (one epoch). The turn (0.9°/s) crosses its 0.29°/s threshold later
  // than that, so it does not change the third leg's start.
  const double starts[] = {60.0, 200.0, 340.0, 480.0};
  const double ends[] = {160.0, 300.0, 440.0, 580.0};
  for (std::size_t k = 0; k < 4; ++k) {
    SCOPED_TRACE(k);
    EXPECT_NEAR(r.legs[k].t_start_s, starts[k] - 2.0, 1.0 + 1e-9);
    EXPECT_NEAR(r.legs[k].t_end_s, ends[k] + 2.0, 1.0 + 1e-9);
  }
  EXPECT_EQ(r.legs[0].name, "ahead 50 m");
  EXPECT_EQ(r.legs[1].name, "crab to port 50 m");
  EXPECT_EQ(r.legs[2].name, "astern 50 m, heading change -90°");
  EXPECT_EQ(r.legs[3].name, "astern 50 m");
}

TEST(FourCorner, AutoFallsBackToTheTrackWhenSetpointsNeverChange) {
  FourCornerInput in = box();
  std::fill(in.setpoint_north_m.begin(), in.setpoint_north_m.end(), 0.0);
  std::fill(in.setpoint_east_m.begin(), in.setpoint_east_m.end(), 0.0);
  std::fill(in.setpoint_heading_rad.begin(), in.setpoint_heading_rad.end(), 0.0);
  EXPECT_EQ(analyse_four_corner(in).segmentation, "track");
  FourCornerOptions forced;
  forced.segmentation = LegSegmentation::kSetpoints;
  EXPECT_THROW(analyse_four_corner(in, forced), core::InputError);
}

TEST(FourCorner, HeadingWrapsWhereTheLogJumps) {
  // A turn from 350° to 10° in the track is a +20° change, not −340°.
  EXPECT_EQ(leg_name(0.0, 0.0, std::remainder(20.0 * kPi / 180.0, 2 * kPi)), "heading change +20°");
  // The box rotated by 225°: the third leg turns from 225° to 135°, through 180°, where the
  // logged heading jumps from −180° to +180°.
  FourCornerInput in = box(false);
  const double phi = 225.0 * kPi / 180.0;
  for (double& h : in.heading_rad) h = std::remainder(h + phi, 2.0 * kPi);
  for (std::size_t i = 0; i < in.t_s.size(); ++i) {
    const double n = in.north_m[i], e = in.east_m[i];
    in.north_m[i] = std::cos(phi) * n - std::sin(phi) * e;
    in.east_m[i] = std::sin(phi) * n + std::cos(phi) * e;
  }
  const FourCornerResult r = analyse_four_corner(in);
  ASSERT_EQ(r.legs.size(), 4u);
  EXPECT_EQ(r.legs[2].name, "astern 50 m, heading change -90°");
}

TEST(FourCorner, LegNames) {
  EXPECT_EQ(leg_name(50.0, 0.3, 0.0), "ahead 50 m");
  EXPECT_EQ(leg_name(-20.0, 30.0, 0.0), "astern 20 m, crab to starboard 30 m");
  EXPECT_EQ(leg_name(50.0, 5.0, 0.0), "ahead 50 m");  // 5 m < a quarter of 50 m
  EXPECT_EQ(leg_name(0.5, 0.2, 0.01), "hold");
}

TEST(FourCorner, BadInput) {
  FourCornerInput in = box();
  FourCornerInput no_heading = in;
  no_heading.heading_rad.assign(in.t_s.size(), kNaN);
  EXPECT_THROW(analyse_four_corner(no_heading), core::InputError);
  FourCornerInput no_position = in;
  no_position.north_m.clear();
  EXPECT_THROW(analyse_four_corner(no_position), core::InputError);
  // No setpoint change and no motion: no leg.
  FourCornerInput still = box(false);
  for (std::size_t i = 0; i < still.t_s.size(); ++i) {
    if (!std::isnan(still.north_m[i])) still.north_m[i] = still.east_m[i] = 0.0;
    still.heading_rad[i] = 0.0;
  }
  EXPECT_THROW(analyse_four_corner(still), core::InputError);
  FourCornerOptions bad;
  bad.radius_m = 0.0;
  EXPECT_THROW(analyse_four_corner(in, bad), core::InputError);
}

}  // namespace
}  // namespace dynpos::ident
