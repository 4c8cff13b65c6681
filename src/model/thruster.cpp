#include "dynpos/model/thruster.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "actuator_checks.hpp"
#include "dynpos/model/delay_line.hpp"
#include "dynpos/sim/rk4.hpp"

namespace dynpos::model {

using detail::clamp_abs;
using detail::kPi;

namespace {

// The [propeller] table: every parameter with its range (core/param_range.hpp).
template <typename P>
std::vector<core::BasicParamField<core::ParamValue<P>>> fields(P& p) {
  return {
      {{"rho_kg_m3", "kg/m³", 900, 1100}, &p.rho},
      {{"diameter_m", "m", 0.1, 10}, &p.diameter},
      {{"kt_forward", "1", 1e-3, 1}, &p.kt_forward},
      {{"kt_reverse", "1", 1e-3, 1}, &p.kt_reverse},
      {{"kq_forward", "1", 1e-4, 0.5}, &p.kq_forward},
      {{"kq_reverse", "1", 1e-4, 0.5}, &p.kq_reverse},
      {{"kt_slope", "1", 0, 1}, &p.kt_slope},
      {{"kq_slope", "1", 0, 0.5}, &p.kq_slope},
      {{"max_shaft_speed_rps", "rps", 0.1, 50}, &p.max_shaft_speed},
      {{"max_power_W", "W", 1, 1e8}, &p.max_power},
      {{"max_torque_Nm", "N·m", 1, 1e7}, &p.max_torque},
      {{"shaft_inertia_kgm2", "kg·m²", 1e-3, 1e6}, &p.shaft_inertia},
      {{"friction_Nms", "N·m·s", 0, 1e5}, &p.friction},
      {{"motor_time_constant_s", "s", 1e-3, 10}, &p.motor_time_constant},
      {{"ref_rate_limit_rps_per_s", "rps/s", 1e-3, 100}, &p.ref_rate_limit},
      {{"ref_time_constant_s", "s", 5e-3, 10}, &p.ref_time_constant},
      {{"kp_Nms", "N·m·s", 1e-3, 1e7}, &p.kp},
      {{"ki_Nm", "N·m", 0, 1e8}, &p.ki},
      {{"dead_time_s", "s", 0, 20}, &p.dead_time},
  };
}

}  // namespace

std::vector<core::ParamField> param_fields(ThrusterParams& params) { return fields(params); }

void ThrusterParams::validate() const { core::check_ranges("propeller", fields(*this)); }

Thruster::Thruster(const ThrusterParams& params)
    : params_(params), diameter_pow4_(std::pow(params.diameter, 4)) {
  params_.validate();
}

double Thruster::thrust_coefficient(double n) const noexcept {
  const double kt = n >= 0.0 ? params_.kt_forward : params_.kt_reverse;
  return params_.rho * kt * diameter_pow4_;
}

double Thruster::thrust(double n, double advance_speed) const noexcept {
  // sign(n)ρD⁴n²(K_T0 − k_T·V_a/(|n|D)) = ρD⁴K_T0·n|n| − ρD³k_T·V_a·n: no division by n.
  const double d = params_.diameter;
  return thrust_coefficient(n) * n * std::abs(n) -
         params_.rho * d * d * d * params_.kt_slope * advance_speed * n;
}

double Thruster::torque(double n, double advance_speed) const noexcept {
  const double d = params_.diameter;
  const double kq = n >= 0.0 ? params_.kq_forward : params_.kq_reverse;
  const double d4 = d * d * d * d;
  return params_.rho * kq * d4 * d * n * std::abs(n) -
         params_.rho * d4 * params_.kq_slope * advance_speed * n;
}

double Thruster::power(double n, double advance_speed) const noexcept {
  return 2.0 * kPi * n * torque(n, advance_speed);
}

double Thruster::shaft_speed_for_thrust(double thrust_n) const noexcept {
  const double n =
      detail::sign(thrust_n) * std::sqrt(std::abs(thrust_n) / thrust_coefficient(thrust_n));
  return clamp_abs(n, params_.max_shaft_speed);
}

double Thruster::max_thrust_forward() const noexcept {
  return thrust_coefficient(1.0) * params_.max_shaft_speed * params_.max_shaft_speed;
}

double Thruster::max_thrust_reverse() const noexcept {
  return thrust_coefficient(-1.0) * params_.max_shaft_speed * params_.max_shaft_speed;
}

Thruster::State Thruster::steady_state(double n, double advance_speed) const noexcept {
  const double nc = clamp_abs(n, params_.max_shaft_speed);
  const double omega = 2.0 * kPi * nc;
  State x;
  x[kNRef] = nc;
  x[kIntegral] = 0.0;  // the feedforward carries the whole steady torque
  x[kMotorTorque] = torque(nc, advance_speed) + params_.friction * omega;
  x[kOmega] = omega;
  return x;
}

Thruster::State Thruster::derivatives(const State& x, const ThrusterInput& u) const noexcept {
  const ThrusterParams& p = params_;
  const double n_c = clamp_abs(u.n_command, p.max_shaft_speed);
  const double n_ref = x[kNRef];
  const double omega = x[kOmega];

  // Reference generator: a first-order filter inside a rate limit.
  const double n_ref_dot = clamp_abs((n_c - n_ref) / p.ref_time_constant, p.ref_rate_limit);
  const double omega_ref = 2.0 * kPi * n_ref;
  const double omega_ref_dot = 2.0 * kPi * n_ref_dot;

  // Core PI controller on ω with friction, load and inertia feedforward (Sørensen 2012).
  const double error = omega_ref - omega;
  const double q_ff =
      p.friction * omega_ref + torque(n_ref, u.advance_speed) + p.shaft_inertia * omega_ref_dot;
  const double q_unsat = q_ff + p.kp * error + p.ki * x[kIntegral];
  const double q_limit = std::min(p.max_torque, p.max_power / std::max(std::abs(omega), 1e-9));
  const double q_c = clamp_abs(q_unsat, q_limit);
  // Conditional integration: hold the integral while the error drives further into saturation.
  const bool windup = (q_unsat != q_c) && (error * (q_unsat - q_c) > 0.0);

  const double n = omega / (2.0 * kPi);
  State dx;
  dx[kNRef] = n_ref_dot;
  dx[kIntegral] = windup ? 0.0 : error;
  dx[kMotorTorque] = (q_c - x[kMotorTorque]) / p.motor_time_constant;  // (2.23), stable form
  dx[kOmega] = (x[kMotorTorque] - torque(n, u.advance_speed) - p.friction * omega) /
               p.shaft_inertia;  // (2.24)
  return dx;
}

ThrusterOutput Thruster::outputs(const State& x, double advance_speed) const noexcept {
  ThrusterOutput out;
  out.shaft_speed = x[kOmega] / (2.0 * kPi);
  out.thrust = thrust(out.shaft_speed, advance_speed);
  out.load_torque = torque(out.shaft_speed, advance_speed);
  out.power = 2.0 * kPi * out.shaft_speed * out.load_torque;
  out.motor_torque = x[kMotorTorque];
  return out;
}

ThrusterStepResponse thruster_step_response(const Thruster& thruster, double n_from, double n_to,
                                            double dt) {
  const ThrusterParams& p = thruster.params();
  const double from = clamp_abs(n_from, p.max_shaft_speed);
  const double to = clamp_abs(n_to, p.max_shaft_speed);
  // Long enough for the dead time, the ramp and ten reference/loop time constants to settle.
  const double duration =
      p.dead_time + std::abs(to - from) / p.ref_rate_limit + 10.0 * p.ref_time_constant + 15.0;
  const auto steps = static_cast<std::size_t>(std::ceil(duration / dt));

  DelayLine line(p.dead_time, dt, from);
  sim::Rk4<4> rk4;
  Thruster::State x = thruster.steady_state(from);
  ThrusterStepResponse r;
  for (StepResponse* s : {&r.shaft_speed, &r.thrust}) {
    s->t_s.resize(steps + 1);
    s->y.resize(steps + 1);
  }
  for (std::size_t k = 0; k <= steps; ++k) {
    const double tk = static_cast<double>(k) * dt;
    const ThrusterOutput y = thruster.outputs(x);
    r.shaft_speed.t_s[k] = r.thrust.t_s[k] = tk;
    r.shaft_speed.y[k] = y.shaft_speed;
    r.thrust.y[k] = y.thrust;
    const ThrusterInput u{line.push(to), 0.0};
    rk4.step([&](double, const Thruster::State& xs,
                 Thruster::State& dxs) { dxs = thruster.derivatives(xs, u); },
             tk, dt, x, x);
  }
  return r;
}

ThrusterStepTruth thruster_step_truth(const Thruster& thruster, double n_from, double n_to,
                                      double dt) {
  const ThrusterStepResponse r = thruster_step_response(thruster, n_from, n_to, dt);
  ThrusterStepTruth truth;
  truth.shaft_speed =
      fopdt_two_point(r.shaft_speed.t_s, r.shaft_speed.y, 0.0).value_or(FopdtTruth{});
  truth.thrust = fopdt_two_point(r.thrust.t_s, r.thrust.y, 0.0).value_or(FopdtTruth{});
  return truth;
}

void FirstOrderThrusterParams::validate() const {
  const double* v[] = {&time_constant, &dead_time, &max_thrust_forward, &max_thrust_reverse};
  core::check_ranges(
      "FirstOrderThrusterParams",
      std::vector<core::ConstParamField>{{{"time_constant", "s", 0.005, 100, true, true}, v[0]},
                                         {{"dead_time", "s", 0, 20, false, true}, v[1]},
                                         {{"max_thrust_forward", "N", 0, 1e8, true, true}, v[2]},
                                         {{"max_thrust_reverse", "N", 0, 1e8, true, true}, v[3]}});
}

FirstOrderThruster::FirstOrderThruster(const FirstOrderThrusterParams& params) : params_(params) {
  params_.validate();
}

double FirstOrderThruster::derivative(double thrust, double thrust_command) const noexcept {
  const double tc =
      std::clamp(thrust_command, -params_.max_thrust_reverse, params_.max_thrust_forward);
  return (tc - thrust) / params_.time_constant;  // (2.29)
}

}  // namespace dynpos::model
