// Failures as they happen, GNSS dropouts and the observer in a scenario run: the scenario keys,
// their errors, the drive cut, the allocation's redistribution and the truth.

#include "dynpos/scenario/unit_failure.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "../source_dir.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/scenario/vessel_plant.hpp"

namespace dynpos::scenario {
namespace {

const std::filesystem::path kSource = DYNPOS_SOURCE_DIR;

VesselConfig vessel(const char* name = "gunnerus.toml") {
  return load_vessel_config(kSource / "data" / "vessels" / name);
}

// Stationkeeping at heading 0 with 10 m/s wind 30° off the bow for `duration` s.
ScenarioSpec hold(double duration) {
  ScenarioSpec spec;
  spec.name = "hold";
  spec.duration_s = duration;
  spec.environment.wind_speed_mps = 10.0;
  spec.environment.wind_from_deg = 30.0;
  spec.setpoints.push_back({0.0, 0.0, 0.0, 0.0, "hold"});
  return spec;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(UnitFailure, NamesTheModelsActuatorsAndLayoutUnitsAndGroups) {
  const UnitFailure model({10.0, "stb+tunnel"}, vessel());
  EXPECT_EQ(model.units(vessel()), (std::vector<std::string>{"stb", "tunnel"}));
  EXPECT_TRUE(model.capacity().empty());
  const model::ThrustAllocationOptions options = model.allocation({});
  EXPECT_EQ(options.capacity(1), 0.0);
  EXPECT_EQ(options.capacity(4), 0.0);
  EXPECT_EQ(options.capacity(0), 1.0);
  const VesselConfig layout = vessel("gunnerus-2015.toml");
  const UnitFailure group({10.0, "group:port"}, layout);
  EXPECT_EQ(group.units(layout), (std::vector<std::string>{"pod_port", "tunnel"}));
  EXPECT_THAT(error_of([&] {
                UnitFailure({1.0, "bow3"}, layout);
              }),
              ::testing::HasSubstr("no unit or group 'bow3'"));
  EXPECT_THAT(error_of([&] {
                UnitFailure({1.0, "port+rudder"}, vessel());
              }),
              ::testing::HasSubstr("unknown actuator 'rudder'"));
}

TEST(UnitFailure, CutsTheDrivesFromItsTimeOnAndHoldsTheSteering) {
  const VesselConfig layout = vessel("gunnerus-2015.toml");
  const VesselPlant plant(layout);
  const UnitFailure f({5.0, "pod_port"}, layout);
  Eigen::VectorXd x = plant.initial_state(0.0);
  x[VesselPlant::kUnits + 1] = 0.7;  // pod_port points at 0.7 rad
  Eigen::VectorXd u = Eigen::VectorXd::Constant(plant.input_size(), 3.0);
  f.cut(4.99, x, u);
  EXPECT_EQ(u[VesselPlant::kCmdUnits], 3.0);
  f.cut(5.0, x, u);
  EXPECT_EQ(u[VesselPlant::kCmdUnits], 0.0);      // shaft speed order
  EXPECT_EQ(u[VesselPlant::kCmdUnits + 1], 0.7);  // azimuth held where it points
  EXPECT_EQ(u[VesselPlant::kCmdUnits + 2], 3.0);  // pod_stb untouched
}

TEST(UnitFailure, TheRunTripsTheUnitAndItsTruthStatesTheResponse) {
  ScenarioSpec spec = hold(360.0);
  spec.failure = FailureEvent{300.0, "tunnel"};
  const ScenarioRun run = run_scenario(spec, vessel(), 1);
  ASSERT_TRUE(run.truth.failure);
  const FailureTruth& f = *run.truth.failure;
  EXPECT_EQ(f.time_s, 300.0);
  EXPECT_EQ(f.units, (std::vector<std::string>{"tunnel"}));
  EXPECT_GT(f.peak_excursion_m, 0.0);
  EXPECT_GE(f.time_to_peak_s, 0.0);
  // The tunnel's shaft runs down with its own dynamics: running before, near zero 20 s after.
  const auto& t = run.truth_log.time();
  const auto& n = run.truth_log.values("rpm.tunnel");
  double before = 0.0, after = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] > 240.0 && t[i] < 300.0) before = std::max(before, std::abs(n[i]));
    if (t[i] > 320.0) after = std::max(after, std::abs(n[i]));
  }
  EXPECT_GT(before, 0.5);
  EXPECT_LT(after, 1e-3 * before);
  // truth.json reads back the same.
  const TrialTruth back = from_json(to_json(run.truth));
  ASSERT_TRUE(back.failure);
  EXPECT_EQ(back.failure->peak_excursion_m, f.peak_excursion_m);
  EXPECT_EQ(back.failure->recovery_s.has_value(), f.recovery_s.has_value());
}

