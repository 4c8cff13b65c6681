#include "dynpos/ident/station_keeping.hpp"

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

// 600 s at 10 Hz. North: UTM-like offset plus a sine of amplitude 1 m (std 1/√2 over whole
// periods); east: constant; heading: ±1° square wave about 0° (359° and 1°); wind from 350° or
// 10° alternately at 8 ± 1 m/s; thrusters: port 20 kN and 100 kW, tunnel ±5 kN without power.
StationKeepingInput synthetic() {
  StationKeepingInput in;
  for (int i = 0; i <= 6000; ++i) {
    const double t = 0.1 * i;
    in.t_s.push_back(t);
    in.north_m.push_back(7'000'000.0 + std::sin(2.0 * kPi * t / 20.0));
    in.east_m.push_back(500'000.0);
    const double s = (i % 2 == 0) ? 1.0 : -1.0;
    in.heading_rad.push_back(std::remainder(s * kPi / 180.0, 2.0 * kPi));
    in.wind_speed_mps.push_back(8.0 + s);
    in.wind_dir_rad.push_back(s * 10.0 * kPi / 180.0);
  }
  in.thrusters.push_back({"port", std::vector<double>(in.t_s.size(), 20e3),
                          std::vector<double>(in.t_s.size(), 100e3)});
  std::vector<double> tunnel(in.t_s.size());
  for (std::size_t i = 0; i < tunnel.size(); ++i) tunnel[i] = (i / 100) % 2 == 0 ? 5e3 : -5e3;
  in.thrusters.push_back({"tunnel", tunnel, {}});
  return in;
}

TEST(StationKeeping, StatisticsOfAKnownWindow) {
  const StationKeepingInput in = synthetic();
  const StationKeepingResult r = analyse_station_keeping(in, {"w", 100.0, 400.0});
  // A sine of amplitude 1 m over 15 whole periods: std 1/√2 (sampling error < 1e-3 m).
  ASSERT_TRUE(r.position_std_north_m);
  EXPECT_NEAR(*r.position_std_north_m, 1.0 / std::sqrt(2.0), 1e-3);
  EXPECT_NEAR(*r.position_std_east_m, 0.0, 1e-9);  // the offset drops out
  // 359° and 1° average to 0°, not 180° (3001 samples, one extra +1°: 1°/3001 = 6e-6 rad);
  // the circular std of ±1° is 1°.
  ASSERT_TRUE(r.heading_rad.mean);
  EXPECT_NEAR(*r.heading_rad.mean, 0.0, 1e-5);
  EXPECT_NEAR(*r.heading_rad.std * 180.0 / kPi, 1.0, 1e-3);
  EXPECT_NEAR(*r.wind_speed_mps.mean, 8.0, 1e-2);  // 3001 samples: one extra +1
  EXPECT_NEAR(*r.wind_speed_mps.std, 1.0, 1e-3);
  EXPECT_NEAR(*r.wind_dir_rad.mean, 0.0, 1e-3);
  // Port: 20 kN for 300 s = 6000 kNs; 100 kW → 30 MJ. Tunnel ±5 kN: mean |T| 5 kN.
  ASSERT_EQ(r.thrusters.size(), 2u);
  EXPECT_NEAR(*r.thrusters[0].mean_abs_thrust_N, 20e3, 1e-6);
  EXPECT_NEAR(*r.thrusters[0].accumulated_thrust_Ns, 6e6, 1e-3);
  EXPECT_NEAR(*r.thrusters[0].energy_J, 30e6, 1e-3);
  // |T| of a square wave through the trapezoid: the 0.1 s sign changes cost a little.
  EXPECT_NEAR(*r.thrusters[1].mean_abs_thrust_N, 5e3, 5e3 * 0.01);
  // The tunnel's power is not logged: its energy, and so the total, are missing, never 0.
  EXPECT_FALSE(r.thrusters[1].energy_J);
  EXPECT_FALSE(r.total_energy_J);
  ASSERT_TRUE(r.total_mean_abs_thrust_N);
  EXPECT_NEAR(*r.total_mean_abs_thrust_N, 25e3, 60.0);
}

TEST(StationKeeping, PositionFromASlowSensorAndMissingWind) {
  StationKeepingInput in = synthetic();
  for (std::size_t i = 0; i < in.t_s.size(); ++i) {
    if (i % 10 != 0) in.north_m[i] = in.east_m[i] = kNaN;  // GNSS at 1 Hz
  }
  in.wind_speed_mps.clear();
  in.wind_dir_rad.clear();
  const StationKeepingResult r = analyse_station_keeping(in, {"w", 100.0, 400.0});
  EXPECT_EQ(r.position_samples, 301u);
  EXPECT_NEAR(*r.position_std_north_m, 1.0 / std::sqrt(2.0), 1e-2);
  EXPECT_FALSE(r.wind_speed_mps.mean);
  EXPECT_FALSE(r.wind_dir_rad.std);
}

TEST(StationKeeping, BadWindowsAndMissingPositionAreInputErrors) {
  StationKeepingInput in = synthetic();
  EXPECT_THROW(analyse_station_keeping(in, {"w", 500.0, 700.0}), core::InputError);
  EXPECT_THROW(analyse_station_keeping(in, {"w", 300.0, 300.0}), core::InputError);
  EXPECT_THROW(analyse_station_keeping(in, {"w", 100.0, 100.5}), core::InputError);  // 6 fixes
  // A window's problem names its request key, never a command-line spelling.
  try {
    analyse_station_keeping(in, {"w", 500.0, 700.0});
    ADD_FAILURE() << "no error";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.option(), "from/to");
    EXPECT_EQ(e.where().column_name, "from/to");
    EXPECT_NE(e.problem().find("the window 500 … 700 s is not inside the log (0 … "),
              std::string::npos)
        << e.problem();
  }
  in.north_m.clear();
  EXPECT_THROW(analyse_station_keeping(in, {"w", 100.0, 400.0}), core::InputError);
}

