// Runs of the virtual trial on a [[thruster]] layout: the shipped azimuth vessels in pure DP,
// the DP 4-corner and joystick steps, judged from their logs.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <string>

#include "../source_dir.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/model/thruster_unit.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/scenario/vessel_plant.hpp"

namespace dynpos::scenario {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

VesselConfig shipped(const char* stem) {
  return load_vessel_config(std::filesystem::path(DYNPOS_SOURCE_DIR) / "data" / "vessels" /
                            (std::string(stem) + ".toml"));
}

ScenarioSpec scenario(const char* stem, double duration_s) {
  ScenarioSpec s = load_scenario(std::filesystem::path(DYNPOS_SOURCE_DIR) / "data" / "scenarios" /
                                 (std::string(stem) + ".toml"));
  s.set_duration(duration_s);
  s.device_files.reset();
  return s;
}

// The largest slew rate [deg/s] of an azimuth's true direction between log rows.
double max_slew_deg_s(const core::Log& truth, const std::string& unit) {
  const auto& t = truth.time();
  const auto& a = truth.values("azimuth." + unit);
  double rate = 0.0;
  for (std::size_t k = 1; k < t.size(); ++k) {
    const double turn = std::remainder(a[k] - a[k - 1], 2.0 * std::numbers::pi) * kDeg;
    rate = std::max(rate, std::abs(turn) / (t[k] - t[k - 1]));
  }
  return rate;
}

// Rows of `values` [deg] strictly inside a forbidden sector (its edges allowed, 0.01°).
int rows_in_forbidden(const std::vector<double>& values_deg,
                      const std::vector<model::AngleSector>& forbidden) {
  int n = 0;
  for (const double v : values_deg) {
    if (core::is_missing(v)) continue;
    bool inside = false;  // inside the sector shrunk by the tolerance at both ends
    for (const model::AngleSector& s : forbidden) {
      inside |= model::in_forbidden_sector(v / kDeg, {{s.from_deg + 0.01, s.to_deg - 0.01}}, 0.0);
    }
    n += inside ? 1 : 0;
  }
  return n;
}

TEST(LayoutRun, TheLogNamesEachUnitsColumns) {
  const VesselConfig vessel = shipped("osv-80m");
  const ScenarioRun run = run_scenario(scenario("pure-dp", 60.0), vessel, 1);
  for (const model::ThrusterUnit& u : vessel.thrusters) {
    for (const char* kind : {"rpm.", "thrust.", "power.", "command.rpm.", "command.thrust."}) {
      EXPECT_TRUE(run.log.has(kind + u.name)) << kind << u.name;
    }
    for (const char* kind : {"rpm.", "thrust.", "power."}) {
      EXPECT_TRUE(run.truth_log.has(kind + u.name)) << kind << u.name;
    }
    const bool azimuth = u.type == model::UnitType::kAzimuth;
    EXPECT_EQ(run.log.has("azimuth." + u.name), azimuth) << u.name;
    EXPECT_EQ(run.log.has("command.azimuth." + u.name), azimuth) << u.name;
    EXPECT_EQ(run.truth_log.has("azimuth." + u.name), azimuth) << u.name;
  }
  // The model's own actuators are not in the log of a layout.
  EXPECT_FALSE(run.log.has("rpm.port"));
  EXPECT_FALSE(run.truth_log.has("rudder.stb"));
  // The units as run, with the drive each got, are in truth.json's vessel.
  ASSERT_TRUE(run.truth.vessel.contains("thruster"));
  EXPECT_EQ(run.truth.vessel["thruster"].size(), vessel.thrusters.size());
  EXPECT_GT(run.truth.vessel["thruster"][0]["time_constant_s"].get<double>(), 0.0);
}

TEST(LayoutRun, AzimuthsHoldTheirSlewRateAndStayOutOfTheirForbiddenSectors) {
  // Pure DP with its heading changes (0, 90, 45°) turns the main azimuths through half a circle,
  // past their forbidden sectors.
  for (const char* stem : {"gunnerus-2015", "osv-80m"}) {
    const VesselConfig vessel = shipped(stem);
    const ScenarioRun run = run_scenario(scenario("pure-dp", 1000.0), vessel, 3);
    for (const model::ThrusterUnit& u : vessel.thrusters) {
      if (u.type != model::UnitType::kAzimuth) continue;
      SCOPED_TRACE(std::string(stem) + " " + u.name);
      // The true direction at 10 Hz: at most the rate (a row apart, 1e-9 for round-off).
      EXPECT_LE(max_slew_deg_s(run.truth_log, u.name), u.rate_deg_per_s * (1.0 + 1e-9));
      std::vector<double> truth_deg = run.truth_log.values("azimuth." + u.name);
      for (double& v : truth_deg) v *= kDeg;
      EXPECT_EQ(rows_in_forbidden(truth_deg, u.forbidden_deg), 0);
      EXPECT_EQ(rows_in_forbidden(run.log.values("command.azimuth." + u.name), u.forbidden_deg), 0);
    }
  }
}

TEST(LayoutRun, TheSameSeedGivesTheSameLogBitForBit) {
  const VesselConfig vessel = shipped("gunnerus-2015");
  const ScenarioSpec spec = scenario("four-corner", 200.0);
  const ScenarioRun a = run_scenario(spec, vessel, 7);
  const ScenarioRun b = run_scenario(spec, vessel, 7);
  ASSERT_EQ(a.log.size(), b.log.size());
  for (std::size_t c = 0; c < a.log.channels().size(); ++c) {
    const auto& x = a.log.channels()[c].values;
    const auto& y = b.log.channels()[c].values;
    for (std::size_t k = 0; k < x.size(); ++k) {
      ASSERT_TRUE(std::memcmp(&x[k], &y[k], sizeof(double)) == 0) << a.log.channels()[c].name;
    }
  }
}

TEST(LayoutRun, TheFourCornerLegsAreSailed) {
  // The DP 4-corner's setpoints, each taken up when the last is reached: all four legs are
  // reached within the run on both shipped azimuth vessels.
  for (const char* stem : {"gunnerus-2015", "osv-80m"}) {
    const ScenarioRun run = run_scenario(scenario("four-corner", 900.0), shipped(stem), 1);
    SCOPED_TRACE(stem);
    ASSERT_GE(run.truth.setpoints.size(), 4u);
    for (const SetpointTruth& leg : run.truth.setpoints) {
      EXPECT_TRUE(leg.t_reached_s.has_value()) << leg.name;
    }
  }
}

TEST(LayoutRun, ASurgeStepMovesTheVesselAhead) {
  // A joystick surge step with auto heading: the speed rises with the lever, the heading holds
  // and every unit's thrust follows its order (the last row's feedback within 2 % of the
  // unit's rating of its order).
  const VesselConfig vessel = shipped("osv-80m");
  ScenarioSpec spec = scenario("surge-steps-forward", 300.0);
  spec.settle_s = 0.0;
  spec.heading_hold = true;
  spec.joystick = {{10.0, 60.0, 0.0, 0.0}};
  const ScenarioRun run = run_scenario(spec, vessel, 1);
  const auto& u = run.truth_log.values("u");
  EXPECT_GT(u.back(), 1.0);
  for (const double h : run.truth_log.values("heading")) {
    EXPECT_LT(std::abs(std::remainder(h, 2.0 * std::numbers::pi)) * kDeg, 3.0);
  }
  for (const model::ThrusterUnit& unit : vessel.thrusters) {
    const double ordered = run.log.values("command.thrust." + unit.name).back() * 1e3;
    const double got = run.truth_log.values("thrust." + unit.name).back();
    EXPECT_NEAR(got, ordered, 0.02 * unit.max_thrust_N) << unit.name;
  }
}

TEST(LayoutRun, ALostUnitMakesNoThrustAndTheOthersHoldInABeamSea) {
  // The supply vessel without its port main azimuth, DP number 2 weather on the beam: the
  // starboard main sits at the edge of its forbidden sector (75°) and the optimum's surge
  // changes sign; it once swung round to the sector's other edge again and again and the
  // vessel drifted 290 m in 900 s. Held within 1 m after the first 300 s.
  VesselConfig vessel = shipped("osv-80m");
  vessel.thruster_capacity.assign(vessel.thrusters.size(), 1.0);
  vessel.thruster_capacity[3] = 0.0;  // main_port
  ScenarioSpec spec = scenario("pure-dp", 900.0);
  spec.setpoints.resize(1);
  spec.environment = {0.5, 270.0, 3.4, 90.0, 0.4, 4.5, 90.0, 60};
  const ScenarioRun run = run_scenario(spec, vessel, 2);
  double largest = 0.0;
  for (const double f : run.truth_log.values("thrust.main_port")) largest = std::max(largest, f);
  EXPECT_EQ(largest, 0.0);
  const auto& t = run.truth_log.time();
  const auto& n = run.truth_log.values("north");
  const auto& e = run.truth_log.values("east");
  for (std::size_t k = 0; k < n.size(); ++k) {
    if (t[k] >= 300.0) {
      EXPECT_LT(std::hypot(n[k], e[k]), 1.0) << t[k];
    }
  }
}

TEST(LayoutRun, ManualRudderStepsAreRefusedOnALayout) {
  const VesselConfig vessel = shipped("gunnerus-2015");
  const ScenarioSpec spec = scenario("yaw-steps", 100.0);
  try {
    (void)run_scenario(spec, vessel, 1);
    FAIL() << "a layout ran the model's rudder steps";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("steps the model's two rudders"), std::string::npos)
        << e.what();
  }
  VesselConfig bad = vessel;
  bad.thruster_capacity = {1.0};
  EXPECT_THROW(run_scenario(scenario("pure-dp", 10.0), bad, 1), core::InputError);
}

}  // namespace
}  // namespace dynpos::scenario
