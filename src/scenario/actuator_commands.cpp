#include "dynpos/scenario/actuator_commands.hpp"

#include "dynpos/scenario/vessel_plant.hpp"

namespace dynpos::scenario {

ActuatorDelays::ActuatorDelays(const VesselConfig& vessel, double dt_s,
                               const ActuatorCommands& initial)
    : port_(vessel.propeller.dead_time, dt_s, initial.n_port_rps),
      stb_(vessel.propeller.dead_time, dt_s, initial.n_stb_rps),
      rudder_port_(vessel.rudder.dead_time, dt_s, initial.rudder_port_rad),
      rudder_stb_(vessel.rudder.dead_time, dt_s, initial.rudder_stb_rad),
      tunnel_(vessel.tunnel.dead_time, dt_s, initial.n_tunnel_rps) {
  for (std::size_t k = 0; k < vessel.thrusters.size(); ++k) {
    const double dead_time_s = vessel.thrusters[k].dead_time_s;
    const ActuatorCommands::Unit held =
        k < initial.units.size() ? initial.units[k] : ActuatorCommands::Unit{};
    unit_n_.emplace_back(dead_time_s, dt_s, held.n_rps);
    unit_angle_.emplace_back(dead_time_s, dt_s, held.angle_rad);
  }
}

void ActuatorDelays::step(const ActuatorCommands& commands, sim::VectorRef u) {
  u[VesselPlant::kCmdPort] = port_.push(commands.n_port_rps);
  u[VesselPlant::kCmdStb] = stb_.push(commands.n_stb_rps);
  u[VesselPlant::kCmdRudderPort] = rudder_port_.push(commands.rudder_port_rad);
  u[VesselPlant::kCmdRudderStb] = rudder_stb_.push(commands.rudder_stb_rad);
  u[VesselPlant::kCmdTunnel] = tunnel_.push(commands.n_tunnel_rps);
  for (std::size_t k = 0; k < unit_n_.size(); ++k) {
    const Eigen::Index j = VesselPlant::kCmdUnits + 2 * static_cast<Eigen::Index>(k);
    u[j] = unit_n_[k].push(commands.units[k].n_rps);
    u[j + 1] = unit_angle_[k].push(commands.units[k].angle_rad);
  }
}

}  // namespace dynpos::scenario
