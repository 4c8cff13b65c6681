#include "dynpos/scenario/dp_task.hpp"

namespace dynpos::scenario {

control::DpControllerParams dp_controller_params(const VesselConfig& vessel,
                                                 const model::Hull& hull) {
  control::DpControllerParams p;
  p.M = hull.mass_matrix();
  p.M(1, 2) = p.M(2, 1) = 0.5 * (p.M(1, 2) + p.M(2, 1));
  p.D =
      Eigen::Vector3d(vessel.hull.x_u_Ns_m, vessel.hull.y_v_Ns_m, vessel.hull.n_r_Nms).asDiagonal();
  // The gains are the virtual Gunnerus's; another hull keeps their bandwidths (K_p) and damping
  // ratios with K_d and K_i scaled by its inertia in each axis, and the anti-windup bound by its
  // joystick's force and moment (what its thrusters give there). 1 for the Gunnerus itself.
  const VesselConfig gunnerus;
  const Eigen::Vector3d inertia =
      p.M.diagonal().cwiseQuotient(model::Hull(gunnerus.hull).mass_matrix().diagonal());
  p.Kd.diagonal() = p.Kd.diagonal().cwiseProduct(inertia);
  p.Ki.diagonal() = p.Ki.diagonal().cwiseProduct(inertia);
  const JoystickParams& js = vessel.joystick;
  const JoystickParams& gjs = gunnerus.joystick;
  p.bias_limit = p.bias_limit.cwiseProduct(Eigen::Vector3d(js.max_surge_N / gjs.max_surge_N,
                                                           js.max_sway_N / gjs.max_sway_N,
                                                           js.max_yaw_Nm / gjs.max_yaw_Nm));
  return p;
}

DpTask::DpTask(const ScenarioSpec& spec, const VesselConfig& vessel, const model::Hull& hull,
               const Eigen::Vector3d& eta0_n, double control_period_s)
    : params_(dp_controller_params(vessel, hull)),
      controller_(params_),
      reference_(control::ReferenceModelParams{}, eta0_n),
      setpoints_(spec.setpoints),
      period_s_(control_period_s) {
  if (spec.hybrid_integral) jumps_.emplace(*spec.hybrid_integral, params_, control_period_s);
}

std::optional<DpDemand> DpTask::control(double t, const Eigen::Vector3d& eta_n,
                                        const Eigen::Vector3d& nu_b) {
  x2_b_.reset();
  setpoints_.advance(t, eta_n);
  if (!setpoints_.active()) return std::nullopt;
  reference_.step(setpoints_.setpoint_n(), period_s_);
  const control::DpCommand command =
      controller_.control(eta_n, nu_b, reference_.reference(), bias_hat_n_);
  x2_b_ = command.x2;
  const DpDemand demand{command.tau_b, reference_.at_rest(0.01)};
  if (jumps_) {
    // (5.47), within the controller's anti-windup bound.
    if (const auto jump = jumps_->step(t, command.x1, command.x2, eta_n.z())) {
      bias_hat_n_ =
          (bias_hat_n_ + *jump).cwiseMax(-params_.bias_limit).cwiseMin(params_.bias_limit);
    }
  }
  return demand;
}

void DpTask::integrate_bias(double psi_rad, bool allocation_met) {
  if (x2_b_ && allocation_met) {
    bias_hat_n_ = controller_.advance_bias(bias_hat_n_, psi_rad, *x2_b_, period_s_);
  }
}

}  // namespace dynpos::scenario
