#include "dynpos/capability/vessel_units.hpp"

#include "dynpos/capability/thrust_region.hpp"

namespace dynpos::capability {

std::vector<model::ThrusterUnit> gunnerus_units(const model::ThrustAllocator& allocator,
                                                double surge_speed_mps) {
  const ThrustLimits limits = thrust_limits(allocator, surge_speed_mps);
  const auto& p = allocator.configuration().params();
  std::vector<model::ThrusterUnit> out;
  const Eigen::Vector2d props[2] = {p.p_port_propeller_b, p.p_stb_propeller_b};
  const Eigen::Vector2d rudders[2] = {p.p_port_rudder_b, p.p_stb_rudder_b};
  const char* names[2] = {"port", "stb"};
  for (int k = 0; k < 2; ++k) {
    model::ThrusterUnit u;
    u.name = names[k];
    u.type = model::UnitType::kPropellerRudder;
    u.x_m = props[k].x();
    u.y_m = props[k].y();
    u.max_thrust_N = limits.hi_N(k);
    u.max_reverse_thrust_N = -limits.lo_N(k);
    u.rudder_lift_per_thrust = limits.cone.kappa;
    u.rudder_lift_at_zero_N = limits.cone.c_N;
    u.rudder_max_force_N = limits.hi_N(2 + k);
    u.rudder_x_m = rudders[k].x();
    out.push_back(u);
  }
  model::ThrusterUnit tunnel;
  tunnel.name = "tunnel";
  tunnel.type = model::UnitType::kTunnel;
  tunnel.x_m = p.p_tunnel_b.x();
  tunnel.y_m = p.p_tunnel_b.y();
  tunnel.max_thrust_N = limits.hi_N(4);
  tunnel.max_reverse_thrust_N = -limits.lo_N(4);
  out.push_back(tunnel);
  return out;
}

}  // namespace dynpos::capability
