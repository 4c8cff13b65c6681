// The virtual trial's device files read back through the analyses: the same figures as the
// clean log.csv they were written from, within the resolution of the device formats.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include "../io/io_test_util.hpp"
#include "../source_dir.hpp"
#include "dynpos/analysis/leverarm_gnss.hpp"
#include "dynpos/analysis/leverarm_mru.hpp"
#include "dynpos/analysis/station_keeping.hpp"
#include "dynpos/analysis/step.hpp"
#include "dynpos/scenario/campaign.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::analysis {
namespace {

namespace fs = std::filesystem;
using io::testing::TempDir;

fs::path source(const std::string& relative) { return fs::path(DYNPOS_SOURCE_DIR) / relative; }

// 300 s of the pure-DP stationkeeping programme (it asks for device files), in Hs 2 m: run
// once and read by every test that needs it (the tests only read the folder).
const fs::path& pure_dp_dir() {
  static const TempDir dir;
  static const bool written = [] {
    const scenario::VesselConfig vessel =
        scenario::load_vessel_config(source("data/vessels/gunnerus.toml"));
    scenario::ScenarioSpec spec = scenario::load_scenario(source("data/scenarios/pure-dp.toml"));
    spec.set_duration(300.0);
    scenario::write_scenario_run(scenario::run_scenario(spec, vessel, 21), dir.path());
    return true;
  }();
  (void)written;
  return dir.path();
}

// The clean log's antenna 1 as the position.
LogSource clean_positions() {
  LogSource clean;
  clean.log = pure_dp_dir() / "log.csv";
  clean.columns = {"lat=gnss1.lat", "lon=gnss1.lon"};
  return clean;
}

// A built-in scenario, shortened to `duration_s` (0: as written), with device files at the
// rates of `files`, run with seed 3 into `dir`.
void write_with_devices(const std::string& name, double duration_s,
                        const scenario::DeviceFilesSpec& files, const fs::path& dir) {
  const scenario::VesselConfig vessel =
      scenario::load_vessel_config(source("data/vessels/gunnerus.toml"));
  scenario::ScenarioSpec spec = scenario::load_scenario(source("data/scenarios/" + name + ".toml"));
  if (duration_s > 0.0) spec.set_duration(duration_s);
  spec.device_files = files;
  scenario::write_scenario_run(scenario::run_scenario(spec, vessel, 3), dir);
}

StationKeepingReport station_keeping(LogSource source) {
  StationKeepingRequest request;
  request.source = std::move(source);
  request.t_from_s = 60.0;
  request.t_to_s = 290.0;
  return run_station_keeping(request);
}

TEST(DeviceFiles, StationKeepingFromTheNmeaCaptureMatchesTheCleanLog) {
  const fs::path& dir = pure_dp_dir();
  const LogSource clean = clean_positions();
  LogSource capture;
  capture.log = dir / "devices" / "gnss1.nmea";  // no options: detected by content
  const StationKeepingReport a = station_keeping(clean);
  const StationKeepingReport b = station_keeping(capture);
  ASSERT_EQ(a.windows.size(), 1u);
  ASSERT_EQ(b.windows.size(), 1u);
  const ident::StationKeepingResult& wa = a.windows[0];
  const ident::StationKeepingResult& wb = b.windows[0];
  // The capture's clock is its logger stamps, which start at the log's t = 0 (the truncated
  // first line is skipped, the next carries the same fix time): the same 1 Hz fixes.
  EXPECT_EQ(wb.position_samples, wa.position_samples);
  ASSERT_TRUE(wa.position_std_north_m && wb.position_std_north_m);
  // GGA writes 7 decimals of arc minutes (0.19 mm of latitude): the spreads agree to 1 mm.
  EXPECT_NEAR(*wb.position_std_north_m, *wa.position_std_north_m, 1e-3);
  EXPECT_NEAR(*wb.position_std_east_m, *wa.position_std_east_m, 1e-3);
  EXPECT_GT(*wa.position_std_north_m, 0.01);  // the vessel moves: the comparison means something
  // HDT is the gyro at the fix times (1 Hz, 3 decimals of a degree), log.csv has it at its own
  // rate: the mean heading over 230 s agrees within 0.1°, far inside the 2° operating limit.
  ASSERT_TRUE(wa.heading_rad.mean && wb.heading_rad.mean);
  EXPECT_NEAR(*wb.heading_rad.mean, *wa.heading_rad.mean, 0.1 * std::numbers::pi / 180.0);
  // The report says what was read: the capture's cut lines are counted, not fatal.
  ASSERT_EQ(b.input.files.size(), 1u);
  EXPECT_EQ(b.input.files[0].format, "nmea");
  EXPECT_GE(b.input.files[0].skipped.total(), 2u);  // first and last line cut mid-sentence
  ASSERT_TRUE(b.input.origin);
  EXPECT_EQ(*b.input.origin, "2014-08-27T10:00:00.000Z");
}

TEST(DeviceFiles, StepsFromTheThrusterAndOrderFilesMatchTheCleanLog) {
  // The first 900 s of the forward surge steps: port rpm orders 0 → 9 → 18 → 27 rpm. The
  // feedback file (epoch ms, 2 Hz) is the main log; the dithered orders (seconds + nanoseconds,
  // 2 Hz) come from their own file, aligned by the absolute stamps of the two.
  TempDir dir;
  scenario::DeviceFilesSpec files;
  files.order_wiggle_rpm = 2.0;
  write_with_devices("surge-steps-forward", 900.0, files, dir.path());
  StepRequest clean;
  clean.source.log = dir.path() / "log.csv";
  clean.source.columns = {"input=command.rpm.port", "output=rpm.port"};
  clean.min_step = 0.1;  // [rps]: 6 rpm, below the 9 rpm steps, 7 σ of the dither
  StepRequest devices = clean;
  const std::string orders = (dir.path() / "devices" / "orders.csv").string();
  devices.source.log = dir.path() / "devices" / "thrusters.csv";
  devices.source.columns = {"time=EpochMs", "output=port_rpm", "input=order_rpm_port@" + orders,
                            "time.sec=sec@" + orders, "time.nsec=nsec@" + orders};
  const StepReport a = run_step(clean);
  const StepReport b = run_step(devices);
  ASSERT_EQ(a.steps.size(), 3u);
  ASSERT_EQ(b.steps.size(), a.steps.size());
  // Levels are medians over 60 s of 2 Hz orders (n = 120) with a uniform dither of ±a: each
  // within a/√n·3 (3σ of the median of a uniform), Δu within √2 of that.
  const double a_rps = 2.0 / 60.0;
  const double du_tol = 3.0 * std::sqrt(2.0) * a_rps / std::sqrt(120.0);
  for (std::size_t k = 0; k < a.steps.size(); ++k) {
    SCOPED_TRACE(k);
    const StepFit& x = a.steps[k];
    const StepFit& y = b.steps[k];
    ASSERT_EQ(x.status, core::Status::kOk);
    ASSERT_EQ(y.status, core::Status::kOk);
    // Both order logs sample the command at the same instants (2 Hz is a divisor of the log
    // rate): the same step time, to round-off.
    EXPECT_NEAR(y.step.t_step, x.step.t_step, 1e-6);
    EXPECT_NEAR(*y.gain, *x.gain, du_tol / std::abs(*x.step.delta_u()) * 1.01);
    // The feedback is sampled at 2 Hz instead of 10 Hz: T and δ within half its sample
    // interval.
    EXPECT_NEAR(*y.time_constant_s, *x.time_constant_s, 0.25);
    EXPECT_NEAR(*y.dead_time_s, *x.dead_time_s, 0.25);
  }
  ASSERT_EQ(b.input.files.size(), 2u);
  EXPECT_EQ(b.input.files[0].time_format, "epoch-ms");
  EXPECT_EQ(b.input.files[1].time_format, "sec-nsec");
  EXPECT_EQ(b.input.files[1].clock_offset_s, 0.0);  // the two files start at the same second
  ASSERT_TRUE(b.input.origin);
  EXPECT_EQ(b.input.origin->substr(0, 19), "2014-08-27T10:00:00");
}

TEST(DeviceFiles, MruArmsFromTheMruFileMatchTheCleanLog) {
  // The turning circle (the manoeuvre that determines the MRU arms); MRU 1 from its own file
  // with ISO date-time stamps, the motion from truth.csv (relative seconds, the same t = 0).
  TempDir dir;
  write_with_devices("turning-circle", 0.0, {}, dir.path());
  LeverarmMruRequest clean;
  clean.source.log = dir.path() / "truth.csv";
  clean.mru_log = {{"mru1", dir.path() / "log.csv"}};
  LeverarmMruRequest devices;
  const std::string mru = (dir.path() / "devices" / "mru.csv").string();
  devices.source.log = dir.path() / "truth.csv";
  devices.source.columns = {"time=Time@" + mru, "mru1.ax=AccX@" + mru, "mru1.ay=AccY@" + mru,
                            "mru1.az=AccZ@" + mru};
  const LeverarmMruReport a = run_leverarm_mru(clean);
  const LeverarmMruReport b = run_leverarm_mru(devices);
  ASSERT_EQ(b.result.arms.size(), 1u);
  const auto arm_a = std::find_if(a.result.arms.begin(), a.result.arms.end(),
                                  [](const calib::ArmEstimate& e) { return e.name == "mru1"; });
  ASSERT_NE(arm_a, a.result.arms.end());
  // The device file carries every digit of the samples and millisecond stamps of a 100 Hz
  // clock: the two time axes differ by round-off only, so the arms agree to 1 µm.
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(b.result.arms[0].l_b_m[axis], arm_a->l_b_m[axis], 1e-6) << axis;
  }
  EXPECT_GT(std::abs(arm_a->l_b_m.z()), 1.0);  // a real arm, not a zero that matches a zero
  ASSERT_EQ(b.input.files.size(), 2u);
  EXPECT_EQ(b.input.files[1].time_format, "iso8601");
}

