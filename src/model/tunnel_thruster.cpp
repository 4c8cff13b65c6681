#include "dynpos/model/tunnel_thruster.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "actuator_checks.hpp"
#include "dynpos/model/delay_line.hpp"
#include "dynpos/sim/rk4.hpp"

namespace dynpos::model {

using detail::clamp_abs;
using detail::kPi;

namespace {

// The [tunnel] table: every parameter with its range (core/param_range.hpp).
template <typename P>
std::vector<core::BasicParamField<core::ParamValue<P>>> fields(P& p) {
  return {
      {{"rho_kg_m3", "kg/m³", 900, 1100}, &p.rho},
      {{"diameter_m", "m", 0.1, 5}, &p.diameter},
      {{"kt_starboard", "1", 1e-3, 1}, &p.kt_starboard},
      {{"kt_port", "1", 1e-3, 1}, &p.kt_port},
      {{"kq", "1", 1e-4, 0.5}, &p.kq},
      {{"max_shaft_speed_rps", "rps", 0.1, 100}, &p.max_shaft_speed},
      {{"time_constant_s", "s", 0.005, 20, true}, &p.time_constant},
      {{"rate_limit_rps_per_s", "rps/s", 1e-3, 100}, &p.rate_limit},
      {{"dead_time_s", "s", 0, 20}, &p.dead_time},
      {{"speed_factor_min", "1", 0, 1}, &p.speed_factor_min},
      {{"speed_factor_scale_mps", "m/s", 0.01, 20}, &p.speed_factor_scale},
      {{"x_m", "m", -50, 50, true, true}, &p.x},
  };
}

}  // namespace

std::vector<core::ParamField> param_fields(TunnelThrusterParams& params) { return fields(params); }

void TunnelThrusterParams::validate() const { core::check_ranges("tunnel", fields(*this)); }

TunnelThruster::TunnelThruster(const TunnelThrusterParams& params)
    : params_(params), diameter_pow4_(std::pow(params.diameter, 4)) {
  params_.validate();
}

double TunnelThruster::shaft_acceleration(double n, double n_command) const noexcept {
  const double target = clamp_abs(n_command, params_.max_shaft_speed);
  return clamp_abs((target - n) / params_.time_constant, params_.rate_limit);
}

double TunnelThruster::speed_factor(double surge_speed) const noexcept {
  const double r = surge_speed / params_.speed_factor_scale;
  return params_.speed_factor_min + (1.0 - params_.speed_factor_min) * std::exp(-r * r);
}

double TunnelThruster::thrust_coefficient(double n) const noexcept {
  const double kt = n >= 0.0 ? params_.kt_starboard : params_.kt_port;
  return params_.rho * kt * diameter_pow4_;
}

double TunnelThruster::thrust(double n, double surge_speed) const noexcept {
  return thrust_coefficient(n) * n * std::abs(n) * speed_factor(surge_speed);
}

double TunnelThruster::shaft_speed_for_thrust(double thrust_n, double surge_speed) const noexcept {
  const double bollard = thrust_n / speed_factor(surge_speed);
  const double n =
      detail::sign(bollard) * std::sqrt(std::abs(bollard) / thrust_coefficient(bollard));
  return clamp_abs(n, params_.max_shaft_speed);
}

double TunnelThruster::max_thrust_starboard(double surge_speed) const noexcept {
  return thrust(params_.max_shaft_speed, surge_speed);
}

double TunnelThruster::max_thrust_port(double surge_speed) const noexcept {
  return -thrust(-params_.max_shaft_speed, surge_speed);
}

TunnelThrusterOutput TunnelThruster::outputs(double n, double surge_speed) const noexcept {
  TunnelThrusterOutput out;
  out.shaft_speed = n;
  out.speed_factor = speed_factor(surge_speed);
  out.thrust = thrust_coefficient(n) * n * std::abs(n) * out.speed_factor;
  const double d = params_.diameter;
  const double q = params_.rho * params_.kq * d * d * d * d * d * n * std::abs(n);  // (2.26)
  out.power = 2.0 * kPi * n * q;                                                    // (2.28)
  return out;
}

StepResponse tunnel_step_response(const TunnelThruster& thruster, double n_from, double n_to,
                                  double dt) {
  const TunnelThrusterParams& p = thruster.params();
  const double from = clamp_abs(n_from, p.max_shaft_speed);
  const double to = clamp_abs(n_to, p.max_shaft_speed);
  // Dead time, the rate-limited ramp and ten time constants, plus margin.
  const double duration =
      p.dead_time + std::abs(to - from) / p.rate_limit + 10.0 * p.time_constant + 5.0;
  return scalar_step_response(
      [&](double n, double cmd) { return thruster.shaft_acceleration(n, cmd); }, from, to,
      p.dead_time, duration, dt);
}

FopdtTruth tunnel_step_truth(const TunnelThruster& thruster, double n_from, double n_to,
                             double dt) {
  const StepResponse r = tunnel_step_response(thruster, n_from, n_to, dt);
  return fopdt_two_point(r.t_s, r.y, 0.0).value_or(FopdtTruth{});
}

}  // namespace dynpos::model
