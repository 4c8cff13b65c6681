#pragma once
/// \file
/// VesselPlant: the continuous dynamics of the whole virtual vessel — hull, two speed-controlled
/// propellers, two rudders and the tunnel thruster — as one sim::HybridSystem (no jumps).
///
/// State x ∈ ℝ²¹ (indices below): the hull state (hull.hpp, 10), port and starboard propeller
/// (thruster.hpp, 4 each), port and starboard rudder angle [rad], tunnel shaft speed [rps].
/// Held input u ∈ ℝ¹³: the delayed actuator commands (port/stb shaft speed [rps], port/stb
/// rudder angle [rad], tunnel shaft speed [rps]); the environment force in BODY held over the
/// step (wind + wave drift) [N, N, N·m]; the force in NED (bias (2.22) + step loads)
/// [N, N, N·m]; the current velocity in NED [m/s]. Dead times and the environment are
/// discrete and advanced once per tick by the run's tasks (sample and hold; actuator_commands.hpp,
/// trial_environment.hpp).

#include <Eigen/Core>

#include "dynpos/model/hull.hpp"
#include "dynpos/model/rudder.hpp"
#include "dynpos/model/thrust_configuration.hpp"
#include "dynpos/model/thruster.hpp"
#include "dynpos/model/tunnel_thruster.hpp"
#include "dynpos/scenario/vessel_config.hpp"
#include "dynpos/sim/hybrid_system.hpp"

namespace dynpos::scenario {

/// Instantaneous actuator outputs of the plant.
struct ActuatorState {
  model::ThrusterOutput port, stb;
  model::TunnelThrusterOutput tunnel;
  model::RudderForce rudder_port, rudder_stb;
  Eigen::Vector3d tau_b = Eigen::Vector3d::Zero();  ///< actuator force and moment in BODY
};

/// Throws core::InputError (option `key`) for a vessel with a [[thruster]] layout: the plant
/// runs the model's own units (the two propellers with rudders and the tunnel), and a run of
/// another layout with them would be a run of another vessel.
void check_simulated(const VesselConfig& vessel, const char* key = "vessel");

class VesselPlant final : public sim::HybridSystem {
 public:
  static constexpr int kHull = 0, kPort = 10, kStb = 14, kRudderPort = 18, kRudderStb = 19,
                       kTunnel = 20, kStateSize = 21;
  static constexpr int kCmdPort = 0, kCmdStb = 1, kCmdRudderPort = 2, kCmdRudderStb = 3,
                       kCmdTunnel = 4, kTauEnvBody = 5, kForceNed = 8, kCurrentNed = 11,
                       kInputSize = 13;

  /// Throws core::InputError for a vessel the plant cannot run (check_simulated).
  explicit VesselPlant(const VesselConfig& config);

  Eigen::Index state_size() const override { return kStateSize; }
  Eigen::Index input_size() const override { return kInputSize; }
  void flow(double t, const sim::ConstVectorRef& x, const sim::ConstVectorRef& u,
            sim::VectorRef dxdt) const override;

  /// Actuator outputs at state x with current velocity current_n [m/s].
  ActuatorState actuators(const sim::ConstVectorRef& x, const Eigen::Vector2d& current_n) const;

  /// A state at rest (zero speed, actuators idle) with heading ψ₀ [rad].
  Eigen::VectorXd initial_state(double heading_rad) const;

  const model::Hull& hull() const noexcept { return hull_; }
  const model::Thruster& propeller() const noexcept { return propeller_; }
  const model::Rudder& rudder() const noexcept { return rudder_; }
  const model::TunnelThruster& tunnel() const noexcept { return tunnel_; }
  const model::ThrustConfiguration& layout() const noexcept { return layout_; }

 private:
  // actuators() with cos ψ and sin ψ of x's heading given (flow() needs them too).
  ActuatorState actuators(const sim::ConstVectorRef& x, const Eigen::Vector2d& current_n,
                          double cos_psi, double sin_psi) const;

  model::Hull hull_;
  model::Thruster propeller_;
  model::Rudder rudder_;
  model::TunnelThruster tunnel_;
  model::ThrustConfiguration layout_;
};

}  // namespace dynpos::scenario