TEST(DeviceFiles, ThrustFromTheFeedbackFileBesideTheNmeaCapture) {
  // The capture is the main log (positions, heading); the thrust feedback (epoch ms, 2 Hz) is
  // a further file, aligned by the absolute stamps of the two.
  const fs::path& dir = pure_dp_dir();
  const LogSource clean = clean_positions();
  LogSource capture;
  const std::string thrusters = (dir / "devices" / "thrusters.csv").string();
  capture.log = dir / "devices" / "gnss1.nmea";
  capture.columns = {"time=EpochMs@" + thrusters, "thrust.port=port_thrust@" + thrusters,
                     "thrust.stb=stb_thrust@" + thrusters,
                     "thrust.tunnel=tunnel_thrust@" + thrusters};
  const StationKeepingReport a = station_keeping(clean);
  const StationKeepingReport b = station_keeping(capture);
  ASSERT_EQ(b.windows.size(), 1u);
  const ident::StationKeepingResult& wa = a.windows[0];
  const ident::StationKeepingResult& wb = b.windows[0];
  ASSERT_TRUE(wa.total_mean_abs_thrust_N && wb.total_mean_abs_thrust_N);
  EXPECT_GT(*wa.total_mean_abs_thrust_N, 1e3);
  // The feedback file holds every 5th sample of log.csv's 10 Hz thrust, put on the capture's
  // 1 Hz axis (linear between its 2 Hz samples): the mean of 230 of them against the mean of
  // 2300. DP thrust moves slowly (its spread over the window is ~1 kN): within 2 % (120 N).
  EXPECT_NEAR(*wb.total_mean_abs_thrust_N, *wa.total_mean_abs_thrust_N,
              0.02 * *wa.total_mean_abs_thrust_N);
  ASSERT_EQ(b.input.files.size(), 2u);
  EXPECT_EQ(b.input.files[0].format, "nmea");
  EXPECT_EQ(b.input.files[1].time_format, "epoch-ms");
  // Both clocks are UTC and start at 10:00:00: no offset, the alignment is by the stamps.
  EXPECT_EQ(b.input.files[1].clock_offset_s, 0.0);
  EXPECT_THAT(b.input.files[1].notes, ::testing::Contains("aligned on the main log by its "
                                                          "absolute time stamps"));
}

