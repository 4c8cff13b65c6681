// The virtual sea trial's NMEA output (write_scenario_run → gnssK.nmea), read back with
// io::read_nmea_gnss and checked against the trial log it was written from.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <random>
#include <string>

#include "../source_dir.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/io/csv_reader.hpp"
#include "dynpos/io/nmea.hpp"
#include "dynpos/scenario/campaign.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/trial_truth.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::scenario {
namespace {

namespace fs = std::filesystem;
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kMetresPerRadian = 6.371e6;  // mean Earth radius; 1 % is plenty here

class TempDir {
 public:
  TempDir() {
    std::random_device entropy;
    path_ = fs::temp_directory_path() / ("dynpos-nmea-" + std::to_string(entropy()));
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

fs::path source(const std::string& relative) { return fs::path(DYNPOS_SOURCE_DIR) / relative; }

std::string file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

ScenarioSpec short_turning_circle(double duration_s) {
  ScenarioSpec spec = load_scenario(source("data/scenarios/turning-circle.toml"));
  spec.set_duration(duration_s);
  return spec;
}

TEST(CampaignNmea, EveryAntennaRoundTripsAgainstLogCsv) {
  const VesselConfig vessel = load_vessel_config(source("data/vessels/gunnerus.toml"));
  const ScenarioSpec spec = short_turning_circle(30.0);
  EXPECT_EQ(spec.start_utc, "2014-08-27T10:00:00Z");  // the default: a Gunnerus trial day
  const ScenarioRun run = run_scenario(spec, vessel, 11);
  TempDir dir;
  write_scenario_run(run, dir.path());
  EXPECT_EQ(run.truth.start_utc, "2014-08-27T10:00:00Z");
  EXPECT_EQ(read_trial_truth(dir.path() / "truth.json").start_utc, "2014-08-27T10:00:00Z");

  const core::Log csv = io::read_csv_all(dir.path() / "log.csv");  // lat/lon in rad (SI)
  const double start_s = io::parse_utc_time_of_day(spec.start_utc);
  int antennas = 0;
  for (int k = 1; k <= 9; ++k) {
    const std::string name = "gnss" + std::to_string(k);
    if (!csv.has(name + ".lat")) continue;
    ++antennas;
    ASSERT_TRUE(fs::exists(dir.path() / (name + ".nmea"))) << name;
    const io::NmeaGnssLog nmea = io::read_nmea_gnss(dir.path() / (name + ".nmea"), name);
    EXPECT_EQ(nmea.date, "2014-08-27");
    EXPECT_EQ(nmea.skipped, 0u);
    const auto& lat = csv.values(name + ".lat");
    const auto& lon = csv.values(name + ".lon");
    const auto& height = csv.values(name + ".height");
    const auto& heading = csv.values("heading");
    std::size_t j = 0;
    double worst_h_m = 0.0, worst_v_m = 0.0, worst_t_s = 0.0, worst_heading_deg = 0.0;
    double last_heading = core::kMissing;
    for (std::size_t i = 0; i < csv.size(); ++i) {
      if (!core::is_missing(heading[i])) last_heading = heading[i];
      if (core::is_missing(lat[i])) continue;
      ASSERT_LT(j, nmea.log.size()) << name << ": fewer NMEA epochs than fixes in log.csv";
      // UTC time of day = start_utc + t.
      worst_t_s = std::max(worst_t_s, std::abs(nmea.log.time()[j] - (start_s + csv.time()[i])));
      worst_h_m = std::max(worst_h_m,
                           std::abs(nmea.log.values(name + ".lat")[j] - lat[i]) * kMetresPerRadian);
      worst_h_m = std::max(worst_h_m, std::abs(nmea.log.values(name + ".lon")[j] - lon[i]) *
                                          kMetresPerRadian * std::cos(lat[i]));
      worst_v_m = std::max(worst_v_m, std::abs(nmea.log.values(name + ".height")[j] - height[i]));
      const double hdt_deg = nmea.log.values("heading")[j] / kDeg;
      worst_heading_deg = std::max(worst_heading_deg,
                                   std::abs(std::remainder(hdt_deg - last_heading / kDeg, 360.0)));
      EXPECT_EQ(nmea.log.values(name + ".quality")[j], 4.0);
      EXPECT_TRUE(std::isnan(nmea.log.values(name + ".satellites")[j]));  // not simulated
      EXPECT_FALSE(std::isnan(nmea.log.values(name + ".sog")[j]));
      ++j;
    }
    EXPECT_EQ(j, nmea.log.size()) << name;
    EXPECT_GE(j, 29u) << name;  // 1 Hz over 30 s
    // Written precision: time to 1 ms (the log's times are whole milliseconds, so exact up to
    // double rounding), latitude/longitude to 1e-7 minute (≤ 0.093 mm after rounding),
    // altitude and separation to 1 mm each (≤ 0.5 mm after rounding; the separation 39.5 m
    // is exact), heading to 0.001° (≤ 0.0005°).
    EXPECT_LT(worst_t_s, 1e-6) << name;
    EXPECT_LT(worst_h_m, 0.1e-3) << name;
    EXPECT_LE(worst_v_m, 0.5e-3 + 1e-9) << name;
    EXPECT_LE(worst_heading_deg, 0.0005 + 1e-9) << name;
    // SOG from the antenna's track over ±1 s: near the truth's speed at the control origin
    // (the turning circle runs at about 3 m/s; the antenna's own speed differs by r × lever
    // arm, ≤ 0.05 rad/s × 15 m, plus 1 cm noise / 2 s).
    const auto& sog = nmea.log.values(name + ".sog");
    EXPECT_GT(sog[sog.size() / 2], 1.5) << name;
    EXPECT_LT(sog[sog.size() / 2], 5.0) << name;
  }
  EXPECT_EQ(antennas, 3);
}

TEST(CampaignNmea, SameSeedGivesByteIdenticalFiles) {
  const VesselConfig vessel = load_vessel_config(source("data/vessels/gunnerus.toml"));
  const ScenarioSpec spec = short_turning_circle(5.0);
  TempDir a, b;
  write_scenario_run(run_scenario(spec, vessel, 3), a.path());
  write_scenario_run(run_scenario(spec, vessel, 3), b.path());
  const std::string first = file_bytes(a.path() / "gnss1.nmea");
  EXPECT_FALSE(first.empty());
  EXPECT_EQ(first, file_bytes(b.path() / "gnss1.nmea"));
  EXPECT_EQ(first.substr(0, 7), "$GNGGA,");
  // No temporary files are left behind.
  for (const auto& entry : fs::directory_iterator(a.path())) {
    EXPECT_NE(entry.path().filename().string()[0], '.') << entry.path();
  }
}

TEST(CampaignNmea, StartJustBeforeMidnightRollsOverDateAndTime) {
  const VesselConfig vessel = load_vessel_config(source("data/vessels/gunnerus.toml"));
  ScenarioSpec spec = short_turning_circle(8.0);
  spec.start_utc = "2015-12-31T23:59:55.5Z";
  const ScenarioRun run = run_scenario(spec, vessel, 5);
  TempDir dir;
  write_scenario_run(run, dir.path());
  const std::string text = file_bytes(dir.path() / "gnss1.nmea");
  EXPECT_THAT(text, ::testing::HasSubstr(",311215,"));  // RMC dates before and after midnight
  EXPECT_THAT(text, ::testing::HasSubstr(",010116,"));
  const io::NmeaGnssLog nmea = io::read_nmea_gnss(dir.path() / "gnss1.nmea", "gnss1");
  EXPECT_EQ(nmea.date, "2015-12-31");
  EXPECT_GT(nmea.log.time().back(), 86400.0);  // time continues past midnight
  const auto& t = run.log.time();
  const auto& lat = run.log.values("gnss1.lat");
  for (std::size_t i = 0, j = 0; i < t.size(); ++i) {
    if (core::is_missing(lat[i])) continue;
    ASSERT_LT(j, nmea.log.size());
    EXPECT_NEAR(nmea.log.time()[j], 86395.5 + t[i], 1e-6);
    ++j;
  }
}

TEST(CampaignNmea, ScenarioFileStartUtcIsReadAndChecked) {
  TempDir dir;
  const auto write = [&](const std::string& name, const std::string& start) {
    const fs::path path = dir.path() / name;
    std::ofstream(path) << "name = \"t\"\nduration_s = 5\nstart_utc = \"" << start << "\"\n";
    return path;
  };
  EXPECT_EQ(load_scenario(write("ok.toml", "2020-02-29T06:30:00Z")).start_utc,
            "2020-02-29T06:30:00Z");
  for (const char* bad : {"06:30:00", "2019-02-29T06:30:00Z", "2014-08-27T25:00:00Z"}) {
    try {
      load_scenario(write("bad.toml", bad));
      ADD_FAILURE() << bad << " was accepted";
    } catch (const core::InputError& e) {
      EXPECT_THAT(e.what(), ::testing::HasSubstr("bad.toml (start_utc)")) << e.what();
      EXPECT_THAT(e.what(), ::testing::HasSubstr("YYYY-MM-DDTHH:MM:SS")) << e.what();
    }
  }
}

}  // namespace
}  // namespace dynpos::scenario
