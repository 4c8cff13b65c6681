// LogSource with an NMEA 0183 capture: detection by content, the forced formats, the report.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "../source_dir.hpp"
#include "dynpos/analysis/log_source.hpp"
#include "input_error_capture.hpp"

namespace dynpos::analysis {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using testing::input_error;

std::filesystem::path capture(const std::string& name) {
  return std::filesystem::path(DYNPOS_SOURCE_DIR) / "tests" / "data" / "nmea" / name;
}

bool position_and_heading(const std::string& role) {
  return role == "lat" || role == "lon" || role == "heading";
}

TEST(LogSourceNmea, DetectedByContentWithItsReport) {
  LogSource source;
  source.log = capture("station.nmea");
  const LoadedLog loaded = source.load(position_and_heading);
  EXPECT_THAT(loaded.log.channel_names(), ElementsAre("lat", "lon", "heading"));
  EXPECT_EQ(loaded.log.size(), 20u);
  ASSERT_EQ(loaded.input.files.size(), 1u);
  const io::FileReport& file = loaded.input.files.front();
  EXPECT_EQ(file.format, "nmea");
  EXPECT_EQ(file.records, 44u);  // sentences used, not rows
  EXPECT_EQ(file.skipped.total(), 6u);
  EXPECT_EQ(loaded.input.origin, "2024-05-01T23:59:50.000Z");
  EXPECT_EQ(loaded.input.origin_zone, "UTC");
  ASSERT_EQ(loaded.input.roles.size(), 3u);
  EXPECT_DOUBLE_EQ(loaded.input.roles[0].rate_hz.value_or(0.0), 1.0);
  // Station keeping's position: lat/lon made local.
  const auto local = local_position(loaded.log);
  ASSERT_TRUE(local);
  EXPECT_NEAR(local->north_m[1] - local->north_m[0], -2.0, 1e-3);  // 1 m north → 1 m south
}

TEST(LogSourceNmea, StrictFormatAndColumnOptions) {
  LogSource source;
  source.log = capture("station.nmea");
  source.strict = true;
  EXPECT_THAT(input_error([&] { source.load(position_and_heading); }).what(),
              HasSubstr("station.nmea:1: line not usable (truncated)"));
  source.strict = false;
  source.format = "xml";
  EXPECT_EQ(input_error([&] { source.load(position_and_heading); }).option(), "format");
  source.format = "nmea";
  source.columns = {"heading=HDT"};
  EXPECT_EQ(input_error([&] { source.load(position_and_heading); }).option(), "col");
  source.columns.clear();
  source.format = "csv";  // read as CSV, the capture has no header with a time column
  EXPECT_THAT(input_error([&] { source.load(position_and_heading); }).what(),
              HasSubstr("station.nmea"));
}

}  // namespace
}  // namespace dynpos::analysis