TEST(DeviceFiles, PositionsFromACaptureBesideTheCsvLog) {
  // log.csv is the main log; lat and lon come from the antenna's capture (a further file).
  const fs::path& dir = pure_dp_dir();
  LogSource source;
  const std::string capture = (dir / "devices" / "gnss1.nmea").string();
  source.log = dir / "log.csv";
  source.columns = {"lat=lat@" + capture, "lon=lon@" + capture};
  // log.csv counts seconds from 10:00:00, the capture has UTC stamps: the clocks are aligned by
  // the offset only. The capture's t = 0 is its first GGA, 10:00:01 (the 10:00:00 one is the
  // line cut at the start of the capture), so the offset is 1 s; the report says so.
  source.clock_offsets = {capture + "=1"};
  const core::Log log = source.read([](const std::string& role) {
    return role == "gnss1.lat" || role == "lat" || role == "lon";
  });
  const std::vector<double>& lat_clean = log.values("gnss1.lat");
  const std::vector<double>& lat = log.values("lat");
  // At the fix times (where log.csv has its 1 Hz fixes) the aligned capture gives the fix:
  // GGA's 7 decimals of arc minutes are 1.7e-9 of a minute = 2.9e-11 rad; 1e-10 rad = 0.6 mm.
  std::size_t fixes = 0;
  for (std::size_t i = 0; i < log.size(); ++i) {
    if (core::is_missing(lat_clean[i]) || core::is_missing(lat[i])) continue;
    EXPECT_NEAR(lat[i], lat_clean[i], 1e-10) << "t = " << log.time()[i];
    ++fixes;
  }
  EXPECT_GE(fixes, 298u);  // 300 s of 1 Hz fixes; the capture's cut first and last lines
}

