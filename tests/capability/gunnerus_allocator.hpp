#pragma once
// The built-in vessel's allocator, with actuators lost, for the capability tests.

#include <string>
#include <vector>

#include "dynpos/capability/thrust_region.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::capability::testing {

inline model::ThrustAllocator gunnerus_allocator(const std::vector<std::string>& failed = {}) {
  const scenario::VesselConfig v;
  return model::ThrustAllocator(
      model::Thruster(v.propeller), model::Rudder(v.rudder), model::TunnelThruster(v.tunnel),
      model::ThrustConfiguration(v.layout), with_failures(v.allocation, failed));
}

}  // namespace dynpos::capability::testing
