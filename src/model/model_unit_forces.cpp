#include "dynpos/model/model_unit_forces.hpp"

namespace dynpos::model {

ModelUnitForces model_unit_forces(const Rudder& rudder, const ThrustConfiguration& layout,
                                  const ModelUnitOutputs& outputs,
                                  const Eigen::Vector3d& nu_r) noexcept {
  const Eigen::Vector2d v_port =
      ThrustConfiguration::velocity_at(nu_r, layout.params().p_port_rudder_b);
  const Eigen::Vector2d v_stb =
      ThrustConfiguration::velocity_at(nu_r, layout.params().p_stb_rudder_b);
  ModelUnitForces out;
  out.rudder_port =
      rudder.force(outputs.rudder_port_rad, {v_port.x(), v_port.y(), outputs.thrust_port_N});
  out.rudder_stb =
      rudder.force(outputs.rudder_stb_rad, {v_stb.x(), v_stb.y(), outputs.thrust_stb_N});
  ActuatorForces f;
  f.thrust_port = outputs.thrust_port_N;
  f.thrust_stb = outputs.thrust_stb_N;
  f.rudder_port_b = out.rudder_port.f_b;
  f.rudder_stb_b = out.rudder_stb.f_b;
  f.tunnel = outputs.tunnel_thrust_N;
  out.tau_b = layout.tau(f);  // (2.37)
  return out;
}

}  // namespace dynpos::model
