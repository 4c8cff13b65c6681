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

namespace {

constexpr double kDegToRad = kPi / 180.0;

// The [rudder] table: every parameter with its range (core/param_range.hpp); angles in degrees.
template <typename P>
std::vector<core::BasicParamField<core::ParamValue<P>>> fields(P& p) {
  return {
      {{"max_angle_deg", "deg", 1, 90, false, false, kDegToRad}, &p.max_angle},
      // The servo rate below 1 rad/s.
      {{"rate_limit_deg_per_s", "deg/s", 0.1, 1.0 / kDegToRad, false, true, kDegToRad},
       &p.rate_limit},
      {{"servo_time_constant_s", "s", 0.005, 10, true}, &p.servo_time_constant},
      {{"dead_time_s", "s", 0, 10, false, true}, &p.dead_time},
      {{"area_m2", "m²", 0.01, 50}, &p.area},
      {{"aspect_ratio", "1", 0.2, 10, true}, &p.aspect_ratio},
      {{"lift_slope_per_rad", "1/rad", 0.1, 2.0 * kPi}, &p.lift_slope},
      {{"stall_angle_deg", "deg", 1, 60, false, false, kDegToRad}, &p.stall_angle},
      {{"post_stall_lift_fraction", "1", 0, 1}, &p.post_stall_lift_fraction},
      {{"post_stall_width_deg", "deg", 0.1, 90, false, false, kDegToRad}, &p.post_stall_width},
      {{"drag_zero", "1", 0, 1}, &p.drag_zero},
      {{"drag_angle", "1", 0, 3, false, true}, &p.drag_angle},
      {{"slipstream_fraction", "1", 0, 1}, &p.slipstream_fraction},
      {{"propeller_diameter_m", "m", 0.1, 10}, &p.propeller_diameter},
      {{"flow_straightening", "1", 0, 1}, &p.flow_straightening},
      {{"astern_lift_factor", "1", 0, 1}, &p.astern_lift_factor},
      {{"rho_kg_m3", "kg/m³", 900, 1100}, &p.rho},
  };
}

}  // namespace

std::vector<core::ParamField> param_fields(RudderParams& params) { return fields(params); }

void RudderParams::validate() const { core::check_ranges("rudder", fields(*this)); }

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
