#include "dynpos/scenario/truth_recorder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "dynpos/core/angle.hpp"

namespace dynpos::scenario {
namespace {

using Plant = VesselPlant;

// The channels of truth.csv, in order (docs/log-format.md).
const std::vector<std::pair<std::string, std::string>> kChannels = {
    {"north", "m"},
    {"east", "m"},
    {"down", "m"},
    {"heading", "rad"},
    {"roll", "rad"},
    {"pitch", "rad"},
    {"u", "m/s"},
    {"v", "m/s"},
    {"w", "m/s"},
    {"p", "rad/s"},
    {"q", "rad/s"},
    {"r", "rad/s"},
    {"rpm.port", "rps"},
    {"rpm.stb", "rps"},
    {"rpm.tunnel", "rps"},
    {"thrust.port", "N"},
    {"thrust.stb", "N"},
    {"thrust.tunnel", "N"},
    {"power.port", "W"},
    {"power.stb", "W"},
    {"power.tunnel", "W"},
    {"rudder.port", "rad"},
    {"rudder.stb", "rad"},
    {"command.surge", "1"},
    {"command.sway", "1"},
    {"command.yaw", "1"},
    {"lever.surge", "1"},
    {"lever.sway", "1"},
    {"lever.yaw", "1"},
    {"wind_speed", "m/s"},
    {"wind_dir", "rad"},
    {"current.north", "m/s"},
    {"current.east", "m/s"},
    {"setpoint.north", "m"},
    {"setpoint.east", "m"},
    {"setpoint.heading", "rad"},
    {"bias_estimate.north", "N"},
    {"bias_estimate.east", "N"},
    {"bias_estimate.yaw", "N*m"},
    {"load.north", "N"},
    {"load.east", "N"},
    {"load.yaw", "N*m"},
};

// A sample with a distinct value in every field.
VesselSample sample() {
  VesselSample s;
  s.motion.p_n = {1.0, 2.0, 3.0};
  s.motion.theta = {0.1, 0.2, -0.5};  // heading −0.5 rad: logged as 2π − 0.5
  s.motion.v_n = {4.0, 0.0, 0.0};
  s.motion.omega_nb_b = {0.01, 0.02, 0.03};
  s.shaft_speed_rps = {5.0, 6.0, 7.0};
  s.thrust_N = {8.0, 9.0, 10.0};
  s.power_W = {11.0, 12.0, 13.0};
  s.rudder_rad = {0.3, 0.4};
  s.wind_speed_mps = 14.0;
  s.wind_from_rad = 1.5;
  s.current_n = {0.5, 0.6};
  s.load_n = {15.0, 16.0, 17.0};
  return s;
}

struct Fixture {
  VesselConfig vessel;
  Plant plant{vessel};
  ScenarioSpec spec;
  InitialTrim trim;
  std::optional<ControlTask> control;

  explicit Fixture(bool dp) {
    spec.duration_s = 60.0;
    if (dp) {
      spec.setpoints = {{0.0, 10.0, 20.0, -90.0, "hold"}};
    } else {
      spec.joystick = {{0.0, 50.0, -20.0, 10.0}};
    }
    trim = initial_trim(spec, vessel, plant);
    control.emplace(spec, vessel, plant, trim, 1);
    control->step(0.0, trim.x0, Eigen::VectorXd::Zero(plant.input_size()));
  }
};

TEST(TruthRecorder, DeclaresTheChannelsOfTruthCsv) {
  Fixture f(false);
  core::Log log;
  const TruthRecorder recorder(log, *f.control);
  ASSERT_EQ(log.channels().size(), kChannels.size());
  for (std::size_t i = 0; i < kChannels.size(); ++i) {
    EXPECT_EQ(log.channels()[i].name, kChannels[i].first) << i;
    EXPECT_EQ(log.channels()[i].unit, kChannels[i].second) << i;
  }
}

TEST(TruthRecorder, RowHoldsTheSampleAndTheOperatorsDemand) {
  Fixture f(false);
  core::Log log;
  TruthRecorder recorder(log, *f.control);
  Eigen::VectorXd x = f.trim.x0, u = Eigen::VectorXd::Zero(Plant::kInputSize);
  const VesselSample s = sample();
  recorder.record(sim::TaskContext(7, 0.7, x, u), s);
  ASSERT_EQ(log.size(), 1u);
  EXPECT_EQ(log.time()[0], 0.7);
  const auto at = [&](const char* name) { return log.values(name)[0]; };
  EXPECT_EQ(at("north"), 1.0);
  EXPECT_EQ(at("down"), 3.0);
  EXPECT_EQ(at("heading"), core::wrap_2pi(-0.5));
  EXPECT_EQ(at("roll"), 0.1);
  EXPECT_EQ(at("pitch"), 0.2);
  EXPECT_EQ(at("u"), s.motion.v_b().x());
  EXPECT_EQ(at("v"), s.motion.v_b().y());
  EXPECT_EQ(at("r"), 0.03);
  EXPECT_EQ(at("rpm.tunnel"), 7.0);
  EXPECT_EQ(at("thrust.stb"), 9.0);
  EXPECT_EQ(at("power.port"), 11.0);
  EXPECT_EQ(at("rudder.stb"), 0.4);
  EXPECT_EQ(at("lever.sway"), -0.2);
  EXPECT_EQ(at("command.surge"), f.control->demand_pct().x() / 100.0);
  EXPECT_EQ(at("wind_dir"), 1.5);
  EXPECT_EQ(at("current.east"), 0.6);
  EXPECT_EQ(at("load.yaw"), 17.0);
  // Outside DP there is no setpoint and no bias estimate.
  EXPECT_TRUE(core::is_missing(at("setpoint.north")));
  EXPECT_TRUE(core::is_missing(at("setpoint.heading")));
  EXPECT_TRUE(core::is_missing(at("bias_estimate.north")));
}

TEST(TruthRecorder, DpRowsHoldTheSetpointAndTheBiasEstimate) {
  Fixture f(true);
  core::Log log;
  TruthRecorder recorder(log, *f.control);
  Eigen::VectorXd x = f.trim.x0, u = Eigen::VectorXd::Zero(Plant::kInputSize);
  recorder.record(sim::TaskContext(0, 0.0, x, u), sample());
  EXPECT_EQ(log.values("setpoint.north")[0], 10.0);
  EXPECT_EQ(log.values("setpoint.east")[0], 20.0);
  EXPECT_EQ(log.values("setpoint.heading")[0], core::wrap_2pi(core::deg_to_rad(-90.0)));
  EXPECT_EQ(log.values("bias_estimate.east")[0], f.control->bias_hat_n().y());
}

}  // namespace
}  // namespace dynpos::scenario
