// A log spread over several files (read_log_files, LogSource::load): each file on its own clock
// + offset, aligned on the main log's time axis, every role by its own interpolation.

#include "dynpos/analysis/log_source.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <string>

#include <fmt/format.h>

#include "input_error_capture.hpp"

namespace dynpos::analysis {
namespace {

using ::testing::ContainsRegex;
using ::testing::HasSubstr;
using testing::input_error;

constexpr double kDeg = std::numbers::pi / 180.0;

// Surge speed in nav.csv [m/s]: smooth, so linear interpolation at 1 Hz has a known error.
double surge_mps(double t) { return 2.0 + 0.5 * std::sin(0.3 * (t - 100.0)); }
// Heading in nav.csv [deg]: 2 °/s from 357°, crossing 0° at t = 101.5 s.
double heading_deg(double t) { return std::fmod(357.0 + 2.0 * (t - 100.0), 360.0); }

// main.csv: 10 Hz, t = 100 … 110 s. nav.csv: 1 Hz on the same clock with its own time column
// "stamp", r blank at 105–107 s (a 4 s gap). gps.csv: 1 Hz on a clock 100.5 s behind.
class LogFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device entropy;
    dir_ =
        std::filesystem::temp_directory_path() / ("dynpos-log-files-" + std::to_string(entropy()));
    std::filesystem::create_directories(dir_);
    std::string main = "time,v\n";
    for (int i = 0; i <= 100; ++i) main += fmt::format("{:.1f},{}\n", 100.0 + 0.1 * i, 0.01 * i);
    write("main.csv", main);
    std::string nav = "stamp,SOG,HDG,cmd,r\n";
    for (int k = 0; k <= 10; ++k) {
      const double t = 100.0 + k;
      const std::string r = (k >= 5 && k <= 7) ? "" : "1.5";
      nav += fmt::format("{},{:.17g},{:.17g},{},{}\n", t, surge_mps(t), heading_deg(t),
                         k < 3 ? 10 : 50, r);
    }
    write("nav.csv", nav);
    std::string gps = "time,N\n";
    for (int k = 0; k <= 9; ++k) gps += fmt::format("{},{}\n", k, 10 * k);
    write("gps.csv", gps);
    write("late.csv", "time,N\n500,1\n501,2\n");
    write("sparse.csv", "time,E\n99.95,1\n110.05,2\n");
  }
  void TearDown() override {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name, std::ios::binary) << text;
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  LogSource source() const {
    LogSource s;
    s.log = dir_ / "main.csv";
    const std::string nav = path("nav.csv");
    s.columns = {"u=SOG@" + nav, "heading=HDG@" + nav, "command.port=cmd@" + nav,
                 "r=r@" + nav,   "time=stamp@" + nav,  "north=N@" + path("gps.csv")};
    s.clock_offsets = {path("gps.csv") + "=100.5"};
    return s;
  }

  static LoadedLog load(const LogSource& s) {
    return s.load([](const std::string&) { return true; });
  }

  std::filesystem::path dir_;
};

TEST_F(LogFiles, RolesOfOtherFilesLandOnTheMainTimeAxis) {
  const LoadedLog loaded = load(source());
  const core::Log& log = loaded.log;
  ASSERT_EQ(log.size(), 101u);  // the main log's axis
  EXPECT_DOUBLE_EQ(log.time().front(), 100.0);
  for (std::size_t i = 0; i < log.size(); ++i) {
    const double t = log.time()[i];
    SCOPED_TRACE(t);
    // Linear between 1 Hz samples: |error| ≤ h²/8 · max|u''| = 1²/8 · 0.5 · 0.3² = 5.7e-3 m/s.
    EXPECT_NEAR(log.values("u")[i], surge_mps(t), 5.7e-3);
    // Along the shorter arc across 0°: the analytic heading, exact up to roundings (1e-12 rad).
    const double psi = log.values("heading")[i];
    EXPECT_NEAR(std::remainder(psi - heading_deg(t) * kDeg, 2.0 * std::numbers::pi), 0.0, 1e-12);
    EXPECT_TRUE(psi >= 0.0 && psi < 2.0 * std::numbers::pi);
    // A command holds its last sample: 10 % until 102 s, 50 % from the sample at 103 s on.
    EXPECT_DOUBLE_EQ(log.values("command.port")[i], t < 103.0 - 1e-9 ? 0.10 : 0.50);
    // r: 1.5 °/s, NaN inside the 4 s gap (104, 108) s, wider than 2.5 × 1 s.
    const bool in_gap = t > 104.0 + 1e-9 && t < 108.0 - 1e-9;
    EXPECT_EQ(std::isnan(log.values("r")[i]), in_gap);
    if (!in_gap) {
      EXPECT_DOUBLE_EQ(log.values("r")[i], 1.5 * kDeg);
    }
  }
  // The bound is nearly reached (so it is not vacuous): at 105.5 s, where |u''| is largest, the
  // error is 1/8 · 0.045 · sin(1.65) ≈ 5.6e-3 m/s.
  EXPECT_GT(std::abs(log.values("u")[55] - surge_mps(105.5)), 5e-3);
  // Midway across 0° (101.5 s): 0° modulo 2π, not 180° as a straight line through 359° and 1°.
  EXPECT_NEAR(std::remainder(log.values("heading")[15], 2.0 * std::numbers::pi), 0.0, 1e-12);
}

