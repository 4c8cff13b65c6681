#include "dynpos/analysis/simulate.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "../source_dir.hpp"
#include "dynpos/core/error.hpp"

namespace dynpos::analysis {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

const std::filesystem::path kShortScenario =
    std::filesystem::path(DYNPOS_SOURCE_DIR) / "tests" / "cli" / "short.toml";

SimulateRequest short_request(const std::filesystem::path& out_dir) {
  SimulateRequest r;
  r.scenario = kShortScenario.string();
  r.out_dir = out_dir;
  r.seed = 7;
  r.duration_s = 5.0;
  return r;
}

std::filesystem::path fresh_dir(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

TEST(SimulateRequest, OverridesMustBePositiveAndNameTheirOption) {
  SimulateRequest r = short_request("out");
  EXPECT_NO_THROW(r.validate());
  for (const double bad : {0.0, -5.0}) {
    r.duration_s = bad;
    try {
      r.validate();
      FAIL() << "duration " << bad << " was accepted";
    } catch (const core::InputError& e) {
      EXPECT_EQ(e.option(), "duration");
      EXPECT_THAT(e.problem(), HasSubstr("must be > 0 s"));
    }
  }
  r.duration_s.reset();
  r.log_rate_hz = 0.0;
  try {
    r.validate();
    FAIL() << "a log rate of 0 was accepted";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.option(), "log_rate");
  }
}

TEST(SimulateRequest, ScenarioAndOutputFolderAreNeededUnlessListing) {
  SimulateRequest r;
  r.out_dir = "out";
  EXPECT_THROW(
      {
        try {
          r.validate();
        } catch (const core::InputError& e) {
          EXPECT_THAT(e.what(), StartsWith("no scenario given"));
          throw;
        }
      },
      core::InputError);
  r.scenario = "yaw-steps";
  r.out_dir.clear();
  EXPECT_THROW(r.validate(), core::InputError);
  r.list = true;
  r.scenario.clear();
  EXPECT_NO_THROW(r.validate());
}

TEST(Simulate, ListShowsEveryBuiltInScenario) {
  SimulateRequest r;
  r.list = true;
  const SimulateReport report = run_simulate(r);
  const auto& list = std::get<std::vector<ScenarioListing>>(report.result);
  ASSERT_GE(list.size(), 7u);
  EXPECT_TRUE(std::any_of(list.begin(), list.end(),
                          [](const ScenarioListing& s) { return s.name == "dp-ice-load"; }));
  EXPECT_THAT(to_text(report), HasSubstr("surge-steps-forward      "));
}

TEST(Simulate, ShortRunWritesTheRunFolder) {
  const std::filesystem::path dir = fresh_dir("dynpos_simulate_test");
  const SimulateReport report = run_simulate(short_request(dir / "run"));
  const auto& run = std::get<SimulatedRun>(report.result);
  EXPECT_EQ(run.scenario, "short-steps");
  EXPECT_EQ(run.duration_s, 5.0);
  EXPECT_EQ(run.seed, 7u);
  EXPECT_EQ(run.rows, 51u);  // 5 s at 10 Hz, both ends
  EXPECT_GT(run.channels, 10u);
  for (const char* file : {"log.csv", "truth.csv", "truth.json", "gnss1.nmea"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / "run" / file)) << file;
  }
  EXPECT_THAT(to_text(report), StartsWith("simulated 'short-steps' (5 s, seed 7): 51 rows x " +
                                          std::to_string(run.channels) + " channels\nwrote "));
  std::filesystem::remove_all(dir);
}

TEST(Simulate, UnknownScenarioListsTheBuiltInOnes) {
  SimulateRequest r = short_request(fresh_dir("dynpos_simulate_unknown"));
  r.scenario = "no-such-test";
  try {
    run_simulate(r);
    FAIL() << "an unknown scenario ran";
  } catch (const core::InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("unknown scenario 'no-such-test'"));
    EXPECT_THAT(e.what(), HasSubstr("surge-steps-forward"));
  }
}

}  // namespace
}  // namespace dynpos::analysis
