#include "dynpos/scenario/actuator_commands.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dynpos/scenario/vessel_plant.hpp"

namespace dynpos::scenario {
namespace {

TEST(ActuatorDelays, EachCommandArrivesAfterItsDeadTime) {
  VesselConfig vessel;
  vessel.propeller.dead_time = 0.5;
  vessel.rudder.dead_time = 0.2;
  vessel.tunnel.dead_time = 0.3;
  const double dt = 0.1;
  ActuatorCommands initial;
  initial.n_port_rps = 1.0;
  initial.n_stb_rps = 1.5;
  ActuatorDelays delays(vessel, dt, initial);
  Eigen::VectorXd u = Eigen::VectorXd::Constant(VesselPlant::kInputSize, -7.0);
  const ActuatorCommands commands{2.0, 2.5, 0.1, 0.2, 3.0, {}};
  // Tick k: a command given from tick 0 on arrives at the tick of its dead time; before, the
  // line holds what was commanded before the run.
  for (int k = 0; k <= 6; ++k) {
    delays.step(commands, u);
    EXPECT_EQ(u[VesselPlant::kCmdPort], k >= 5 ? 2.0 : 1.0) << k;
    EXPECT_EQ(u[VesselPlant::kCmdStb], k >= 5 ? 2.5 : 1.5) << k;
    EXPECT_EQ(u[VesselPlant::kCmdRudderPort], k >= 2 ? 0.1 : 0.0) << k;
    EXPECT_EQ(u[VesselPlant::kCmdRudderStb], k >= 2 ? 0.2 : 0.0) << k;
    EXPECT_EQ(u[VesselPlant::kCmdTunnel], k >= 3 ? 3.0 : 0.0) << k;
  }
  // The environment's inputs are not touched.
  EXPECT_EQ(u[VesselPlant::kTauEnvBody], -7.0);
  EXPECT_EQ(u[VesselPlant::kCurrentNed + 1], -7.0);
}

}  // namespace
}  // namespace dynpos::scenario