TEST(UnitFailure, AFailureTheVesselDoesNotHaveNamesTheScenarioKey) {
  ScenarioSpec spec = hold(10.0);
  spec.source = "trip.toml";
  spec.failure = FailureEvent{5.0, "bow3"};
  const std::string e = error_of([&] { run_scenario(spec, vessel(), 1); });
  EXPECT_THAT(e, ::testing::HasSubstr("trip.toml"));
  EXPECT_THAT(e, ::testing::HasSubstr("failure"));
  EXPECT_THAT(e, ::testing::HasSubstr("unknown actuator 'bow3'"));
}

TEST(ScenarioEvents, FileKeysAndTheirErrors) {
  const auto dir = std::filesystem::temp_directory_path() / "dynpos_unit_failure_test";
  std::filesystem::create_directories(dir);
  const auto load = [&](const std::string& extra) {
    const auto path = dir / "s.toml";
    std::ofstream(path) << "name = \"s\"\nduration_s = 100\n"
                        << extra
                        << "\n[[setpoint]]\nt_s = 0\nnorth_m = 0\neast_m = 0\nheading_deg = 0\n";
    return load_scenario(path);
  };
  const ScenarioSpec ok = load(
      "observer = \"ekf\"\nfailure_at_s = 50\nfailure = \"tunnel\"\n"
      "[[gnss_dropout]]\nt_s = 20\nduration_s = 30");
  EXPECT_EQ(ok.observer, control::ObserverKind::kEkf);
  EXPECT_TRUE(ok.observer_wind_feedforward);  // the default
  EXPECT_FALSE(
      load("observer = \"ekf\"\nobserver_wind_feedforward = false").observer_wind_feedforward);
  EXPECT_THAT(error_of([&] { load("observer_wind_feedforward = \"yes\""); }),
              ::testing::HasSubstr("observer_wind_feedforward"));
  EXPECT_TRUE(ok.inertial_position_aid);  // the default
  EXPECT_FALSE(load("inertial_position_aid = false").inertial_position_aid);
  EXPECT_THAT(error_of([&] { load("inertial_position_aid = 1"); }),
              ::testing::HasSubstr("inertial_position_aid"));
  ASSERT_TRUE(ok.failure);
  EXPECT_EQ(ok.failure->t_s, 50.0);
  EXPECT_TRUE(any_covers(ok.gnss_dropouts, 20.0));
  EXPECT_TRUE(any_covers(ok.gnss_dropouts, 49.9));
  EXPECT_FALSE(any_covers(ok.gnss_dropouts, 50.0));
  EXPECT_THAT(error_of([&] { load("observer = \"kalman\""); }),
              ::testing::HasSubstr("unknown observer 'kalman'"));
  EXPECT_THAT(error_of([&] { load("failure_at_s = 500\nfailure = \"tunnel\""); }),
              ::testing::HasSubstr("failure_at_s"));
  EXPECT_THAT(error_of([&] { load("failure_at_s = 5"); }), ::testing::HasSubstr("failure"));
  EXPECT_THAT(error_of([&] {
                load(
                    "[[gnss_dropout]]\nt_s = 20\nduration_s = 30\n"
                    "[[gnss_dropout]]\nt_s = 40\nduration_s = 5");
              }),
              ::testing::HasSubstr("not overlap"));
  std::filesystem::remove_all(dir);
}

TEST(ScenarioEvents, AnObserverNeedsDpSetpoints) {
  ScenarioSpec spec;
  spec.name = "joystick";
  spec.duration_s = 10.0;
  spec.observer = control::ObserverKind::kPassive;
  EXPECT_THAT(error_of([&] { spec.validate(); }),
              ::testing::HasSubstr("an observer runs in the DP loop"));
}