// Lever arms from the logger alone on what the devices wrote: the MRU file (date-time stamps,
// vendor names, 10 Hz), each antenna's serial capture (logger stamps, first and last line cut)
// and the gyro heading from the trial logger's file beside them. Against the same estimate on
// the clean log.csv: the same 897 fixes and the arms within 0.1 mm (the capture's 7 decimals
// of arc minutes are 0.2 mm; the MRU file repeats the log's values).
TEST(DeviceFiles, LoggerOnlyLeverArmsFromTheDeviceFiles) {
  const fs::path& dir = pure_dp_dir();
  LeverarmGnssRequest clean;
  clean.source.log = dir / "log.csv";
  clean.antennas = {"gnss1", "gnss2", "gnss3"};
  clean.imu_arm = Eigen::Vector3d(0.358, 0.804, -4.321);
  const LeverarmGnssReport a = run_leverarm_gnss(clean);
  LeverarmGnssRequest devices = clean;
  devices.source.log = dir / "devices" / "mru.csv";
  devices.source.columns = {"time=Time",        "mru1.roll=Roll",
                            "mru1.pitch=Pitch", "mru1.p=RollRate",
                            "mru1.q=PitchRate", "mru1.r=YawRate",
                            "mru1.ax=AccX",     "mru1.ay=AccY",
                            "mru1.az=AccZ",     "heading=heading@" + (dir / "log.csv").string()};
  for (const char* k : {"gnss1", "gnss2", "gnss3"})
    devices.nmea[k] = dir / "devices" / (std::string(k) + ".nmea");
  const LeverarmGnssReport b = run_leverarm_gnss(devices);
  ASSERT_TRUE(a.ins && b.ins);
  EXPECT_EQ(b.method, LeverarmGnssMethod::kIns);
  EXPECT_EQ(b.ins->gnss.fixes, a.ins->gnss.fixes);
  ASSERT_EQ(b.ins->gnss.arms.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) {
      if (a.ins->gnss.arms[k].determinacy[i] == calib::Determinacy::kNot) continue;
      EXPECT_NEAR(b.ins->gnss.arms[k].l_b_m[i], a.ins->gnss.arms[k].l_b_m[i], 1e-4) << k << i;
    }
  EXPECT_EQ(b.input.files[0].time_format, "iso8601");
  EXPECT_THAT(b.input.files.back().notes,
              ::testing::Contains("aligned on the main log by its absolute time stamps"));
}

}  // namespace
}  // namespace dynpos::analysis
