#include "dynpos/scenario/actuator_commands.hpp"

#include "dynpos/scenario/vessel_plant.hpp"

namespace dynpos::scenario {

ActuatorDelays::ActuatorDelays(const VesselConfig& vessel, double dt_s,
                               const ActuatorCommands& initial)
    : port_(vessel.propeller.dead_time, dt_s, initial.n_port_rps),
      stb_(vessel.propeller.dead_time, dt_s, initial.n_stb_rps),
      rudder_port_(vessel.rudder.dead_time, dt_s, initial.rudder_port_rad),
      rudder_stb_(vessel.rudder.dead_time, dt_s, initial.rudder_stb_rad),
      tunnel_(vessel.tunnel.dead_time, dt_s, initial.n_tunnel_rps) {}

void ActuatorDelays::step(const ActuatorCommands& commands, sim::VectorRef u) {
  u[VesselPlant::kCmdPort] = port_.push(commands.n_port_rps);
  u[VesselPlant::kCmdStb] = stb_.push(commands.n_stb_rps);
  u[VesselPlant::kCmdRudderPort] = rudder_port_.push(commands.rudder_port_rad);
  u[VesselPlant::kCmdRudderStb] = rudder_stb_.push(commands.rudder_stb_rad);
  u[VesselPlant::kCmdTunnel] = tunnel_.push(commands.n_tunnel_rps);
}

}  // namespace dynpos::scenario
