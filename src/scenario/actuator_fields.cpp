// Vessel-file sections of the actuators: [propeller], [rudder], [tunnel], [layout],
// [allocation]. Keys carry their file unit; angles are degrees in the file.

#include "actuator_fields.hpp"

namespace dynpos::scenario::detail {

std::vector<ParamField> propeller_fields(model::ThrusterParams& p) {
  return {
      {"rho_kg_m3", &p.rho, 900, 1100},
      {"diameter_m", &p.diameter, 0.1, 10},
      {"kt_forward", &p.kt_forward, 1e-3, 1},
      {"kt_reverse", &p.kt_reverse, 1e-3, 1},
      {"kq_forward", &p.kq_forward, 1e-4, 0.5},
      {"kq_reverse", &p.kq_reverse, 1e-4, 0.5},
      {"kt_slope", &p.kt_slope, 0, 1},
      {"kq_slope", &p.kq_slope, 0, 0.5},
      {"max_shaft_speed_rps", &p.max_shaft_speed, 0.1, 50},
      {"max_power_W", &p.max_power, 1, 1e8},
      {"max_torque_Nm", &p.max_torque, 1, 1e7},
      {"shaft_inertia_kgm2", &p.shaft_inertia, 1e-3, 1e6},
      {"friction_Nms", &p.friction, 0, 1e5},
      {"motor_time_constant_s", &p.motor_time_constant, 1e-3, 10},
      {"ref_rate_limit_rps_per_s", &p.ref_rate_limit, 1e-3, 100},
      {"ref_time_constant_s", &p.ref_time_constant, 5e-3, 10},
      {"kp_Nms", &p.kp, 1e-3, 1e7},
      {"ki_Nm", &p.ki, 0, 1e8},
      {"dead_time_s", &p.dead_time, 0, 20},
  };
}

std::vector<ParamField> rudder_fields(model::RudderParams& p) {
  return {
      {"max_angle_deg", &p.max_angle, 1, 90, kDegToRad},
      {"rate_limit_deg_per_s", &p.rate_limit, 0.1, 100, kDegToRad},
      {"servo_time_constant_s", &p.servo_time_constant, 1e-3, 10},
      {"dead_time_s", &p.dead_time, 0, 20},
      {"area_m2", &p.area, 0.01, 50},
      {"aspect_ratio", &p.aspect_ratio, 0.1, 10},
      {"lift_slope_per_rad", &p.lift_slope, 0.1, 10},
      {"stall_angle_deg", &p.stall_angle, 1, 60, kDegToRad},
      {"post_stall_lift_fraction", &p.post_stall_lift_fraction, 0, 1},
      {"post_stall_width_deg", &p.post_stall_width, 0.1, 90, kDegToRad},
      {"drag_zero", &p.drag_zero, 0, 1},
      {"drag_angle", &p.drag_angle, 0, 5},
      {"slipstream_fraction", &p.slipstream_fraction, 0, 1},
      {"propeller_diameter_m", &p.propeller_diameter, 0.1, 10},
      {"flow_straightening", &p.flow_straightening, 0, 1},
      {"astern_lift_factor", &p.astern_lift_factor, 0, 1},
      {"rho_kg_m3", &p.rho, 900, 1100},
  };
}

std::vector<ParamField> tunnel_fields(model::TunnelThrusterParams& p) {
  return {
      {"rho_kg_m3", &p.rho, 900, 1100},
      {"diameter_m", &p.diameter, 0.1, 5},
      {"kt_starboard", &p.kt_starboard, 1e-3, 1},
      {"kt_port", &p.kt_port, 1e-3, 1},
      {"kq", &p.kq, 1e-4, 0.5},
      {"max_shaft_speed_rps", &p.max_shaft_speed, 0.1, 100},
      {"time_constant_s", &p.time_constant, 1e-3, 20},
      {"rate_limit_rps_per_s", &p.rate_limit, 1e-3, 100},
      {"dead_time_s", &p.dead_time, 0, 20},
      {"speed_factor_min", &p.speed_factor_min, 0, 1},
      {"speed_factor_scale_mps", &p.speed_factor_scale, 0.01, 20},
      {"x_m", &p.x, -100, 100},
  };
}

std::vector<ParamField> layout_fields(model::ThrustConfigurationParams& p) {
  return {
      {"port_propeller_x_m", &p.p_port_propeller_b.x(), -100, 100},
      {"port_propeller_y_m", &p.p_port_propeller_b.y(), -50, 50},
      {"stb_propeller_x_m", &p.p_stb_propeller_b.x(), -100, 100},
      {"stb_propeller_y_m", &p.p_stb_propeller_b.y(), -50, 50},
      {"port_rudder_x_m", &p.p_port_rudder_b.x(), -100, 100},
      {"port_rudder_y_m", &p.p_port_rudder_b.y(), -50, 50},
      {"stb_rudder_x_m", &p.p_stb_rudder_b.x(), -100, 100},
      {"stb_rudder_y_m", &p.p_stb_rudder_b.y(), -50, 50},
      {"tunnel_x_m", &p.p_tunnel_b.x(), -100, 100},
      {"tunnel_y_m", &p.p_tunnel_b.y(), -50, 50},
  };
}

std::vector<ParamField> allocation_fields(model::ThrustAllocationOptions& p) {
  return {
      {"weight_thrust_port", &p.weights[0], 1e-6, 1e6},
      {"weight_thrust_stb", &p.weights[1], 1e-6, 1e6},
      {"weight_rudder_port", &p.weights[2], 1e-6, 1e6},
      {"weight_rudder_stb", &p.weights[3], 1e-6, 1e6},
      {"weight_tunnel", &p.weights[4], 1e-6, 1e6},
      {"priority_surge", &p.priority[0], 1e-6, 1e6},
      {"priority_sway", &p.priority[1], 1e-6, 1e6},
      {"priority_yaw", &p.priority[2], 1e-6, 1e6},
      {"force_scale_N", &p.force_scale, 1, 1e9},
      {"moment_scale_Nm", &p.moment_scale, 1, 1e10},
      {"max_rudder_angle_deg", &p.max_rudder_angle, 1, 60, kDegToRad},
      {"rate_thrust_port_N_per_s", &p.rate_limits[0], 1, 1e8},
      {"rate_thrust_stb_N_per_s", &p.rate_limits[1], 1, 1e8},
      {"rate_rudder_port_N_per_s", &p.rate_limits[2], 1, 1e8},
      {"rate_rudder_stb_N_per_s", &p.rate_limits[3], 1, 1e8},
      {"rate_tunnel_N_per_s", &p.rate_limits[4], 1, 1e8},
      {"rudder_drag_compensation", &p.rudder_drag_compensation, 0, 1},
      {"hold_weight", &p.hold_weight, 0, 1e3},
  };
}

}  // namespace dynpos::scenario::detail
