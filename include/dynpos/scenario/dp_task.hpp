#pragma once
/// \file
/// DP mode of a scenario run: the operator's setpoints through the reference model into the DP
/// controller (5.35)–(5.38), run on the low-frequency motion (an ideal observer) at the control
/// rate, with the controller's model M from the hull and D from the hull's linear damping at
/// rest.
///
/// The bias estimate b̂ (5.36) is integrated once per control step with conditional
/// integration: it is frozen while the allocation cannot meet τ_d, so saturated thrust (a large
/// setpoint change, a squall) does not wind it up. With hybrid integral action (the scenario's
/// [hybrid] section, thesis chapter 5) b̂ also jumps by the practical rule (5.64)–(5.67)
/// (hybrid/sampled_integral_jump.hpp), within the controller's anti-windup bound.

#include <Eigen/Core>
#include <optional>

#include "dynpos/control/dp_controller.hpp"
#include "dynpos/control/reference_model.hpp"
#include "dynpos/hybrid/sampled_integral_jump.hpp"
#include "dynpos/model/hull.hpp"
#include "dynpos/scenario/operator_commands.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::scenario {

/// The DP controller's parameters for `vessel`: M = the hull's mass matrix with its sway–yaw
/// coupling made symmetric, D = diag(X_u, Y_v, N_r), gains the defaults (tuned on the virtual
/// Gunnerus) with K_d and K_i scaled by the hull's inertia over the Gunnerus's in each axis and
/// the bias bound by the joystick's maxima over the Gunnerus's (all 1 for the Gunnerus).
control::DpControllerParams dp_controller_params(const VesselConfig& vessel,
                                                 const model::Hull& hull);

/// The demand of one DP control step.
struct DpDemand {
  Eigen::Vector3d tau_b = Eigen::Vector3d::Zero();  ///< τ_d (5.38), BODY [N, N, N·m]
  /// Stationkeeping (reference within 1 % of its rate limits of rest): the allocation holds
  /// the thrusters' split (hold_weight), so it does not switch between its two ways of making a
  /// yaw moment faster than the propellers follow. During a setpoint change the split is free,
  /// as the 4-corner legs need.
  bool hold_split = false;
};

/// The DP loop of a run (see the file comment).
class DpTask {
 public:
  /// The setpoints and hybrid integral action of `spec` on `vessel` (its `hull`), starting at
  /// rest at η₀ (N, E, ψ) [m, m, rad], stepped every control_period_s [s].
  DpTask(const ScenarioSpec& spec, const VesselConfig& vessel, const model::Hull& hull,
         const Eigen::Vector3d& eta0_n, double control_period_s);

  /// The control step at scenario time t [s] at the low-frequency position η (NED) and
  /// velocity ν (BODY): applies the setpoints due, steps the reference, evaluates the control
  /// law and the hybrid jump. Nothing while no setpoint is in force.
  std::optional<DpDemand> control(double t, const Eigen::Vector3d& eta_n,
                                  const Eigen::Vector3d& nu_b);

  /// After the allocation of the same step: b̂ over one control period at heading ψ [rad]
  /// (5.36), unless the allocation did not meet τ_d or no setpoint is in force.
  void integrate_bias(double psi_rad, bool allocation_met);

  bool active() const noexcept { return setpoints_.active(); }
  /// The setpoint in force (N, E, ψ) [m, m, rad]; core::kMissing before the first.
  const Eigen::Vector3d& setpoint_n() const noexcept { return setpoints_.setpoint_n(); }
  /// b̂ (NED) [N, N, N·m].
  const Eigen::Vector3d& bias_hat_n() const noexcept { return bias_hat_n_; }
  const SetpointSchedule& setpoints() const noexcept { return setpoints_; }
  /// The hybrid jump rule, if the scenario has one.
  const std::optional<hybrid::SampledIntegralJump>& jumps() const noexcept { return jumps_; }

 private:
  control::DpControllerParams params_;
  control::DpController controller_;
  control::ReferenceModel reference_;
  SetpointSchedule setpoints_;
  std::optional<hybrid::SampledIntegralJump> jumps_;
  double period_s_;
  Eigen::Vector3d bias_hat_n_ = Eigen::Vector3d::Zero();
  std::optional<Eigen::Vector3d> x2_b_;  // x₂ of this step's control law, for (5.36)
};

}  // namespace dynpos::scenario
