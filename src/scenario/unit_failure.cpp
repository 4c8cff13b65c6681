#include "dynpos/scenario/unit_failure.hpp"

#include "dynpos/model/failure_case.hpp"
#include "dynpos/scenario/vessel_plant.hpp"

namespace dynpos::scenario {

UnitFailure::UnitFailure(const FailureEvent& event, const VesselConfig& vessel, const char* key)
    : time_s_(event.t_s), name_(event.name) {
  if (vessel.thrusters.empty()) {
    actuator_ = model::actuator_index(name_, key);
  } else {
    capacity_ = model::failure_case(vessel.thrusters, name_, key).capacity;
  }
}

model::ThrustAllocationOptions UnitFailure::allocation(
    model::ThrustAllocationOptions options) const {
  if (actuator_ >= 0) options.capacity(actuator_) = 0.0;
  return options;
}

std::vector<std::string> UnitFailure::units(const VesselConfig& vessel) const {
  if (actuator_ >= 0) return {model::actuator_names()[static_cast<std::size_t>(actuator_)]};
  std::vector<std::string> out;
  for (std::size_t k = 0; k < capacity_.size(); ++k) {
    if (capacity_[k] == 0.0) out.push_back(vessel.thrusters[k].name);
  }
  return out;
}

void UnitFailure::cut(double t, const sim::ConstVectorRef& x, sim::VectorRef u) const {
  using Plant = VesselPlant;
  if (!failed_at(t)) return;
  for (std::size_t k = 0; k < capacity_.size(); ++k) {
    if (capacity_[k] != 0.0) continue;
    const Eigen::Index i = 2 * static_cast<Eigen::Index>(k);
    u[Plant::kCmdUnits + i] = 0.0;
    u[Plant::kCmdUnits + i + 1] = x[Plant::kUnits + i + 1];
  }
  switch (actuator_) {
    case 0: u[Plant::kCmdPort] = 0.0; break;
    case 1: u[Plant::kCmdStb] = 0.0; break;
    case 2: u[Plant::kCmdRudderPort] = x[Plant::kRudderPort]; break;
    case 3: u[Plant::kCmdRudderStb] = x[Plant::kRudderStb]; break;
    case 4: u[Plant::kCmdTunnel] = 0.0; break;
    default: break;
  }
}

}  // namespace dynpos::scenario