TEST_F(LogFiles, ClockOffsetShiftsTheSamplesExactly) {
  const core::Log log = load(source()).log;
  // gps.csv sample k (own time k s, north 10k m) is at main time 100.5 + k exactly.
  for (std::size_t i = 0; i < log.size(); ++i) {
    const double t = log.time()[i];
    const double north = log.values("north")[i];
    if (t < 100.5 - 1e-9 || t > 109.5 + 1e-9) {
      EXPECT_TRUE(std::isnan(north)) << t;  // no extrapolation outside the file's range
    } else {
      EXPECT_NEAR(north, 10.0 * (t - 100.5), 1e-9) << t;  // linear through a line
    }
  }
  EXPECT_EQ(log.values("north")[5], 0.0);    // 100.5 s: sample 0, exactly
  EXPECT_EQ(log.values("north")[25], 20.0);  // 102.5 s: sample 2, exactly
  EXPECT_EQ(log.values("north")[95], 90.0);  // 109.5 s: the last sample
}

TEST_F(LogFiles, MaxGapBridgesWhatItIsToldTo) {
  LogSource s = source();
  s.max_gap_s = 5.0;  // wider than r's 4 s gap
  const core::Log log = load(s).log;
  for (double r : log.values("r")) EXPECT_DOUBLE_EQ(r, 1.5 * kDeg);
  s.max_gap_s = -1.0;
  EXPECT_EQ(input_error([&] { load(s); }).option(), "max_gap");
}

TEST_F(LogFiles, ARoleWithNoSampleOnTheMainAxisIsNoted) {
  // sparse.csv spans the main log but its only two samples are 10.1 s apart: with --max-gap 5
  // every main-log time is inside the gap. Not an error, but never a silent all-missing role.
  LogSource s = source();
  s.columns.push_back("east=E@" + path("sparse.csv"));
  s.max_gap_s = 5.0;
  const LoadedLog loaded = load(s);
  for (double e : loaded.log.values("east")) EXPECT_TRUE(std::isnan(e));
  const io::FileReport* sparse = loaded.input.file(path("sparse.csv"));
  ASSERT_NE(sparse, nullptr);
  ASSERT_EQ(sparse->notes.size(), 1u);
  EXPECT_THAT(sparse->notes[0], HasSubstr("role 'east' has no sample on the main log's time axis"));
}

TEST_F(LogFiles, TheReportListsEachFileAndEachRolesOriginAndRate) {
  const io::InputReport input = load(source()).input;
  ASSERT_EQ(input.files.size(), 3u);
  EXPECT_EQ(input.files[0].path, path("main.csv"));  // the main log first
  EXPECT_EQ(input.files[0].records, 101u);
  const io::FileReport* nav = input.file(path("nav.csv"));
  ASSERT_NE(nav, nullptr);
  EXPECT_EQ(nav->format, "csv");
  EXPECT_EQ(nav->time_format, "seconds");
  EXPECT_EQ(nav->records, 11u);
  EXPECT_EQ(nav->clock_offset_s, 0.0);
  EXPECT_TRUE(nav->notes.empty());
  const io::FileReport* gps = input.file(path("gps.csv"));
  ASSERT_NE(gps, nullptr);
  EXPECT_EQ(gps->clock_offset_s, 100.5);
  ASSERT_EQ(gps->notes.size(), 1u);  // it covers only part of the main log
  EXPECT_THAT(gps->notes[0], HasSubstr("covers [100.5, 109.5] s of the main log's [100, 110] s"));

  const auto origin = [&](const std::string& role) {
    for (const io::RoleOrigin& o : input.roles) {
      if (o.role == role) return o;
    }
    ADD_FAILURE() << "no role " << role;
    return io::RoleOrigin{};
  };
  EXPECT_EQ(origin("v").file, path("main.csv"));
  EXPECT_NEAR(*origin("v").rate_hz, 10.0, 1e-9);
  // Rates on each file's own clock: 1 Hz, not the main log's 10 Hz.
  EXPECT_EQ(origin("u").file, path("nav.csv"));
  EXPECT_NEAR(*origin("u").rate_hz, 1.0, 1e-12);
  EXPECT_EQ(origin("north").file, path("gps.csv"));
  EXPECT_NEAR(*origin("north").rate_hz, 1.0, 1e-12);
}

