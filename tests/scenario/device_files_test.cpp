// The virtual trial's device files (write_scenario_run → devices/), checked against the clean
// log.csv samples they were written from.
#include "dynpos/scenario/device_files.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "../io/io_test_util.hpp"
#include "../source_dir.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/scenario/campaign.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::scenario {
namespace {

namespace fs = std::filesystem;

using io::testing::TempDir;

fs::path source(const std::string& relative) { return fs::path(DYNPOS_SOURCE_DIR) / relative; }

std::string file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> out;
  std::string item;
  std::istringstream in(text);
  while (std::getline(in, item, sep)) out.push_back(item);
  if (!text.empty() && text.back() == sep) out.emplace_back();
  return out;
}

double number(const std::string& cell) {
  if (cell.empty()) return core::kMissing;
  double v = 0.0;
  std::from_chars(cell.data(), cell.data() + cell.size(), v);
  return v;
}

// 60 s of the surge step programme (which asks for device files), after its 600 s settling.
struct Trial {
  ScenarioRun run;
  TempDir dir;
  fs::path devices() const { return dir.path() / "devices"; }
};

// One trial shared by the tests of the suite (the simulation is the slow part).
class DeviceFiles : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    trial_ = new Trial{};
    const VesselConfig vessel = load_vessel_config(source("data/vessels/gunnerus.toml"));
    ScenarioSpec spec = load_scenario(source("data/scenarios/surge-steps-forward.toml"));
    spec.set_duration(60.0);
    trial_->run = run_scenario(spec, vessel, 5);
    write_scenario_run(trial_->run, trial_->dir.path());
  }
  static void TearDownTestSuite() {
    delete trial_;
    trial_ = nullptr;
  }
  static const Trial& trial() { return *trial_; }

 private:
  static Trial* trial_;
};
Trial* DeviceFiles::trial_ = nullptr;

TEST_F(DeviceFiles, TheScenarioAsksForThemAndEveryFileIsWritten) {
  const Trial& t = trial();
  ASSERT_TRUE(t.run.device_files);
  EXPECT_DOUBLE_EQ(t.run.device_files->feedback_rate_hz, 2.0);
  for (const char* f :
       {"gnss1.nmea", "gnss2.nmea", "gnss3.nmea", "mru.csv", "thrusters.csv", "orders.csv"}) {
    EXPECT_TRUE(fs::exists(t.devices() / f)) << f;
  }
}

TEST_F(DeviceFiles, NmeaCaptureIsStampedAndCutMidSentence) {
  const Trial& t = trial();
  const std::string capture = file_bytes(t.devices() / "gnss1.nmea");
  const std::vector<std::string> clean = split(file_bytes(t.dir.path() / "gnss1.nmea"), '\n');
  std::vector<std::string> lines = split(capture, '\n');
  ASSERT_EQ(lines.size(), clean.size() - 1);  // clean ends in CR LF: one empty piece more
  EXPECT_NE(capture.back(), '\n');            // the last line stops mid-sentence
  EXPECT_EQ(lines.front().find('Z'), std::string::npos);  // the first starts after its stamp
  // Every whole line: the fix time as the logger's stamp, then the receiver's sentence.
  EXPECT_EQ(lines[1], "2014-08-27T10:00:00.000Z " + clean[1]);
  for (std::size_t i = 1; i + 1 < lines.size(); ++i) {
    ASSERT_GT(lines[i].size(), 25u);
    EXPECT_EQ(lines[i].substr(25), clean[i]) << "line " << i + 1;
    EXPECT_EQ(lines[i].substr(0, 11), "2014-08-27T");
  }
  // 60 s at 1 Hz: the last full fix is stamped 10:01:00.
  EXPECT_EQ(lines[lines.size() - 2].substr(0, 25).find("2014-08-27T10:01:00.000Z"), 0u);
  EXPECT_EQ(clean.back(), "");
  const std::string& cut = lines.back();
  EXPECT_LT(cut.size(), 25 + clean[clean.size() - 2].size());
}

TEST_F(DeviceFiles, MruFileHoldsTheLoggedSamplesAtTheirRate) {
  const Trial& t = trial();
  const core::Log& log = t.run.log;
  const std::vector<std::string> lines = split(file_bytes(t.devices() / "mru.csv"), '\n');
  ASSERT_GE(lines.size(), 3u);
  EXPECT_EQ(lines[0].substr(0, 18), "Time,Roll [deg],Pi");
  std::size_t row = 1;
  for (std::size_t i = 0; i < log.size(); ++i) {
    if (core::is_missing(log.values("mru1.roll")[i])) continue;
    ASSERT_LT(row, lines.size());
    const std::vector<std::string> cells = split(lines[row++], ',');
    ASSERT_EQ(cells.size(), 9u);
    EXPECT_EQ(number(cells[1]), log.values("mru1.roll")[i]);  // shortest round trip: exact
    EXPECT_EQ(number(cells[8]), log.values("mru1.az")[i]);
  }
  EXPECT_EQ(split(lines[1], ',')[0], "2014-08-27 10:00:00.000+00:00");
  EXPECT_EQ(row + 1, lines.size());  // the file ends in a newline
}

