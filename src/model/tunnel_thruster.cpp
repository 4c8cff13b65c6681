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
using detail::require;

void TunnelThrusterParams::validate() const {
  constexpr const char* o = "TunnelThrusterParams";
  require(detail::open_range(rho, 900.0, 1100.0), o, "rho", rho, "in (900, 1100) kg/m^3");
  require(detail::open_range(diameter, 0.0, 5.0), o, "diameter", diameter, "in (0, 5) m");
  require(detail::open_range(kt_starboard, 0.0, 1.0), o, "kt_starboard", kt_starboard, "in (0, 1)");
  require(detail::open_range(kt_port, 0.0, 1.0), o, "kt_port", kt_port, "in (0, 1)");
  require(detail::open_range(kq, 0.0, 0.5), o, "kq", kq, "in (0, 0.5)");
  require(detail::open_range(max_shaft_speed, 0.0, 100.0), o, "max_shaft_speed", max_shaft_speed,
          "in (0, 100) rps");
  require(detail::open_range(time_constant, 0.005, 20.0), o, "time_constant", time_constant,
          "in (0.005, 20) s");
  require(detail::open_range(rate_limit, 0.0, 100.0), o, "rate_limit", rate_limit,
          "in (0, 100) rps/s");
  require(detail::half_open_range(dead_time, 0.0, 20.0), o, "dead_time", dead_time, "in [0, 20) s");
  require(detail::closed_range(speed_factor_min, 0.0, 1.0), o, "speed_factor_min", speed_factor_min,
          "in [0, 1]");
  require(detail::open_range(speed_factor_scale, 0.0, 20.0), o, "speed_factor_scale",
          speed_factor_scale, "in (0, 20) m/s");
  require(detail::open_range(x, -50.0, 50.0), o, "x", x, "in (-50, 50) m");
}

TunnelThruster::TunnelThruster(const TunnelThrusterParams& params) : params_(params) {
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
  return params_.rho * kt * std::pow(params_.diameter, 4);
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

FopdtTruth tunnel_step_truth(const TunnelThruster& thruster, double n_from, double n_to,
                             double dt) {
  const TunnelThrusterParams& p = thruster.params();
  const double from = clamp_abs(n_from, p.max_shaft_speed);
  const double to = clamp_abs(n_to, p.max_shaft_speed);
  // Dead time, the rate-limited ramp and ten time constants, plus margin.
  const double duration =
      p.dead_time + std::abs(to - from) / p.rate_limit + 10.0 * p.time_constant + 5.0;
  return scalar_step_truth(
      [&](double n, double cmd) { return thruster.shaft_acceleration(n, cmd); }, from, to,
      p.dead_time, duration, dt);
}

}  // namespace dynpos::model
