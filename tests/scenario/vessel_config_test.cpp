#include "dynpos/scenario/vessel_config.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "dynpos/core/error.hpp"
#include "dynpos/scenario/scenario_spec.hpp"

namespace dynpos::scenario {
namespace {

const std::filesystem::path kData = std::filesystem::path(DYNPOS_SOURCE_DIR) / "data";

std::filesystem::path write_temp(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path;
}

TEST(VesselConfig, GunnerusFileStatesTheBuiltInValues) {
  const VesselConfig file = load_vessel_config(kData / "vessels" / "gunnerus.toml");
  // The file lists every parameter; it must agree with the documented defaults exactly.
  EXPECT_EQ(file.to_json().dump(), VesselConfig{}.to_json().dump());
  EXPECT_EQ(file.name, "Gunnerus");
}

TEST(VesselConfig, OutOfRangeValueNamesFileLineAndKey) {
  const auto path = write_temp("dynpos_bad_vessel.toml", "name = \"x\"\n\n[hull]\nmass_kg = -4\n");
  EXPECT_THAT([&] { load_vessel_config(path); },
              testing::ThrowsMessage<core::InputError>(
                  testing::ContainsRegex("dynpos_bad_vessel.toml:4:.*hull.mass_kg.*out of range")));
}

TEST(VesselConfig, UnknownKeyIsRejected) {
  const auto path = write_temp("dynpos_typo_vessel.toml", "[propeller]\ndiamter_m = 2.0\n");
  EXPECT_THAT([&] { load_vessel_config(path); },
              testing::ThrowsMessage<core::InputError>(
                  testing::ContainsRegex("typo_vessel.toml:2:.*propeller.diamter_m.*unknown key")));
}

TEST(VesselConfig, AngleKeysAreDegreesInTheFile) {
  const auto path = write_temp("dynpos_rudder_vessel.toml", "[rudder]\nmax_angle_deg = 40\n");
  const VesselConfig v = load_vessel_config(path);
  EXPECT_NEAR(v.rudder.max_angle, 40.0 * M_PI / 180.0, 1e-15);
}

TEST(ScenarioSpec, EveryBuiltInScenarioLoads) {
  const auto names = list_scenarios(kData / "scenarios");
  ASSERT_GE(names.size(), 4u);
  for (const std::string& name : names) {
    const ScenarioSpec spec = load_scenario(kData / "scenarios" / (name + ".toml"));
    EXPECT_EQ(spec.name, name);
    EXPECT_TRUE(!spec.joystick.empty() || !spec.setpoints.empty()) << name;
  }
}

TEST(ScenarioSpec, JoystickTimesMustIncrease) {
  const auto path = write_temp("dynpos_bad_scenario.toml",
                               "name = \"x\"\nduration_s = 10\n[[joystick]]\nt_s = 5\n"
                               "[[joystick]]\nt_s = 4\n");
  EXPECT_THAT([&] { load_scenario(path); },
              testing::ThrowsMessage<core::InputError>(
                  testing::ContainsRegex("joystick\\[2\\].t_s.*not after")));
}

TEST(ScenarioSpec, UnknownScenarioListsTheAvailableOnes) {
  EXPECT_THAT([&] { resolve_scenario("nope", kData / "scenarios"); },
              testing::ThrowsMessage<core::InputError>(
                  testing::ContainsRegex("unknown scenario 'nope'.*surge-steps-forward")));
}

TEST(ScenarioSpec, LogPeriodMustBeAWholeNumberOfSteps) {
  ScenarioSpec s;
  s.name = "x";
  s.dt_s = 0.01;
  s.log_rate_hz = 3.0;
  EXPECT_THROW(s.validate(), core::InputError);
}

TEST(ScenarioSpec, SettlingIsWholeSecondsAndJoystickOnly) {
  const auto bad = [](const std::string& name, const std::string& body) {
    return write_temp(name, "name = \"x\"\nduration_s = 10\n" + body);
  };
  EXPECT_THAT([&] { load_scenario(bad("dynpos_settle_frac.toml", "settle_s = 0.5\n")); },
              testing::ThrowsMessage<core::InputError>(
                  testing::ContainsRegex("settle_s.*whole number of seconds")));
  EXPECT_THAT([&] { load_scenario(bad("dynpos_settle_neg.toml", "settle_s = -1\n")); },
              testing::ThrowsMessage<core::InputError>(testing::ContainsRegex("settle_s")));
  EXPECT_THAT(
      [&] {
        load_scenario(bad("dynpos_settle_dp.toml",
                          "settle_s = 60\n[[setpoint]]\nt_s = 0\nnorth_m = 0\neast_m = 0\n"
                          "heading_deg = 0\n"));
      },
      testing::ThrowsMessage<core::InputError>(testing::ContainsRegex("settle_s.*joystick")));
  // dt = 0.7 s with a log period of 1.4 s and a 7 s run: the run and the log period are whole
  // steps, but 600 s is 857.14… steps, so the scenario's t = 0 would fall between two.
  EXPECT_THAT(
      [&] {
        load_scenario(write_temp("dynpos_settle_dt.toml",
                                 "name = \"x\"\nduration_s = 7\ndt_s = 0.7\n"
                                 "log_rate_hz = 0.7142857142857143\nsettle_s = 600\n"));
      },
      testing::ThrowsMessage<core::InputError>(
          testing::ContainsRegex("settle_s.*600 s is not a multiple of dt_s = 0.7 s")));
  EXPECT_EQ(load_scenario(bad("dynpos_settle_ok.toml", "settle_s = 600\n")).settle_s, 600.0);
}

TEST(ScenarioSpec, DurationIsWholeSteps) {
  // 10 s is 33.3… steps of 0.3 s: an InputError naming the key, not a simulator exception.
  const auto spec = [](const std::string& name, const std::string& dt) {
    return write_temp(name, "name = \"x\"\nduration_s = 10\ndt_s = " + dt + "\n");
  };
  EXPECT_THAT([&] { load_scenario(spec("dynpos_duration_dt.toml", "0.3")); },
              testing::ThrowsMessage<core::InputError>(
                  testing::ContainsRegex("duration_s.*10 s is not a multiple of dt_s = 0.3 s")));
  EXPECT_EQ(load_scenario(spec("dynpos_duration_ok.toml", "0.02")).duration_s, 10.0);
}

}  // namespace
}  // namespace dynpos::scenario
