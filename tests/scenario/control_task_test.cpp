#include "dynpos/scenario/control_task.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dynpos/core/angle.hpp"
#include "dynpos/core/log.hpp"
#include "dynpos/model/thruster.hpp"
#include "dynpos/scenario/joystick_lever.hpp"

namespace dynpos::scenario {
namespace {

using Plant = VesselPlant;
using model::Hull;

ScenarioSpec joystick_spec() {
  ScenarioSpec s;
  s.duration_s = 60.0;
  s.joystick = {{10.0, 50.0, 0.0, 0.0}};
  return s;
}

TEST(InitialTrim, AtRestWithoutInitialSpeed) {
  const VesselConfig vessel;
  const Plant plant(vessel);
  ScenarioSpec spec = joystick_spec();
  spec.initial_heading_deg = 90.0;
  const InitialTrim trim = initial_trim(spec, vessel, plant);
  EXPECT_EQ(trim.x0, plant.initial_state(core::deg_to_rad(90.0)));
  EXPECT_EQ(trim.lever_pct, Eigen::Vector3d::Zero());
  EXPECT_EQ(trim.commands.n_port_rps, 0.0);
}

TEST(InitialTrim, InitialSpeedIsHeldByTheLeverAndThePropellers) {
  const VesselConfig vessel;
  const Plant plant(vessel);
  ScenarioSpec spec = joystick_spec();
  spec.initial_surge_mps = 2.0;
  const InitialTrim trim = initial_trim(spec, vessel, plant);
  EXPECT_EQ(trim.x0[Plant::kHull + Hull::kSurge], 2.0);
  // The lever demands the hull's resistance at 2 m/s through the lever curve.
  const double resistance = -plant.hull().hydrodynamic_forces({2.0, 0, 0}, {2.0, 0, 0}).x();
  EXPECT_GT(resistance, 0.0);
  const Eigen::Vector3d demand =
      lever_to_demand_fraction(trim.lever_pct, vessel.joystick.lever_exponent);
  EXPECT_NEAR(demand.x() * vessel.joystick.max_surge_N, resistance, 1e-6 * resistance);
  EXPECT_NEAR(trim.demand_pct.x(), 100.0 * resistance / vessel.joystick.max_surge_N, 1e-12);
  // Each main propeller gives half of it at the trimmed shaft speed.
  EXPECT_EQ(trim.commands.n_port_rps, trim.commands.n_stb_rps);
  EXPECT_EQ(trim.commands.n_port_rps, plant.propeller().shaft_speed_for_thrust(0.5 * resistance));
  EXPECT_EQ(Eigen::Vector4d(trim.x0.segment<4>(Plant::kPort)),
            Eigen::Vector4d(plant.propeller().steady_state(trim.commands.n_port_rps, 2.0)));
}

TEST(ControlTask, JoystickStepIsAllocatedAndRecordedWithThePropellerTruth) {
  const VesselConfig vessel;
  const Plant plant(vessel);
  const ScenarioSpec spec = joystick_spec();
  const InitialTrim trim = initial_trim(spec, vessel, plant);
  ControlTask control(spec, vessel, plant, trim, 1);
  EXPECT_DOUBLE_EQ(control.period_s(), 1.0 / vessel.joystick.control_rate_hz);
  control.step(0.0, trim.x0, Eigen::VectorXd::Zero(plant.input_size()));
  EXPECT_EQ(control.commands().n_port_rps, 0.0);
  control.step(10.0, trim.x0, Eigen::VectorXd::Zero(plant.input_size()));
  // 50 % lever with exponent 2: 25 % of the largest surge force, both propellers ahead.
  EXPECT_EQ(control.lever_pct(), Eigen::Vector3d(50.0, 0.0, 0.0));
  EXPECT_NEAR(control.demand_pct().x(), 25.0, 1e-12);
  EXPECT_GT(control.commands().n_port_rps, 0.0);
  EXPECT_NEAR(control.forces_N()[0] + control.forces_N()[1], 0.25 * vessel.joystick.max_surge_N,
              1.0);
  control.step(10.1, trim.x0, Eigen::VectorXd::Zero(plant.input_size()));  // held: no new record
  TrialTruth truth;
  control.write_truth(truth);
  ASSERT_EQ(truth.commands.size(), 1u);
  const CommandTruth& c = truth.commands[0];
  EXPECT_EQ(c.t_s, 10.0);
  EXPECT_EQ(c.surge_pct, 50.0);
  EXPECT_NEAR(c.demand_surge_N, 0.25 * vessel.joystick.max_surge_N, 1e-6);
  EXPECT_GT(c.n_port_rps, 0.0);
  // Both main propellers stepped from rest; the truth is the model's Smith fit of the step.
  ASSERT_EQ(truth.propeller_steps.size(), 2u);
  EXPECT_EQ(truth.propeller_steps[0].thruster, "port");
  EXPECT_EQ(truth.propeller_steps[1].thruster, "stb");
  const PropellerStepTruth& port = truth.propeller_steps[0];
  EXPECT_EQ(port.n_from_rps, 0.0);
  EXPECT_EQ(port.n_to_rps, c.n_port_rps);
  const model::ThrusterStepTruth expected =
      model::thruster_step_truth(plant.propeller(), 0.0, port.n_to_rps, spec.dt_s);
  EXPECT_EQ(port.shaft_speed.time_constant, expected.shaft_speed.time_constant);
  EXPECT_EQ(port.thrust.dead_time, expected.thrust.dead_time);
  EXPECT_TRUE(truth.setpoints.empty());
  EXPECT_FALSE(truth.hybrid.has_value());
  EXPECT_FALSE(control.dp_active());
  EXPECT_TRUE(core::is_missing(control.setpoint_n().x()));
}

TEST(ControlTask, RudderStepOverridesTheAllocationsRudders) {
  const VesselConfig vessel;
  const Plant plant(vessel);
  ScenarioSpec spec = joystick_spec();
  spec.rudder = {{5.0, 10.0, false}};
  const InitialTrim trim = initial_trim(spec, vessel, plant);
  ControlTask control(spec, vessel, plant, trim, 1);
  control.step(5.0, trim.x0, Eigen::VectorXd::Zero(plant.input_size()));
  EXPECT_EQ(control.commands().rudder_port_rad, core::deg_to_rad(10.0));
  EXPECT_EQ(control.commands().rudder_stb_rad, core::deg_to_rad(10.0));
  TrialTruth truth;
  control.write_truth(truth);
  ASSERT_EQ(truth.rudder_steps.size(), 1u);
  EXPECT_EQ(truth.rudder_steps[0].to_deg, 10.0);
}

TEST(ControlTask, AutoHeadingAddsAYawDemand) {
  const VesselConfig vessel;
  const Plant plant(vessel);
  ScenarioSpec spec = joystick_spec();
  spec.heading_hold = true;
  const InitialTrim trim = initial_trim(spec, vessel, plant);
  ControlTask control(spec, vessel, plant, trim, 1);
  Eigen::VectorXd x = trim.x0;
  x[Plant::kHull + Hull::kYaw] = core::deg_to_rad(5.0);  // 5° to starboard of ψ(0) = 0
  control.step(0.0, x, Eigen::VectorXd::Zero(plant.input_size()));
  EXPECT_LT(control.demand_pct().z(), 0.0);  // turns back to port
  EXPECT_EQ(control.lever_pct().z(), 0.0);   // the operator's lever is untouched
  // Without auto heading the same state gives no yaw demand.
  spec.heading_hold = false;
  ControlTask manual(spec, vessel, plant, trim, 1);
  manual.step(0.0, x, Eigen::VectorXd::Zero(plant.input_size()));
  EXPECT_EQ(manual.demand_pct().z(), 0.0);
}

TEST(ControlTask, DpModeHoldsTheSetpointAndRecordsIt) {
  const VesselConfig vessel;
  const Plant plant(vessel);
  ScenarioSpec spec;
  spec.duration_s = 60.0;
  spec.setpoints = {{0.0, 0.0, 0.0, 0.0, "hold"}};
  spec.hybrid_integral = hybrid::IntegralJumpParams{};
  const InitialTrim trim = initial_trim(spec, vessel, plant);
  ControlTask control(spec, vessel, plant, trim, 1);
  Eigen::VectorXd x = trim.x0;
  x[Plant::kHull + Hull::kNorth] = 3.0;  // 3 m north of the setpoint
  control.step(0.0, x, Eigen::VectorXd::Zero(plant.input_size()));
  EXPECT_TRUE(control.dp_active());
  EXPECT_EQ(control.setpoint_n(), Eigen::Vector3d::Zero());
  EXPECT_LT(control.forces_N()[0] + control.forces_N()[1], 0.0);  // astern, towards it
  EXPECT_GT(control.bias_hat_n().x(), 0.0);
  TrialTruth truth;
  control.write_truth(truth);
  ASSERT_EQ(truth.setpoints.size(), 1u);
  EXPECT_EQ(truth.setpoints[0].name, "hold");
  ASSERT_TRUE(truth.hybrid.has_value());
  EXPECT_EQ(truth.hybrid->params.dwell_s, hybrid::IntegralJumpParams{}.dwell_s);
  EXPECT_TRUE(truth.commands.empty());
}

TEST(ControlTask, LargestUnmetDemandIsKept) {
  const VesselConfig vessel;
  const Plant plant(vessel);
  ScenarioSpec spec = joystick_spec();
  spec.joystick = {{0.0, 100.0, 100.0, 100.0}, {10.0, 0.0, 0.0, 0.0}};  // beyond the thrusters
  const InitialTrim trim = initial_trim(spec, vessel, plant);
  ControlTask control(spec, vessel, plant, trim, 1);
  control.step(0.0, trim.x0, Eigen::VectorXd::Zero(plant.input_size()));
  control.step(10.0, trim.x0, Eigen::VectorXd::Zero(plant.input_size()));
  TrialTruth truth;
  control.write_truth(truth);
  EXPECT_GT(truth.allocation_unmet_max.norm(), 0.0);
  EXPECT_EQ(truth.allocation_unmet_max, truth.commands[0].tau_unmet.cwiseAbs());
  EXPECT_EQ(truth.commands[1].tau_unmet, Eigen::Vector3d::Zero());
}

}  // namespace
}  // namespace dynpos::scenario