TEST(ScenarioEvents, ADropoutLeavesTheLoggedFixesMissingAndTheObserverCoasts) {
  ScenarioSpec spec = hold(120.0);
  spec.observer = control::ObserverKind::kEkf;
  spec.gnss_dropouts = {{60.0, 30.0}};
  const ScenarioRun run = run_scenario(spec, vessel(), 1);
  const auto& t = run.log.time();
  const auto& lat = run.log.values("gnss1.lat");
  int in_dropout = 0, outside = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (std::isnan(lat[i])) continue;
    (t[i] >= 60.0 && t[i] < 90.0 ? in_dropout : outside) += 1;
  }
  EXPECT_EQ(in_dropout, 0);
  EXPECT_GT(outside, 80);  // 1 Hz over the other 90 s
  // The observer's estimate stays finite and near the true motion through the dropout.
  const core::Log& truth = run.truth_log;
  for (std::size_t i = 0; i < truth.time().size(); ++i) {
    const double e = std::hypot(truth.values("observer.north")[i] - truth.values("lf.north")[i],
                                truth.values("observer.east")[i] - truth.values("lf.east")[i]);
    ASSERT_TRUE(std::isfinite(e));
    if (truth.time()[i] > 30.0) {
      EXPECT_LT(e, 2.0) << "t = " << truth.time()[i];
    }
    // The DP system's position is the inertial bridge's through the dropout, the fix outside
    // (the log's 0.1 s rows clear of the edges).
    const double ti = truth.time()[i];
    const double bridged = truth.values("observer.bridged")[i];
    if (ti > 60.05 && ti < 89.95) {
      EXPECT_EQ(bridged, 1.0) << ti;
    } else if (ti < 59.95 || ti > 90.05) {
      EXPECT_EQ(bridged, 0.0) << ti;
    }
  }
}

// The wind feedforward: the observer's model has the wind force from the DP system's wind sensor,
// so its estimate of the whole environmental load (b̂ and that force) follows the gusts as they
// come, where b̂ alone follows them only through the motion they cause. In 10 m/s of gusty wind
// (12 % turbulence, no waves: the load's fast part is the gusts) both estimates have the load's
// mean (within 5 %; measured 0.1–1.6 % on seeds 1, 2, 3 and 5); with the feedforward the rms
// error of the load estimate about the true load is at most 0.7 of the one without (measured
// 0.51–0.61: what is left is mostly the wind sensor's noise, 0.2 m/s and 2° at 1 Hz, some 4 % of
// the wind force, and the lag of b̂ behind the current and the slowly varying bias).
TEST(ScenarioEvents, TheWindFeedforwardFollowsTheGustsInTheLoadEstimate) {
  ScenarioSpec spec = hold(400.0);
  spec.observer = control::ObserverKind::kEkf;
  const auto figures = [&](bool feedforward) {
    spec.observer_wind_feedforward = feedforward;
    const ScenarioRun run = run_scenario(spec, vessel(), 3);
    const core::Log& truth = run.truth_log;
    std::array<double, 2> mean_error{}, mean_load{}, ms{};
    int n = 0;
    for (std::size_t i = 0; i < truth.time().size(); ++i) {
      if (truth.time()[i] < 100.0) continue;  // the estimate settled
      ++n;
      for (int k = 0; k < 2; ++k) {
        const char* axis = k == 0 ? "north" : "east";
        const double load = truth.values(std::string("env_load.") + axis)[i];
        const double e = truth.values(std::string("observer.bias.") + axis)[i] - load;
        mean_error[k] += e;
        mean_load[k] += load;
        ms[k] += e * e;
      }
    }
    std::array<double, 4> out{};  // relative mean error N, E; rms error N, E [N]
    for (int k = 0; k < 2; ++k) {
      out[k] = std::abs(mean_error[k] / mean_load[k]);
      out[2 + k] = std::sqrt(ms[k] / n);
    }
    return out;
  };
  const std::array<double, 4> with = figures(true), without = figures(false);
  std::printf(
      "load estimate: mean error N %.3f E %.3f, rms error N %.0f E %.0f N with the "
      "feedforward; %.3f %.3f, %.0f %.0f N without\n",
      with[0], with[1], with[2], with[3], without[0], without[1], without[2], without[3]);
  for (int k = 0; k < 2; ++k) {
    EXPECT_LT(with[k], 0.05) << k;
    EXPECT_LT(without[k], 0.05) << k;
    EXPECT_LT(with[2 + k], 0.7 * without[2 + k]) << k;
  }
}

}  // namespace
}  // namespace dynpos::scenario
