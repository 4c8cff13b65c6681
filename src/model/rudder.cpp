#include "dynpos/model/rudder.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "actuator_checks.hpp"
#include "dynpos/model/delay_line.hpp"
#include "dynpos/sim/rk4.hpp"

namespace dynpos::model {

using detail::clamp_abs;
using detail::kPi;
using detail::require;

void RudderParams::validate() const {
  constexpr const char* o = "RudderParams";
  require(detail::open_range(max_angle, 0.0, kPi / 2), o, "max_angle", max_angle,
          "in (0, pi/2) rad");
  require(detail::open_range(rate_limit, 0.0, 1.0), o, "rate_limit", rate_limit, "in (0, 1) rad/s");
  require(detail::open_range(servo_time_constant, 0.005, 10.0), o, "servo_time_constant",
          servo_time_constant, "in (0.005, 10) s");
  require(detail::half_open_range(dead_time, 0.0, 10.0), o, "dead_time", dead_time, "in [0, 10) s");
  require(detail::open_range(area, 0.0, 50.0), o, "area", area, "in (0, 50) m^2");
  require(detail::open_range(aspect_ratio, 0.2, 10.0), o, "aspect_ratio", aspect_ratio,
          "in (0.2, 10)");
  require(lift_slope > 0.0 && lift_slope <= 2.0 * kPi, o, "lift_slope", lift_slope,
          "in (0, 2*pi] 1/rad");
  require(detail::open_range(stall_angle, 0.0, kPi / 2), o, "stall_angle", stall_angle,
          "in (0, pi/2) rad");
  require(detail::closed_range(post_stall_lift_fraction, 0.0, 1.0), o, "post_stall_lift_fraction",
          post_stall_lift_fraction, "in [0, 1]");
  require(post_stall_width > 0.0 && post_stall_width <= kPi / 2, o, "post_stall_width",
          post_stall_width, "in (0, pi/2] rad");
  require(detail::half_open_range(drag_zero, 0.0, 1.0), o, "drag_zero", drag_zero, "in [0, 1)");
  require(detail::half_open_range(drag_angle, 0.0, 3.0), o, "drag_angle", drag_angle, "in [0, 3)");
  require(detail::closed_range(slipstream_fraction, 0.0, 1.0), o, "slipstream_fraction",
          slipstream_fraction, "in [0, 1]");
  require(detail::open_range(propeller_diameter, 0.0, 10.0), o, "propeller_diameter",
          propeller_diameter, "in (0, 10) m");
  require(detail::closed_range(flow_straightening, 0.0, 1.0), o, "flow_straightening",
          flow_straightening, "in [0, 1]");
  require(detail::closed_range(astern_lift_factor, 0.0, 1.0), o, "astern_lift_factor",
          astern_lift_factor, "in [0, 1]");
  require(detail::open_range(rho, 900.0, 1100.0), o, "rho", rho, "in (900, 1100) kg/m^3");
}

Rudder::Rudder(const RudderParams& params) : params_(params) { params_.validate(); }

double Rudder::angle_rate(double angle, double angle_command) const noexcept {
  const double target = clamp_abs(angle_command, params_.max_angle);
  return clamp_abs((target - angle) / params_.servo_time_constant, params_.rate_limit);
}

double Rudder::lift_coefficient(double a) const noexcept {
  const RudderParams& p = params_;
  const double mag = std::abs(a);
  if (mag <= p.stall_angle) return p.lift_slope * a;
  const double peak = p.lift_slope * p.stall_angle;
  const double frac = std::clamp((mag - p.stall_angle) / p.post_stall_width, 0.0, 1.0);
  return detail::sign(a) * peak * (1.0 - (1.0 - p.post_stall_lift_fraction) * frac);
}

double Rudder::drag_coefficient(double a) const noexcept {
  const double s = std::sin(a);
  return params_.drag_zero + params_.drag_angle * s * s;
}

double Rudder::dynamic_pressure(double axial_speed, double propeller_thrust) const noexcept {
  const RudderParams& p = params_;
  const double d = p.propeller_diameter;
  return 0.5 * p.rho * axial_speed * axial_speed +
         p.slipstream_fraction * 4.0 * std::max(propeller_thrust, 0.0) / (kPi * d * d);
}

RudderForce Rudder::force(double angle, const RudderInflow& inflow) const noexcept {
  const RudderParams& p = params_;
  RudderForce out;
  // Signed axial "momentum" of the flow past the rudder: free stream ½ρu|u| (astern flow
  // negative) plus the slipstream increment η·4T⁺/(πD²) of momentum theory.
  const double d = p.propeller_diameter;
  const double axial_pressure =
      0.5 * p.rho * inflow.u * std::abs(inflow.u) +
      p.slipstream_fraction * 4.0 * std::max(inflow.propeller_thrust, 0.0) / (kPi * d * d);
  const double w_x =
      detail::sign(axial_pressure) * std::sqrt(std::abs(axial_pressure) / (0.5 * p.rho));
  const double w_y = p.flow_straightening * inflow.v;
  const double speed2 = w_x * w_x + w_y * w_y;
  if (!(speed2 > 0.0)) return out;  // no inflow, no force
  const double speed = std::sqrt(speed2);
  // Direction in which the water passes the rudder, in BODY.
  const Eigen::Vector2d e_f(-w_x / speed, -w_y / speed);
  // Chord direction, leading edge to trailing edge; α > 0 puts the trailing edge to starboard.
  const Eigen::Vector2d c(-std::cos(angle), std::sin(angle));
  const double cross = c.x() * e_f.y() - c.y() * e_f.x();
  const double alpha_e = std::atan2(cross, c.dot(e_f));
  double cl = 0.0;
  double cd = 0.0;
  if (std::abs(alpha_e) <= kPi / 2) {
    cl = lift_coefficient(alpha_e);
    cd = drag_coefficient(alpha_e);
  } else {
    // Astern flow: the trailing edge leads; measure the angle from the reversed chord.
    const double a_rev = alpha_e - kPi * detail::sign(alpha_e);
    cl = p.astern_lift_factor * lift_coefficient(a_rev);
    cd = drag_coefficient(a_rev);
  }
  const double q = 0.5 * p.rho * speed2;
  const Eigen::Vector2d n_lift(-e_f.y(), e_f.x());  // lift direction for C_L > 0
  out.angle_of_attack = alpha_e;
  out.dynamic_pressure = q;
  out.lift = q * p.area * cl;
  out.drag = q * p.area * cd;
  out.f_b = out.lift * n_lift + out.drag * e_f;
  return out;
}

double Rudder::max_side_force(double axial_speed, double propeller_thrust) const noexcept {
  const double a_lin = std::min(params_.stall_angle, params_.max_angle);
  const double q = dynamic_pressure(std::max(axial_speed, 0.0), propeller_thrust);
  return q * params_.area * params_.lift_slope * a_lin;
}

double Rudder::angle_for_side_force(double side_force, double axial_speed,
                                    double propeller_thrust) const noexcept {
  const double q = dynamic_pressure(std::max(axial_speed, 0.0), propeller_thrust);
  const double gain = q * params_.area * params_.lift_slope;
  if (!(gain > 0.0)) return 0.0;
  const double a_lin = std::min(params_.stall_angle, params_.max_angle);
  return clamp_abs(-side_force / gain, a_lin);  // F_y = −L = −q·A·C_Lα·α
}

FopdtTruth rudder_step_truth(const Rudder& rudder, double angle_from, double angle_to, double dt) {
  const RudderParams& p = rudder.params();
  const double from = clamp_abs(angle_from, p.max_angle);
  const double to = clamp_abs(angle_to, p.max_angle);
  // Dead time, the rate-limited ramp and ten servo time constants, plus margin.
  const double duration =
      p.dead_time + std::abs(to - from) / p.rate_limit + 10.0 * p.servo_time_constant + 5.0;
  return scalar_step_truth([&](double a, double cmd) { return rudder.angle_rate(a, cmd); }, from,
                           to, p.dead_time, duration, dt);
}

}  // namespace dynpos::model
