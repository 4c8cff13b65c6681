#pragma once
// Parameter tables of the actuator sections of the vessel file.

#include <vector>

#include "dynpos/model/thrust_allocation.hpp"
#include "param_fields.hpp"

namespace dynpos::scenario::detail {

std::vector<ParamField> propeller_fields(model::ThrusterParams& p);
std::vector<ParamField> rudder_fields(model::RudderParams& p);
std::vector<ParamField> tunnel_fields(model::TunnelThrusterParams& p);
std::vector<ParamField> layout_fields(model::ThrustConfigurationParams& p);
std::vector<ParamField> allocation_fields(model::ThrustAllocationOptions& p);

}  // namespace dynpos::scenario::detail
