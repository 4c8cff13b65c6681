#pragma once
/// \file
/// The vessel's true state at one log tick, as the truth log records it and the sensors
/// measure it: the full 6-DOF motion (the plant's low-frequency state composed with the
/// wave-frequency motion, differentiated analytically so that (4.2) and (4.65) hold exactly
/// along the sampled path), the actuators' outputs and the weather.

#include <Eigen/Core>
#include <array>
#include <vector>

#include "dynpos/scenario/trial_environment.hpp"
#include "dynpos/scenario/vessel_plant.hpp"
#include "dynpos/sensors/rigid_body_motion.hpp"

namespace dynpos::scenario {

/// The truth at one log tick (SI units).
struct VesselSample {
  sensors::RigidBodyMotion motion;  ///< at the control origin, LF + WF
  /// The low-frequency position and heading alone (N, E, ψ) [m, m, rad], ψ unwrapped.
  Eigen::Vector3d eta_lf_n = Eigen::Vector3d::Zero();
  std::array<double, 3> shaft_speed_rps{};  ///< port, stb, tunnel
  std::array<double, 3> thrust_N{};         ///< port, stb, tunnel
  std::array<double, 3> power_W{};          ///< port, stb, tunnel
  std::array<double, 2> rudder_rad{};       ///< port, stb
  /// A [[thruster]] layout's units in layout order (the arrays above are then zero).
  std::vector<model::UnitOutput> units;
  double wind_speed_mps = 0.0;                          ///< the true wind
  double wind_from_rad = 0.0;                           ///< the direction it comes from, [0, 2π)
  Eigen::Vector2d current_n = Eigen::Vector2d::Zero();  ///< current (N, E) [m/s]
  Eigen::Vector3d load_n = Eigen::Vector3d::Zero();     ///< step loads (NED) [N, N, N·m]
  /// The whole environmental load the thrusters hold against at rest (NED) [N, N, N·m]: wind and
  /// wave drift at the vessel's motion, the current on the hull at rest, the slowly varying bias
  /// (2.22) and the step loads: what an observer's b̂ estimates.
  Eigen::Vector3d env_load_n = Eigen::Vector3d::Zero();
};

/// Takes VesselSamples of a run (keeps the workspace, so sampling does not allocate).
class VesselSampler {
 public:
  /// A sampler of `plant` in `environment` (both must outlive it).
  VesselSampler(const VesselPlant& plant, const TrialEnvironment& environment);

  /// The sample at scenario time t [s] of the plant's state x and held input u, with the
  /// environment's wave generator at the sample of t.
  const VesselSample& sample(double t, const sim::ConstVectorRef& x, const sim::ConstVectorRef& u);

 private:
  const VesselPlant& plant_;
  const TrialEnvironment& environment_;
  Eigen::VectorXd dxdt_;
  VesselSample sample_;
};

}  // namespace dynpos::scenario
