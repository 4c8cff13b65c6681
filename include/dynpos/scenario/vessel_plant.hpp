#pragma once
/// \file
/// VesselPlant: the continuous dynamics of the whole virtual vessel — hull, two speed-controlled
/// propellers, two rudders and the tunnel thruster, or the units of a [[thruster]] layout — as
/// one sim::HybridSystem (no jumps).
///
/// The model's own units. State x ∈ ℝ²¹ (indices below): the hull state (hull.hpp, 10), port and
/// starboard propeller (thruster.hpp, 4 each), port and starboard rudder angle [rad], tunnel shaft
/// speed [rps]. Held input u ∈ ℝ¹³: the delayed actuator commands (port/stb shaft speed [rps],
/// port/stb rudder angle [rad], tunnel shaft speed [rps]); the environment force in BODY held over
/// the step (wind + wave drift) [N, N, N·m]; the force in NED (bias (2.22) + step loads) [N, N,
/// N·m]; the current velocity in NED [m/s]. Dead times and the environment are discrete and
/// advanced once per tick by the run's tasks (sample and hold; actuator_commands.hpp,
/// trial_environment.hpp).
///
/// A [[thruster]] layout of N units (model/unit_drive.hpp). State x ∈ ℝ¹⁰⁺²ᴺ: the hull state,
/// then per unit k its shaft speed [rps] at kUnits + 2k and its steering angle [rad] (azimuth
/// direction α, unwrapped; rudder angle δ; 0 for the others) at kUnits + 2k + 1. Held input
/// u ∈ ℝ¹³⁺²ᴺ: the model's commands (unused), the environment as above, then per unit k the
/// delayed shaft speed command [rps] at kCmdUnits + 2k and steering command [rad] at
/// kCmdUnits + 2k + 1.

#include <Eigen/Core>

#include "dynpos/model/hull.hpp"
#include "dynpos/model/rudder.hpp"
#include "dynpos/model/thrust_configuration.hpp"
#include "dynpos/model/thruster.hpp"
#include "dynpos/model/tunnel_thruster.hpp"
#include "dynpos/model/unit_drive.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/vessel_config.hpp"
#include "dynpos/sim/hybrid_system.hpp"

namespace dynpos::scenario {

/// Instantaneous actuator outputs of the plant.
struct ActuatorState {
  model::ThrusterOutput port, stb;
  model::TunnelThrusterOutput tunnel;
  model::RudderForce rudder_port, rudder_stb;
  /// A [[thruster]] layout: each unit's outputs in layout order (the model's fields above are
  /// then zero); empty for the model's own units.
  std::vector<model::UnitOutput> units;
  Eigen::Vector3d tau_b = Eigen::Vector3d::Zero();  ///< actuator force and moment in BODY
};

/// Throws core::InputError (option `key`) when `spec` cannot run on `vessel`: manual rudder
/// steps name the model's two rudders, which a [[thruster]] layout does not have; and (the
/// scenario file's key `failure`) when its failure names a unit the vessel does not have.
void check_simulated(const VesselConfig& vessel, const ScenarioSpec& spec,
                     const char* key = "vessel");

class VesselPlant final : public sim::HybridSystem {
 public:
  static constexpr int kHull = 0, kPort = 10, kStb = 14, kRudderPort = 18, kRudderStb = 19,
                       kTunnel = 20, kStateSize = 21;
  static constexpr int kCmdPort = 0, kCmdStb = 1, kCmdRudderPort = 2, kCmdRudderStb = 3,
                       kCmdTunnel = 4, kTauEnvBody = 5, kForceNed = 8, kCurrentNed = 11,
                       kInputSize = 13;
  static constexpr int kUnits = 10, kCmdUnits = 13;  ///< a layout's first unit (file comment)

  /// The plant of `config`: its [[thruster]] units when it has them, each at
  /// config.thruster_capacity (empty: all 1; 0 a lost unit), else the model's own.
  explicit VesselPlant(const VesselConfig& config);

  Eigen::Index state_size() const override {
    return drives_.empty() ? kStateSize : kUnits + 2 * static_cast<Eigen::Index>(drives_.size());
  }
  Eigen::Index input_size() const override {
    return drives_.empty() ? kInputSize : kCmdUnits + 2 * static_cast<Eigen::Index>(drives_.size());
  }
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
  /// The drives of a [[thruster]] layout, in layout order; empty for the model's own units.
  const std::vector<model::UnitDrive>& drives() const noexcept { return drives_; }
  /// Each layout unit's capacity (1 as rated, 0 lost), in layout order.
  const std::vector<double>& capacity() const noexcept { return capacity_; }

 private:
  // The layout's actuator force and moment in BODY at state x (allocation-free, for flow()).
  Eigen::Vector3d layout_tau_b(const sim::ConstVectorRef& x) const;

  // actuators() with cos ψ and sin ψ of x's heading given (flow() needs them too).
  ActuatorState actuators(const sim::ConstVectorRef& x, const Eigen::Vector2d& current_n,
                          double cos_psi, double sin_psi) const;

  model::Hull hull_;
  model::Thruster propeller_;
  model::Rudder rudder_;
  model::TunnelThruster tunnel_;
  model::ThrustConfiguration layout_;
  std::vector<model::UnitDrive> drives_;
  std::vector<double> capacity_;
};

}  // namespace dynpos::scenario