TEST(StationKeeping, OneWindowPerSetpointHold) {
  // Holds of 430 s at headings 0, 90, 45 with blanks between setpoint samples; 300 s windows
  // end at each change.
  std::vector<double> t, n, e, h;
  for (int i = 0; i <= 1290; ++i) {
    t.push_back(i);
    const bool logged = i % 10 == 0;
    const double heading = i < 430 ? 0.0 : (i < 860 ? 90.0 : 45.0);
    n.push_back(logged ? 0.0 : kNaN);
    e.push_back(logged ? 0.0 : kNaN);
    h.push_back(logged ? heading * kPi / 180.0 : kNaN);
  }
  const auto w = setpoint_windows(t, n, e, h, 300.0);
  ASSERT_EQ(w.size(), 3u);
  EXPECT_EQ(w[0].name, "heading 0");
  EXPECT_EQ(w[1].name, "heading 90");
  EXPECT_EQ(w[2].name, "heading 45");
  EXPECT_DOUBLE_EQ(w[0].t_to_s, 429.0);
  EXPECT_DOUBLE_EQ(w[0].t_from_s, 129.0);
  EXPECT_DOUBLE_EQ(w[1].t_to_s, 859.0);
  EXPECT_DOUBLE_EQ(w[2].t_to_s, 1290.0);
  EXPECT_DOUBLE_EQ(w[2].t_from_s, 990.0);
  // A hold cut off by the end of the log after 100 s (< half of 300 s) gives no window.
  std::vector<double> t2(t.begin(), t.begin() + 961), n2(n.begin(), n.begin() + 961),
      e2(e.begin(), e.begin() + 961), h2(h.begin(), h.begin() + 961);
  EXPECT_EQ(setpoint_windows(t2, n2, e2, h2, 300.0).size(), 2u);
}

}  // namespace
}  // namespace dynpos::ident
