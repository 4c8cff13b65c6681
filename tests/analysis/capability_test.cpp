// `capability` as a request → report: the worst case over the single failures, DNV's notation,
// the JSON document and the rose, level 2 with a site's environment, and the options checked.

#include "dynpos/analysis/capability.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "../source_dir.hpp"
#include "input_error_capture.hpp"

namespace dynpos::analysis {
namespace {

using testing::option_key_of;

CapabilityRequest gunnerus(int level = 1) {
  CapabilityRequest q;
  q.level = level;
  q.vessel = std::filesystem::path(DYNPOS_SOURCE_DIR) / "data" / "vessels" / "gunnerus.toml";
  q.direction_step = 30.0;
  return q;
}

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("dynpos_capability_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir / name;
}

TEST(Capability, TheWorstCaseIsTheSmallestSingleFailurePerDirection) {
  const CapabilityReport r = run_capability(gunnerus());
  ASSERT_TRUE(r.worst.has_value());
  ASSERT_EQ(r.failures.size(), 5u);
  ASSERT_EQ(r.intact.points.size(), 12u);
  for (std::size_t i = 0; i < r.intact.points.size(); ++i) {
    const auto& w = r.worst->points[i];
    EXPECT_LE(w.max_wind_mps, r.intact.points[i].max_wind_mps);
    for (const auto& c : r.failures) {
      EXPECT_LE(w.max_wind_mps, c.points[i].max_wind_mps);
      if (c.failure == w.failure) {
        EXPECT_EQ(w.max_wind_mps, c.points[i].max_wind_mps);
      }
    }
  }
  const auto n = capability_notation(r);
  ASSERT_TRUE(n[0] && n[1] && n[2] && n[3]);
  EXPECT_GE(*n[0], *n[1]);  // the bow sector is part of the whole circle
  EXPECT_LE(*n[2], *n[0]);
}

TEST(Capability, TheJsonHoldsThePointsOfTheFailureAskedAndTheIntactRose) {
  CapabilityRequest q = gunnerus();
  q.failure = "tunnel";
  const nlohmann::json j = to_json(run_capability(q));
  EXPECT_EQ(j["level"], 1);
  EXPECT_EQ(j["failure"], "tunnel");
  EXPECT_EQ(j["points"], j["cases"]["tunnel"]);
  ASSERT_EQ(j["points"].size(), 12u);
  for (const auto& p : j["points"]) {
    for (const char* key : {"direction_deg", "dp_number", "max_wind_mps", "limiting"}) {
      EXPECT_TRUE(p.contains(key)) << key;
    }
    EXPECT_EQ(p["failure"], "tunnel");
  }
  int lowest = 99;  // C: the failure case's lowest number within ±30° of the bow
  for (const auto& p : j["points"]) {
    const double d = p["direction_deg"];
    if (d <= 30.0 || d >= 330.0) lowest = std::min(lowest, p["dp_number"].get<int>());
  }
  EXPECT_EQ(j["notation"][2], lowest);
  q.failure = "none";
  const nlohmann::json intact = to_json(run_capability(q));
  EXPECT_EQ(intact["points"], intact["intact"]);
  EXPECT_TRUE(intact["cases"].empty());
  EXPECT_EQ(intact["notation"][2], nullptr);  // C and D only with a failure case
}

TEST(Capability, TheRoseHasBothPanelsAndBothCases) {
  const CapabilityReport r = run_capability(gunnerus());
  const auto svg = scratch("rose.svg");
  write_rose(r, svg);
  std::ifstream in(svg);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("DP capability number"), std::string::npos);
  EXPECT_NE(text.find("Limiting wind speed"), std::string::npos);
  EXPECT_NE(text.find("worst single failure"), std::string::npos);
  EXPECT_NE(to_text(r).find("DP capability-L1("), std::string::npos);
}

TEST(Capability, Level2TakesASiteAndFixedValues) {
  const auto site = scratch("site.toml");
  std::ofstream(site) << "[[environment]]\nwind_mps = 0\nhs_m = 0\ntp_s = 0\ncurrent_mps = 0\n"
                         "[[environment]]\nwind_mps = 10\nhs_m = 1\ntp_s = 6\ncurrent_mps = 0.2\n"
                         "[[environment]]\nwind_mps = 20\nhs_m = 2\ntp_s = 7\ncurrent_mps = 0.2\n";
  CapabilityRequest q = gunnerus(2);
  q.site = site;
  q.failure = "none";
  const CapabilityReport r = run_capability(q);
  EXPECT_EQ(r.environment, site.string());
  // A milder site than the DNV table (0.2 m/s current instead of 0.75): more wind held.
  CapabilityRequest dnv = gunnerus(2);
  dnv.failure = "none";
  const CapabilityReport d = run_capability(dnv);
  for (std::size_t i = 0; i < r.intact.points.size(); ++i) {
    const auto& site_point = r.intact.points[i];  // a floor where it holds the site's last row
    EXPECT_TRUE(site_point.beyond_table ||
                site_point.max_wind_mps >= d.intact.points[i].max_wind_mps - 1e-9);
  }
  q.site.clear();
  q.current = 0.0;
  q.hs = 0.0;
  EXPECT_NE(run_capability(q).environment.find("fixed Hs 0 m current 0 m/s"), std::string::npos);
  std::ofstream(site) << "[[environment]]\nwind_mps = 0\nhs = 1\n";
  q = gunnerus(2);
  q.site = site;
  const core::InputError e = testing::input_error([&] { run_capability(q); });
  EXPECT_EQ(e.where().file, site.string());
}

TEST(CapabilityRequest, BadOptionsAreNamed) {
  const auto key = [](auto change) {
    CapabilityRequest q = gunnerus();
    change(q);
    return option_key_of([&] { q.validate(); });
  };
  EXPECT_EQ(key([](CapabilityRequest& q) { q.level = 4; }), "level");
  EXPECT_EQ(key([](CapabilityRequest& q) { q.hs = 1.0; }), "site/hs/tp/current");
  EXPECT_EQ(key([](CapabilityRequest& q) { q.direction_step = 7.0; }), "direction_step");
  EXPECT_EQ(key([](CapabilityRequest& q) { q.vessel = "no_such.toml"; }), "vessel");
  EXPECT_EQ(key([](CapabilityRequest& q) {
              q.level = 3;
              q.footprint = -1.0;
            }),
            "footprint");
  EXPECT_EQ(key([](CapabilityRequest& q) {
              q.level = 2;
              q.tp = 0.0;
            }),
            "tp");
  EXPECT_EQ(key([](CapabilityRequest& q) {
              q.failure = "none";
              q.worst_of = {"port"};
            }),
            "worst_of");
  EXPECT_EQ(key([](CapabilityRequest&) {}), "no error");
  // The failure cases are the vessel's: they are judged once it is read, before any rose.
  CapabilityRequest q = gunnerus();
  q.failure = "bow";
  EXPECT_EQ(option_key_of([&] { run_capability(q); }), "failure");
  q = gunnerus();
  q.worst_of = {"port", "bow"};
  EXPECT_EQ(option_key_of([&] { run_capability(q); }), "worst_of");
}

TEST(Capability, TheWorstCaseCanBeTakenOverSomeFailures) {
  CapabilityRequest q = gunnerus();
  q.worst_of = {"tunnel", "port"};
  const CapabilityReport some = run_capability(q);
  ASSERT_EQ(some.failures.size(), 2u);
  EXPECT_EQ(some.failures[0].failure, "tunnel");
  EXPECT_EQ(some.failures[1].failure, "port");
  const CapabilityReport all = run_capability(gunnerus());
  for (std::size_t i = 0; i < some.worst->points.size(); ++i) {  // fewer cases: no worse
    EXPECT_GE(some.worst->points[i].max_wind_mps, all.worst->points[i].max_wind_mps);
  }
}

TEST(Capability, WriteOutputsWritesTheRoseThenTheJson) {
  const CapabilityReport r = run_capability(gunnerus());
  const std::filesystem::path dir = scratch("outputs");
  const Outputs outputs{(scratch("r.json")).string(), dir};
  const Written written = write_outputs(r, outputs);
  ASSERT_EQ(written.size(), 2u);
  EXPECT_EQ(written[0], dir / "rose.svg");
  EXPECT_EQ(written[1], scratch("r.json"));
  EXPECT_TRUE(std::filesystem::is_regular_file(written[0]));
  std::ifstream in(written[1]);
  EXPECT_EQ(nlohmann::json::parse(in), to_json(r));
  EXPECT_TRUE(write_outputs(r, Outputs{}).empty());
}

}  // namespace
}  // namespace dynpos::analysis