TEST_F(LogFiles, ErrorsNameTheFile) {
  LogSource s = source();
  s.columns.push_back("p=roll_rate@" + path("nav.csv"));
  EXPECT_THAT(input_error([&] { load(s); }).what(),
              ContainsRegex("nav\\.csv:1.*column 'roll_rate' for role 'p' is not in the header"));

  s = source();
  s.columns.push_back("p=x@" + path("absent.csv"));
  EXPECT_THAT(input_error([&] { load(s); }).what(),
              ContainsRegex("absent\\.csv: cannot open the log"));

  s = source();
  s.columns.push_back("p=N@" + path("late.csv"));
  EXPECT_THAT(input_error([&] { load(s); }).what(),
              ContainsRegex("late\\.csv: its times span \\[500, 501\\] s on the main log's clock "
                            "\\(clock offset 0 s\\), outside the main log's \\[100, 110\\] s.*"
                            "--clock-offset"));

  s = source();
  s.clock_offsets.push_back("gps.csv=abc");
  EXPECT_THAT(input_error([&] { load(s); }).what(),
              ContainsRegex("\\(clock_offset\\): malformed argument .gps.csv=abc."));
}

// A GNSS logger whose receiver missed a week-number rollover dates its fixes 1024 weeks early
// (2005-09-12 for 2025-04-28). Aligned by absolute stamps, that file would fall 19.6 years
// before the main log: it is aligned 1024 weeks later, with a note saying so, and the values
// land where they belong; either way round; with --strict it is an error naming the file.
TEST_F(LogFiles, AGpsWeekRolloverIsFoundAndNoted) {
  std::string main = "time,v\n";
  std::string early = "time,N\n";
  for (int k = 0; k <= 10; ++k) {
    main += fmt::format("2025-04-28T11:39:{:02d}Z,{}\n", 10 + k, k);
    early += fmt::format("2005-09-12T11:39:{:02d}.5Z,{}\n", 10 + k, 100 + k);
  }
  write("main_utc.csv", main);
  write("gnss_early.csv", early);
  LogSource s;
  s.log = dir_ / "main_utc.csv";
  s.columns = {"time=time", "v=v", "north=N@" + path("gnss_early.csv")};
  const LoadedLog loaded = load(s);
  const core::Channel& north = loaded.log.channel("north");
  EXPECT_NEAR(north.values[3], 102.5, 1e-9);  // 11:39:13 is halfway from 11:39:12.5 to 13.5
  EXPECT_THAT(loaded.input.files.back().notes,
              ::testing::Contains(HasSubstr("its absolute time stamps are 1024 weeks (19.6 years) "
                                            "before the main log's: its dates are those of a GPS "
                                            "receiver after a week-number rollover; aligned 1024 "
                                            "weeks later")));

  // The main log's receiver rolled over: the other file is aligned 1024 weeks earlier.
  write("main_early.csv", early);
  write("gnss_right.csv", main);
  s.log = dir_ / "main_early.csv";
  s.columns = {"time=time", "north=N", "v=v@" + path("gnss_right.csv")};
  const LoadedLog other = load(s);
  EXPECT_NEAR(other.log.channel("v").values[2], 2.5, 1e-9);
  EXPECT_THAT(other.input.files.back().notes,
              ::testing::Contains(HasSubstr("after the main log's: the main log's dates are")));

  s.strict = true;
  EXPECT_THAT(input_error([&] { load(s); }).what(),
              ContainsRegex("gnss_right\\.csv: its absolute time stamps are 1024 weeks .*"
                            "refused with --strict"));
}

}  // namespace
}  // namespace dynpos::analysis
