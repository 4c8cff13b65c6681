#include "dynpos/scenario/trial_logger.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "dynpos/core/angle.hpp"
#include "dynpos/core/error.hpp"

namespace dynpos::scenario {
namespace {

using Plant = VesselPlant;

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
      spec.joystick = {{0.0, 50.0, 0.0, 0.0}};
    }
    trim = initial_trim(spec, vessel, plant);
    control.emplace(spec, vessel, plant, trim, 1);
    control->step(0.0, trim.x0, Eigen::VectorXd::Zero(plant.input_size()));
  }
};

TEST(TrialLogger, SensorsFirstThenTheCommandChannelsInLoggerUnits) {
  Fixture f(false);
  core::Log log;
  TrialLogger logger(log, f.spec, f.vessel, f.plant, 1, *f.control);
  const std::vector<core::Channel>& ch = log.channels();
  ASSERT_GT(ch.size(), 17u);
  EXPECT_EQ(ch.front().name.rfind("gnss1.", 0), 0u) << ch.front().name;
  const std::size_t first = ch.size() - 17;
  EXPECT_EQ(ch[first].name, "command.surge");
  EXPECT_EQ(ch[first].unit, "%");
  EXPECT_EQ(ch[first + 6].name, "command.rpm.port");
  EXPECT_EQ(ch[first + 6].unit, "rpm");
  EXPECT_EQ(ch[first + 9].name, "command.thrust.port");
  EXPECT_EQ(ch[first + 9].unit, "kN");
  EXPECT_EQ(ch.back().name, "setpoint.heading");
  EXPECT_EQ(ch.back().unit, "deg");

  VesselSample sample;
  logger.record(0.0, sample);
  logger.record(0.1, sample);
  ASSERT_EQ(log.size(), 2u);
  EXPECT_EQ(log.time()[1], 0.1);
  const ActuatorCommands& cmd = f.control->commands();
  EXPECT_EQ(log.values("command.surge")[1], f.control->demand_pct().x());
  EXPECT_EQ(log.values("lever.surge")[1], 50.0);
  EXPECT_EQ(log.values("command.rpm.port")[1], cmd.n_port_rps * 60.0);
  EXPECT_EQ(log.values("command.thrust.stb")[1], f.control->forces_N()[1] * 1e-3);
  EXPECT_EQ(log.values("command.rudder.port")[1], core::rad_to_deg(cmd.rudder_port_rad));
  EXPECT_TRUE(core::is_missing(log.values("setpoint.heading")[1]));
  // The gyro (10 Hz on a 10 Hz log) sampled the truth's heading.
  EXPECT_FALSE(core::is_missing(log.values("heading")[1]));
}

TEST(TrialLogger, DpSetpointIsLoggedInDegrees) {
  Fixture f(true);
  core::Log log;
  TrialLogger logger(log, f.spec, f.vessel, f.plant, 1, *f.control);
  logger.record(0.0, VesselSample{});
  EXPECT_EQ(log.values("setpoint.north")[0], 10.0);
  EXPECT_EQ(log.values("setpoint.heading")[0],
            core::rad_to_deg(core::wrap_2pi(core::deg_to_rad(-90.0))));
}

TEST(TrialLogger, SensorRateOffTheLogGridIsBadInputNamingTheVesselFile) {
  Fixture f(false);
  f.vessel.source = "vessels/odd.toml";
  f.vessel.sensors.gnss[0].timing.rate_hz = 3.0;
  core::Log log;
  EXPECT_THAT(
      [&] { TrialLogger(log, f.spec, f.vessel, f.plant, 1, *f.control); },
      testing::ThrowsMessage<core::InputError>(testing::ContainsRegex(
          "vessels/odd.toml.*gnss1: rate 3 Hz does not divide the log rate 10 Hz.*--log-rate")));
}

}  // namespace
}  // namespace dynpos::scenario
