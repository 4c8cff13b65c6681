#pragma once
/// \file
/// The force of the model's own units — two propellers, each with a rudder in its slipstream,
/// and the bow tunnel thruster — from what they deliver: each propeller's thrust, each rudder's
/// angle and the tunnel's side force, at the hull's velocity through the water ν_r. The rudders
/// see ν_r at their position plus their propeller's slipstream (rudder.hpp); τ_b by (2.37).
///
/// The one home of this sum: the simulator's plant (scenario/vessel_plant.hpp) makes its force
/// with it from its actuator states, and a fit of the hull to a sea-trial log
/// (scenario/hull_drive.hpp) from the logged feedback.

#include <Eigen/Core>

#include "dynpos/model/rudder.hpp"
#include "dynpos/model/thrust_configuration.hpp"

namespace dynpos::model {

/// What the model's units deliver.
struct ModelUnitOutputs {
  double thrust_port_N = 0.0;    ///< port propeller thrust along BODY x [N]
  double thrust_stb_N = 0.0;     ///< starboard propeller thrust along BODY x [N]
  double rudder_port_rad = 0.0;  ///< port rudder angle [rad], + trailing edge to starboard
  double rudder_stb_rad = 0.0;   ///< starboard rudder angle [rad]
  double tunnel_thrust_N = 0.0;  ///< tunnel side force along BODY y [N] (after its speed loss)
};

/// The rudders' forces and the units' total force and moment.
struct ModelUnitForces {
  RudderForce rudder_port, rudder_stb;
  Eigen::Vector3d tau_b = Eigen::Vector3d::Zero();  ///< (X [N], Y [N], N [N·m]) in BODY
};

/// The forces of `outputs` at velocity through the water nu_r = (u_r, v_r, r) in BODY.
ModelUnitForces model_unit_forces(const Rudder& rudder, const ThrustConfiguration& layout,
                                  const ModelUnitOutputs& outputs,
                                  const Eigen::Vector3d& nu_r) noexcept;

}  // namespace dynpos::model
