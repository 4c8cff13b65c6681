#include "dynpos/model/thrust_configuration.hpp"

#include <string>

#include "dynpos/core/error.hpp"

namespace dynpos::model {

namespace {

// The [layout] table: each position with its range (core/param_range.hpp).
template <typename P>
std::vector<core::BasicParamField<core::ParamValue<P>>> fields(P& p) {
  return {
      {{"port_propeller_x_m", "m", -100, 100}, &p.p_port_propeller_b.x()},
      {{"port_propeller_y_m", "m", -50, 50}, &p.p_port_propeller_b.y()},
      {{"stb_propeller_x_m", "m", -100, 100}, &p.p_stb_propeller_b.x()},
      {{"stb_propeller_y_m", "m", -50, 50}, &p.p_stb_propeller_b.y()},
      {{"port_rudder_x_m", "m", -100, 100}, &p.p_port_rudder_b.x()},
      {{"port_rudder_y_m", "m", -50, 50}, &p.p_port_rudder_b.y()},
      {{"stb_rudder_x_m", "m", -100, 100}, &p.p_stb_rudder_b.x()},
      {{"stb_rudder_y_m", "m", -50, 50}, &p.p_stb_rudder_b.y()},
      {{"tunnel_x_m", "m", -100, 100}, &p.p_tunnel_b.x()},
      {{"tunnel_y_m", "m", -50, 50}, &p.p_tunnel_b.y()},
  };
}

void require_layout(bool ok, const char* field, const char* rule) {
  if (!ok) {
    throw core::InputError({},
                           std::string("ThrustConfigurationParams.") + field + ": must " + rule);
  }
}

// Column of B for a force along BODY x at p: (1, 0, −y).
Eigen::Vector3d surge_column(const Eigen::Vector2d& p) { return {1.0, 0.0, -p.y()}; }
// Column of B for a force along BODY y at p: (0, 1, x).
Eigen::Vector3d sway_column(const Eigen::Vector2d& p) { return {0.0, 1.0, p.x()}; }

}  // namespace

std::vector<core::ParamField> param_fields(ThrustConfigurationParams& params) {
  return fields(params);
}

void ThrustConfigurationParams::validate() const {
  core::check_ranges("layout", fields(*this));
  require_layout(p_port_propeller_b.y() < 0.0, "p_port_propeller_b", "have y < 0 (port)");
  require_layout(p_stb_propeller_b.y() > 0.0, "p_stb_propeller_b", "have y > 0 (starboard)");
  require_layout(p_tunnel_b.x() > p_port_rudder_b.x() && p_tunnel_b.x() > p_stb_rudder_b.x(),
                 "p_tunnel_b", "lie forward of both rudders (x larger)");
}

ThrustConfiguration::ThrustConfiguration(const ThrustConfigurationParams& params)
    : params_(params) {
  params_.validate();
  B_.col(kThrustPort) = surge_column(params_.p_port_propeller_b);
  B_.col(kThrustStb) = surge_column(params_.p_stb_propeller_b);
  B_.col(kRudderPort) = sway_column(params_.p_port_rudder_b);
  B_.col(kRudderStb) = sway_column(params_.p_stb_rudder_b);
  B_.col(kTunnel) = sway_column(params_.p_tunnel_b);
}

Eigen::Vector3d ThrustConfiguration::tau(const ActuatorForces& f) const noexcept {
  const auto wrench = [](const Eigen::Vector2d& p, const Eigen::Vector2d& force) {
    return Eigen::Vector3d(force.x(), force.y(), p.x() * force.y() - p.y() * force.x());
  };
  const ThrustConfigurationParams& p = params_;
  Eigen::Vector3d tau_b = wrench(p.p_port_propeller_b, {f.thrust_port, 0.0});
  tau_b += wrench(p.p_stb_propeller_b, {f.thrust_stb, 0.0});
  tau_b += wrench(p.p_port_rudder_b, f.rudder_port_b);
  tau_b += wrench(p.p_stb_rudder_b, f.rudder_stb_b);
  tau_b += wrench(p.p_tunnel_b, {0.0, f.tunnel});
  return tau_b;
}

Eigen::Vector2d ThrustConfiguration::velocity_at(const Eigen::Vector3d& nu_b,
                                                 const Eigen::Vector2d& p_b) noexcept {
  // v_p = v + ω × p with ω = r·ẑ: (u − r·y, v + r·x).
  return {nu_b.x() - nu_b.z() * p_b.y(), nu_b.y() + nu_b.z() * p_b.x()};
}

}  // namespace dynpos::model
