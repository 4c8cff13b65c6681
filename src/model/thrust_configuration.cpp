#include "dynpos/model/thrust_configuration.hpp"

#include <stdexcept>
#include <string>

namespace dynpos::model {

namespace {

void require_finite(const Eigen::Vector2d& p, const char* field) {
  if (!p.allFinite()) {
    throw std::invalid_argument(std::string("ThrustConfigurationParams.") + field +
                                ": must be finite");
  }
}

void require_layout(bool ok, const char* field, const char* rule) {
  if (!ok) {
    throw std::invalid_argument(std::string("ThrustConfigurationParams.") + field + ": must " +
                                rule);
  }
}

// Column of B for a force along BODY x at p: (1, 0, −y).
Eigen::Vector3d surge_column(const Eigen::Vector2d& p) { return {1.0, 0.0, -p.y()}; }
// Column of B for a force along BODY y at p: (0, 1, x).
Eigen::Vector3d sway_column(const Eigen::Vector2d& p) { return {0.0, 1.0, p.x()}; }

}  // namespace

void ThrustConfigurationParams::validate() const {
  require_finite(p_port_propeller_b, "p_port_propeller_b");
  require_finite(p_stb_propeller_b, "p_stb_propeller_b");
  require_finite(p_port_rudder_b, "p_port_rudder_b");
  require_finite(p_stb_rudder_b, "p_stb_rudder_b");
  require_finite(p_tunnel_b, "p_tunnel_b");
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
