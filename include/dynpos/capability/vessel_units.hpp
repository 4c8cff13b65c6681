#pragma once
/// \file
/// The thruster units of a vessel model, for the allocation of any layout
/// (model/layout_allocator.hpp): the 2014 Gunnerus's two propellers with rudders and its tunnel,
/// with the limits the capability analysis gives them (thrust_region.hpp).

#include <vector>

#include "dynpos/model/thrust_allocation.hpp"
#include "dynpos/model/thruster_unit.hpp"

namespace dynpos::capability {

/// The units "port", "stb" (propellers with rudders) and "tunnel" of an intact `allocator` (every
/// capacity 1: failures are the layout allocation's capacities) at surge inflow speed u [m/s],
/// rated as thrust_limits(allocator, u) has them, each rudder's cone and largest force from its
/// model.
std::vector<model::ThrusterUnit> gunnerus_units(const model::ThrustAllocator& allocator,
                                                double surge_speed_mps = 0.0);

}  // namespace dynpos::capability