TEST_F(DeviceFiles, ThrusterFeedbackAtItsOwnRateWithEpochMilliseconds) {
  const Trial& t = trial();
  const std::vector<std::string> lines = split(file_bytes(t.devices() / "thrusters.csv"), '\n');
  // 0 … 60 s at 2 Hz, a header and a final newline.
  ASSERT_EQ(lines.size(), 1u + 121u + 1u);
  const std::vector<std::string> header = split(lines[0], ',');
  EXPECT_EQ(header[0], "EpochMs");
  EXPECT_EQ(header[1], "port_rpm [rpm]");
  // 2014-08-27T10:00:00Z = 16 309 days after 1970-01-01, + 10 h.
  EXPECT_EQ(split(lines[1], ',')[0], "1409133600000");
  EXPECT_EQ(split(lines[2], ',')[0], "1409133600500");
  // At t = 30 s (a row of the 10 Hz log) the port rpm is the log's.
  const core::Log& log = t.run.log;
  const std::size_t i30 = 300;
  ASSERT_DOUBLE_EQ(log.time()[i30], 30.0);
  EXPECT_EQ(number(split(lines[61], ',')[1]), log.values("rpm.port")[i30]);
}

TEST_F(DeviceFiles, OrdersAreDitheredWithinTheirWiggle) {
  const Trial& t = trial();
  const core::Log& log = t.run.log;
  const std::vector<std::string> lines = split(file_bytes(t.devices() / "orders.csv"), '\n');
  const std::vector<std::string> header = split(lines[0], ',');
  ASSERT_GE(header.size(), 3u);
  EXPECT_EQ(header[0], "sec");
  EXPECT_EQ(header[1], "nsec");
  std::size_t rpm_col = 0;
  for (std::size_t k = 0; k < header.size(); ++k) {
    if (header[k] == "order_rpm_port [rpm]") rpm_col = k;
  }
  ASSERT_NE(rpm_col, 0u);
  double sum_abs = 0.0;
  std::size_t n = 0;
  for (std::size_t row = 1; row + 1 < lines.size(); ++row) {
    const std::vector<std::string> cells = split(lines[row], ',');
    const std::size_t i = (row - 1) * 5;  // 2 Hz rows of the 10 Hz log
    EXPECT_EQ(number(cells[0]) + number(cells[1]) * 1e-9, 1409133600.0 + log.time()[i]);
    const double dither = number(cells[rpm_col]) - log.values("command.rpm.port")[i];
    EXPECT_LE(std::abs(dither), 2.0 + 1e-9);  // order_wiggle_rpm = 2 in the scenario
    sum_abs += std::abs(dither);
    ++n;
  }
  // Uniform on ±2 rpm: mean |d| = 1 rpm, σ of the mean over 121 samples ≈ 0.05 rpm.
  EXPECT_NEAR(sum_abs / static_cast<double>(n), 1.0, 0.25);
}

TEST(DeviceFilesSeed, SameSeedSameFilesBitForBit) {
  const VesselConfig vessel = load_vessel_config(source("data/vessels/gunnerus.toml"));
  ScenarioSpec spec = load_scenario(source("data/scenarios/surge-steps-forward.toml"));
  spec.set_duration(20.0);
  TempDir a, b;
  write_scenario_run(run_scenario(spec, vessel, 9), a.path());
  write_scenario_run(run_scenario(spec, vessel, 9), b.path());
  for (const char* f : {"gnss1.nmea", "mru.csv", "thrusters.csv", "orders.csv"}) {
    EXPECT_EQ(file_bytes(a.path() / "devices" / f), file_bytes(b.path() / "devices" / f)) << f;
  }
}

TEST(DeviceFilesSpec, FeedbackRateMustDivideTheLogRate) {
  ScenarioSpec spec = load_scenario(source("data/scenarios/surge-steps-forward.toml"));
  spec.device_files->feedback_rate_hz = 3.0;
  try {
    spec.validate();
    FAIL() << "expected an InputError";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.where().column_name, "device_files.feedback_rate_hz");
    EXPECT_NE(std::string(e.what()).find("does not divide the log rate 10 Hz"), std::string::npos);
  }
}

}  // namespace
}  // namespace dynpos::scenario
