// The virtual trial's device files read back through the analyses: the same figures as the
// clean log.csv they were written from, within the resolution of the device formats.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include "../io/io_test_util.hpp"
#include "dynpos/analysis/station_keeping.hpp"
#include "dynpos/scenario/campaign.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::analysis {
namespace {

namespace fs = std::filesystem;
using io::testing::TempDir;

fs::path source(const std::string& relative) { return fs::path(DYNPOS_SOURCE_DIR) / relative; }

// 300 s of the pure-DP stationkeeping programme (it asks for device files), in Hs 2 m.
void write_pure_dp(const fs::path& dir) {
  const scenario::VesselConfig vessel =
      scenario::load_vessel_config(source("data/vessels/gunnerus.toml"));
  scenario::ScenarioSpec spec = scenario::load_scenario(source("data/scenarios/pure-dp.toml"));
  spec.set_duration(300.0);
  scenario::write_scenario_run(scenario::run_scenario(spec, vessel, 21), dir);
}

StationKeepingReport station_keeping(LogSource source) {
  StationKeepingRequest request;
  request.source = std::move(source);
  request.t_from_s = 60.0;
  request.t_to_s = 290.0;
  return run_station_keeping(request);
}

TEST(DeviceFiles, StationKeepingFromTheNmeaCaptureMatchesTheCleanLog) {
  TempDir dir;
  write_pure_dp(dir.path());
  LogSource clean;
  clean.log = dir.path() / "log.csv";
  clean.columns = {"lat=gnss1.lat", "lon=gnss1.lon"};
  LogSource capture;
  capture.log = dir.path() / "devices" / "gnss1.nmea";  // no options: detected by content
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

}  // namespace
}  // namespace dynpos::analysis
