#include "dynpos/scenario/trial_truth.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "dynpos/core/error.hpp"

namespace dynpos::scenario {
namespace {

// A truth with every field set, every optional present and values that are not round in
// binary (so a reader that loses a bit shows).
TrialTruth full_truth() {
  TrialTruth t;
  t.seed = 18446744073709551557ull;  // above 2⁶³: an unsigned 64-bit seed survives
  t.scenario.name = "dp-test";
  t.scenario.description = "a test";
  t.scenario.duration_s = 900.0;
  t.scenario.dt_s = 0.01;
  t.scenario.log_rate_hz = 10.0;
  t.scenario.initial_heading_deg = 12.5;
  t.scenario.initial_surge_mps = 0.1;
  t.scenario.settle_s = 600.0;
  t.scenario.start_utc = "2014-08-27T10:00:00Z";
  t.scenario.rudder = {{10.0, 20.0, false}, {40.0, 0.0, true}};
  t.scenario.loads = {{300.0, 1e300, -2e4, 0.0, 0.0}, {0.0, 250.0, 0.0, 1.5e4, 3.0}};
  t.scenario.environment.current_speed_mps = 0.2;
  t.scenario.environment.wave_components = 80;
  t.vessel = {{"name", "Gunnerus"}, {"hull", {{"mass_kg", 4.5e5}}}};
  CommandTruth c;
  c.t_s = 10.0;
  c.surge_pct = 30.9;
  c.demand_surge_N = 1.0 / 3.0;
  c.rudder_stb_deg = -0.1;
  c.tau_unmet = {0.1, 0.2, 0.3};
  t.commands = {c};
  t.propeller_steps = {{10.0, "port", 0.0, 2.7, {0.55, 1.47}, {0.6, 1.49}}};
  RudderStepTruth with_nomoto{20.0, 0.0, 20.0, 3.1, {1.8, 1.0}, NomotoTruth{1, 2, 3, 0.1}};
  RudderStepTruth slow{30.0, 20.0, -20.0, 0.05, {2.0, 1.1}, std::nullopt};
  t.rudder_steps = {with_nomoto, slow};
  SetpointTruth hold{"hold", 0.0, 0.0, 0.0, 0.0, 100.0, 12.3};
  SetpointTruth leg{"ahead", 100.0, 50.0, 0.0, 0.0, std::nullopt, std::nullopt};
  t.setpoints = {hold, leg};
  t.hybrid = HybridTruth{hybrid::IntegralJumpParams{}, {300.1, 302.2}};
  t.lever_arms = {{"gnss1", {0.1, 0.2, -10.0}}, {"mru1", {1.0 / 3.0, 0.0, 1.0}}};
  t.mru_acceleration = sensors::AccelerationConvention::kSpecificForce;
  t.time_constants = {NomotoTruth{5, 6, 7, 4}, NomotoTruth{2.5, 3, 4, 1.5}, {1.8, 1.0}};
  t.allocation_unmet_max = {0.0, 1e-9, 2.0};
  t.start_utc = "2014-08-27T10:00:00Z";
  return t;
}

std::filesystem::path temp_file(const std::string& name) {
  const auto* info = testing::UnitTest::GetInstance()->current_test_info();
  return std::filesystem::temp_directory_path() /
         ("dynpos-trial-truth-" + std::string(info->name()) + "-" + name);
}

TEST(TrialTruth, DocumentHasTheKeysOfTruthJson) {
  const nlohmann::json j = to_json(full_truth());
  std::vector<std::string> keys;
  for (const auto& [key, value] : j.items()) keys.push_back(key);
  // nlohmann::json orders object keys, so the file lists them sorted.
  EXPECT_THAT(keys, testing::ElementsAre("allocation_unmet_max", "commands", "hybrid", "lever_arms",
                                         "mru_acceleration", "propeller_steps", "rudder_steps",
                                         "scenario", "seed", "setpoints", "start_utc",
                                         "time_constants", "units", "vessel"));
  EXPECT_EQ(j["units"], "SI unless a key names its unit");
  EXPECT_EQ(j["mru_acceleration"], "specific-force");
  EXPECT_EQ(j["hybrid"]["rule"], "practical (5.64)-(5.67), b_hat += Lambda R(psi) x2");
  EXPECT_EQ(j["lever_arms"]["gnss1"], nlohmann::json({0.1, 0.2, -10.0}));
  EXPECT_EQ(j["commands"][0]["tau_unmet"], nlohmann::json({0.1, 0.2, 0.3}));
  EXPECT_EQ(j["propeller_steps"][0]["shaft_speed"]["T_s"], 0.55);
  EXPECT_EQ(j["time_constants"]["nomoto_3kn"]["Tr_s"], 4.0);
  EXPECT_EQ(j["time_constants"]["rudder_0_to_20deg"]["delay_s"], 1.0);
  // Optional values: present when set, absent otherwise; "never" and "release" are null.
  EXPECT_TRUE(j["rudder_steps"][0].contains("nomoto"));
  EXPECT_FALSE(j["rudder_steps"][1].contains("nomoto"));
  EXPECT_EQ(j["setpoints"][0]["t_reached_s"], 12.3);
  EXPECT_FALSE(j["setpoints"][1].contains("t_end_s"));
  EXPECT_FALSE(j["setpoints"][1].contains("t_reached_s"));
  EXPECT_TRUE(j["scenario"]["loads"][0]["t_off_s"].is_null());
  EXPECT_EQ(j["scenario"]["loads"][1]["t_off_s"], 250.0);
  EXPECT_TRUE(j["scenario"]["rudder"][1]["angle_deg"].is_null());
  EXPECT_EQ(j["scenario"]["environment"]["wave_components"], 80);
}

TEST(TrialTruth, WithoutHybridOrSetpointsTheListsAreEmptyAndHybridIsAbsent) {
  const nlohmann::json j = to_json(TrialTruth{});
  EXPECT_FALSE(j.contains("hybrid"));
  EXPECT_EQ(j["setpoints"], nlohmann::json::array());
  EXPECT_EQ(j["commands"], nlohmann::json::array());
  EXPECT_EQ(j["lever_arms"], nlohmann::json::object());
}

TEST(TrialTruth, ReadBackGivesTheSameDocumentToTheBit) {
  const TrialTruth truth = full_truth();
  const nlohmann::json j = to_json(truth);
  const TrialTruth back = from_json(j);
  EXPECT_EQ(to_json(back).dump(), j.dump());
  EXPECT_EQ(back.seed, truth.seed);
  EXPECT_EQ(back.commands[0].demand_surge_N, 1.0 / 3.0);
  EXPECT_EQ(back.lever_arms.at("mru1"), truth.lever_arms.at("mru1"));
  EXPECT_EQ(back.scenario.loads[0].t_off_s, 1e300);
  EXPECT_TRUE(back.scenario.rudder[1].release);
  ASSERT_TRUE(back.hybrid.has_value());
  EXPECT_EQ(back.hybrid->params.lambda, hybrid::IntegralJumpParams{}.lambda);
  EXPECT_EQ(back.hybrid->jump_times_s, truth.hybrid->jump_times_s);
  EXPECT_EQ(back.mru_acceleration, sensors::AccelerationConvention::kSpecificForce);
  ASSERT_TRUE(back.rudder_steps[0].nomoto.has_value());
  EXPECT_EQ(back.rudder_steps[0].nomoto->Tr_s, 0.1);
  EXPECT_FALSE(back.rudder_steps[1].nomoto.has_value());
  EXPECT_EQ(back.setpoints[0].t_end_s, 100.0);
}

TEST(TrialTruth, FileRoundTripsThroughWriteAndRead) {
  const std::filesystem::path path = temp_file("truth.json");
  write_trial_truth(full_truth(), path);
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  // The file is the pretty-printed document with a final newline.
  EXPECT_EQ(text.str(), to_json(full_truth()).dump(2) + "\n");
  EXPECT_EQ(to_json(read_trial_truth(path)).dump(), to_json(full_truth()).dump());
  std::filesystem::remove(path);
}

// A truth file of more than 64 MiB (a JSON document of a few kB) is refused by its size.
TEST(TrialTruth, AFileOfMoreThan64MiBIsRefused) {
  const std::filesystem::path path = temp_file("big_truth.json");
  std::ofstream(path) << "{}";
  std::filesystem::resize_file(path, (std::uintmax_t{64} << 20) + 1);
  EXPECT_THAT([&] { read_trial_truth(path); },
              testing::ThrowsMessage<core::InputError>(
                  testing::HasSubstr("big_truth.json: more than 64 MiB")));
  std::filesystem::remove(path);
}

TEST(TrialTruth, AFailureReadsBackWithItsRecoveryOrWithoutOne) {
  TrialTruth t = full_truth();
  FailureTruth f;
  f.time_s = 600.0;
  f.unit = "stb+tunnel";
  f.units = {"stb", "tunnel"};
  f.footprint_m = 0.93;
  f.peak_excursion_m = 90.4;
  f.time_to_peak_s = 298.7;
  f.peak_heading_deg = 82.9;
  t.failure = f;  // never back within the footprint
  nlohmann::json j = nlohmann::json::parse(to_json(t).dump());
  EXPECT_TRUE(j["failure"]["recovery_s"].is_null());
  TrialTruth back = from_json(j);
  ASSERT_TRUE(back.failure.has_value());
  EXPECT_FALSE(back.failure->recovery_s.has_value());
  EXPECT_EQ(back.failure->units, f.units);
  EXPECT_EQ(back.failure->time_to_peak_s, 298.7);
  t.failure->recovery_s = 162.0;
  back = from_json(nlohmann::json::parse(to_json(t).dump()));
  ASSERT_TRUE(back.failure.has_value());
  EXPECT_EQ(back.failure->recovery_s, 162.0);
}

TEST(TrialTruth, MissingNumberIsNullAndReadsAsNaN) {
  TrialTruth t = full_truth();
  t.rudder_steps[0].servo.time_constant = std::numeric_limits<double>::quiet_NaN();
  const nlohmann::json j = nlohmann::json::parse(to_json(t).dump());
  EXPECT_TRUE(j["rudder_steps"][0]["servo"]["T_s"].is_null());
  EXPECT_TRUE(std::isnan(from_json(j).rudder_steps[0].servo.time_constant));
}

TEST(TrialTruth, BadValueNamesFileAndKey) {
  nlohmann::json j = to_json(full_truth());
  j["commands"][0].erase("t_s");
  EXPECT_THAT([&] { from_json(j, "run/truth.json"); },
              testing::ThrowsMessage<core::InputError>(
                  testing::ContainsRegex("run/truth.json.*commands\\[0\\]\\.t_s.*missing")));
  j = to_json(full_truth());
  j["lever_arms"]["gnss1"] = {1.0, 2.0};
  EXPECT_THAT([&] { from_json(j, "t.json"); },
              testing::ThrowsMessage<core::InputError>(
                  testing::ContainsRegex("t.json.*lever_arms\\.gnss1.*3 numbers")));
  j = to_json(full_truth());
  j["scenario"]["environment"]["hs_m"] = "calm";
  EXPECT_THAT([&] { from_json(j, "t.json"); },
              testing::ThrowsMessage<core::InputError>(
                  testing::ContainsRegex("scenario\\.environment\\.hs_m.*not a number")));
  j = to_json(full_truth());
  j["mru_acceleration"] = "gravity";
  EXPECT_THAT([&] { from_json(j, "t.json"); },
              testing::ThrowsMessage<core::InputError>(testing::ContainsRegex("mru_acceleration")));
  j = to_json(full_truth());
  j["seed"] = -1;
  EXPECT_THAT([&] { from_json(j, "t.json"); },
              testing::ThrowsMessage<core::InputError>(testing::ContainsRegex("seed.*negative")));
}

TEST(TrialTruth, UnreadableFileNamesTheFile) {
  const std::filesystem::path path = temp_file("broken.json");
  std::ofstream(path) << "{\"seed\": 1,";
  EXPECT_THAT([&] { read_trial_truth(path); },
              testing::ThrowsMessage<core::InputError>(
                  testing::ContainsRegex("broken.json.*not valid JSON")));
  std::filesystem::remove(path);
  EXPECT_THAT(
      [&] { read_trial_truth(path); },
      testing::ThrowsMessage<core::InputError>(testing::ContainsRegex("broken.json.*cannot open")));
}

}  // namespace
}  // namespace dynpos::scenario
