#include "dynpos/scenario/vessel_config.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "../source_dir.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/model/sea_state.hpp"
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

// [[thruster]] units: each type with its keys, defaults scaled from the rated thrust, and the
// errors naming the file, line and key.
TEST(VesselConfig, ThrusterLayoutUnits) {
  const auto path =
      write_temp("dynpos_layout_vessel.toml",
                 "name = \"OSV\"\n"
                 "[[thruster]]\nname = \"bow1\"\ntype = \"tunnel\"\n"
                 "x_m = 35.0\ny_m = 0.0\nmax_thrust_N = 1.1e5\ngroup = \"bus A\"\n"
                 "[[thruster]]\nname = \"main_port\"\ntype = \"azimuth\"\n"
                 "x_m = -36.0\ny_m = -6.0\nmax_thrust_N = 3.5e5\n"
                 "forbidden_deg = [[60.0, 120.0]]\nrate_deg_per_s = 12\n"
                 "[[thruster]]\nname = \"main_stb\"\ntype = \"propeller_rudder\"\n"
                 "x_m = -36.0\ny_m = 6.0\nmax_thrust_N = 3.0e5\nrudder_x_m = -38.0\n");
  const VesselConfig v = load_vessel_config(path);
  ASSERT_EQ(v.thrusters.size(), 3u);
  EXPECT_EQ(v.thrusters[0].type, model::UnitType::kTunnel);
  EXPECT_DOUBLE_EQ(v.thrusters[0].max_reverse_thrust_N, 0.9 * 1.1e5);  // the stated default
  EXPECT_EQ(v.thrusters[0].group, "bus A");
  EXPECT_EQ(v.thrusters[1].forbidden_deg.size(), 1u);
  EXPECT_EQ(v.thrusters[1].rate_deg_per_s, 12.0);
  EXPECT_EQ(v.thrusters[1].max_reverse_thrust_N, 0.0);
  EXPECT_DOUBLE_EQ(v.thrusters[2].max_reverse_thrust_N, 3.0e5 * 5.8 / 8.13);
  EXPECT_EQ(v.thrusters[2].rudder_lift_per_thrust, 0.65);
  EXPECT_EQ(v.thrusters[2].rudder_x_m, -38.0);
  EXPECT_TRUE(VesselConfig{}.thrusters.empty());

  const auto error_of = [](const std::string& name, const std::string& text) {
    try {
      load_vessel_config(write_temp(name, text));
    } catch (const core::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string unit = "[[thruster]]\nname = \"a\"\ntype = \"azimuth\"\nx_m = 0\ny_m = 0\n";
  EXPECT_THAT(error_of("dynpos_t1.toml", unit + "max_thrust_N = 0\n"),
              testing::ContainsRegex("t1.toml:6:.*thruster\\[1\\].max_thrust_N.*out of range"));
  EXPECT_THAT(
      error_of("dynpos_t2.toml", unit + "max_thrust_N = 1e5\nforbidden_deg = [[10, 370]]\n"),
      testing::ContainsRegex("t2.toml:7:.*forbidden_deg.*leaves \\[0, 360\\)"));
  EXPECT_THAT(error_of("dynpos_t3.toml", unit + "max_thrust_N = 1e5\nrudder_x_m = 1\n"),
              testing::ContainsRegex("t3.toml:7:.*the azimuth unit has no rudder_x_m"));
  EXPECT_THAT(
      error_of("dynpos_t4.toml", unit + "max_thrust_N = 1e5\n" + unit + "max_thrust_N = 1e5\n"),
      testing::ContainsRegex("t4.toml:8:.*a second unit named 'a'"));
  EXPECT_THAT(error_of("dynpos_t5.toml", "[[thruster]]\nname = \"a\"\ntype = \"pod\"\n"),
              testing::ContainsRegex("t5.toml:3:.*unknown thruster type 'pod'"));
  EXPECT_THAT(error_of("dynpos_t6.toml",
                       unit + "max_thrust_N = 1e5\nforbidden_deg = [[0, 180], [180, 0]]\n"),
              testing::ContainsRegex("t6.toml:7:.*forbid every direction"));
  // A loss table: its angles increase, its factors are in [0, 1], and it is an azimuth's.
  EXPECT_THAT(
      error_of("dynpos_t7.toml", unit + "max_thrust_N = 1e5\nloss = [[90, 0.5], [80, 1.0]]\n"),
      testing::ContainsRegex("t7.toml:7:.*loss.*the angles must increase"));
  EXPECT_THAT(error_of("dynpos_t9.toml", unit + "max_thrust_N = 1e5\nloss = [[90, 1.5]]\n"),
              testing::ContainsRegex("t9.toml:7:.*loss.*factor 1.5 is not in \\[0, 1\\]"));
  EXPECT_THAT(error_of("dynpos_t10.toml",
                       "[[thruster]]\nname = \"t\"\ntype = \"tunnel\"\n"
                       "max_thrust_N = 1e5\nloss = [[90, 0.5]]\n"),
              testing::ContainsRegex("t10.toml:5:.*the tunnel unit has no loss"));
  EXPECT_THAT(error_of("dynpos_t11.toml", unit + "max_thrust_N = 1e5\nloss = [90, 0.5]\n"),
              testing::ContainsRegex("t11.toml:7:.*each point is a pair"));
  // The names of failure cases are not units' names: a unit "none" would vanish from them.
  for (const char* name : {"none", "worst", "group:A"}) {
    EXPECT_THAT(error_of("dynpos_t8.toml",
                         "[[thruster]]\nname = \"" + std::string(name) + "\"\ntype = \"tunnel\"\n"),
                testing::ContainsRegex("t8.toml:2:.*is a failure case's name"))
        << name;
  }
}

TEST(VesselConfig, AFolderOrAMissingFileIsNotTheBuiltInVessel) {
  const auto dir = std::filesystem::temp_directory_path();
  EXPECT_THAT([&] { load_vessel_config(dir); },
              testing::ThrowsMessage<core::InputError>(testing::HasSubstr("not a regular file")));
  EXPECT_THAT([&] { load_vessel_config(dir / "dynpos_no_such_vessel.toml"); },
              testing::ThrowsMessage<core::InputError>(
                  testing::ContainsRegex("no_such_vessel.toml: cannot open the file")));
}

// Vessel and scenario files are TOML of a few kB: more than 16 MiB is refused by its size.
TEST(VesselConfig, AFileOfMoreThan16MiBIsRefused) {
  const auto path = write_temp("dynpos_big_vessel.toml", "name = \"x\"\n");
  std::filesystem::resize_file(path, (std::uintmax_t{16} << 20) + 1);
  EXPECT_THAT([&] { load_vessel_config(path); },
              testing::ThrowsMessage<core::InputError>(
                  testing::ContainsRegex("big_vessel.toml: more than 16 MiB")));
  EXPECT_THAT([&] { load_scenario(path); },
              testing::ThrowsMessage<core::InputError>(
                  testing::ContainsRegex("big_vessel.toml: more than 16 MiB")));
  std::filesystem::remove(path);
}

TEST(VesselConfig, AnEmptyFileIsNotTheBuiltInVessel) {
  for (const char* text : {"", "\n# only a comment\n\n"}) {
    const auto path = write_temp("dynpos_empty_vessel.toml", text);
    EXPECT_THAT([&] { load_vessel_config(path); },
                testing::ThrowsMessage<core::InputError>(testing::ContainsRegex(
                    "dynpos_empty_vessel.toml: the vessel file has no key")));
  }
}

TEST(VesselConfig, AngleKeysAreDegreesInTheFile) {
  const auto path = write_temp("dynpos_rudder_vessel.toml", "[rudder]\nmax_angle_deg = 40\n");
  const VesselConfig v = load_vessel_config(path);
  EXPECT_NEAR(v.rudder.max_angle, 40.0 * M_PI / 180.0, 1e-15);
}

// docs/vessel-file.md lists the ranges of the code's tables: the text between the markers is
// vessel_param_tables_markdown(). After changing a table, paste the "expected" text of this
// test's failure between the markers.
TEST(VesselConfig, DocsListTheRangesTheCodeChecks) {
  std::ifstream in(std::filesystem::path(DYNPOS_SOURCE_DIR) / "docs" / "vessel-file.md");
  ASSERT_TRUE(in) << "docs/vessel-file.md is missing";
  const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string begin = "<!-- BEGIN generated by vessel_param_tables_markdown() -->\n";
  const std::string end = "<!-- END generated -->";
  const auto from = doc.find(begin);
  const auto to = doc.find(end);
  ASSERT_NE(from, std::string::npos);
  ASSERT_NE(to, std::string::npos);
  const std::string listed = doc.substr(from + begin.size(), to - from - begin.size());
  EXPECT_EQ(listed, vessel_param_tables_markdown() + "\n");
}

// One table per section: for every key, a value just outside its range (the bound itself for
// an open end) is rejected by validate() too, naming the section and key, as the reader names
// them; the defaults are inside every range.
TEST(VesselConfig, ValidationChecksEveryKeyAgainstTheFileRange) {
  VesselConfig defaults;
  EXPECT_NO_THROW(defaults.validate());
  std::size_t keys = 0;
  for (const core::ParamSection& s : vessel_param_sections(defaults)) {
    for (const core::ParamField& f : s.fields) {
      ++keys;
      const core::ParamRange& r = f.range;
      EXPECT_TRUE(r.contains_si(*f.value)) << s.name << "." << r.key << " default";
      for (const double outside : {r.lo_open ? r.lo : r.lo - std::max(1.0, std::abs(r.lo)),
                                   r.hi_open ? r.hi : r.hi + std::max(1.0, std::abs(r.hi))}) {
        VesselConfig v;
        for (const core::ParamSection& vs : vessel_param_sections(v)) {
          if (vs.name != s.name) continue;
          for (const core::ParamField& vf : vs.fields) {
            if (vf.range.key == r.key) *vf.value = outside * r.to_si;
          }
        }
        EXPECT_THAT([&] { v.validate(); },
                    testing::ThrowsMessage<core::InputError>(
                        testing::HasSubstr("(" + s.name + "." + r.key + "): value")))
            << outside;
      }
    }
  }
  EXPECT_GT(keys, 150u);
}

TEST(VesselConfig, OneRangeForFileAndModel) {
  // The tunnel's position was accepted in (-100, 100) m by the file and (-50, 50) m by the
  // model: one range now, checked where the file names the line.
  const auto path = write_temp("dynpos_tunnel_vessel.toml", "[tunnel]\nx_m = 60\n");
  EXPECT_THAT([&] { load_vessel_config(path); },
              testing::ThrowsMessage<core::InputError>(testing::ContainsRegex(
                  "tunnel_vessel.toml:2:[0-9]+ \\(tunnel.x_m\\): value 60 is out of range; "
                  "expected a number in \\(-50, 50\\)")));
  // The scenario's environment and the wave model share their ranges too.
  model::SeaStateParams sea;
  sea.hs_m = 9.0;
  EXPECT_THAT([&] { sea.validate(); },
              testing::ThrowsMessage<core::InputError>(testing::HasSubstr(
                  "(environment.hs_m): value 9 is out of range; expected a number in [0, 8]")));
}

TEST(VesselConfig, RulesBetweenKeysNameTheFile) {
  // y_rdot so large that the mass matrix is not positive definite: each key is in range.
  const auto path = write_temp("dynpos_mass_vessel.toml", "[hull]\ny_rdot_kgm = 9e9\n");
  EXPECT_THAT([&] { load_vessel_config(path); },
              testing::ThrowsMessage<core::InputError>(testing::StartsWith(
                  path.string() + ": HullParams.y_rdot_kgm must be small enough that M is "
                                  "positive definite; check the vessel file's values")));
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
