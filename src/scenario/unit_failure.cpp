#include "dynpos/scenario/unit_failure.hpp"

#include "dynpos/model/failure_case.hpp"
#include "dynpos/scenario/vessel_plant.hpp"

namespace dynpos::scenario {

namespace {

// The parts of "a+b+…".
std::vector<std::string> parts(const std::string& name) {
  std::vector<std::string> out;
  std::size_t from = 0;
  for (std::size_t plus = name.find('+'); plus != std::string::npos; plus = name.find('+', from)) {
    out.push_back(name.substr(from, plus - from));
    from = plus + 1;
  }
  out.push_back(name.substr(from));
  return out;
}

}  // namespace

UnitFailure::UnitFailure(const FailureEvent& event, const VesselConfig& vessel, const char* key)
    : time_s_(event.t_s), name_(event.name) {
  for (const std::string& part : parts(name_)) {
    if (vessel.thrusters.empty()) {
      actuators_.push_back(model::actuator_index(part, key));
      continue;
    }
    const std::vector<double> lost = model::failure_case(vessel.thrusters, part, key).capacity;
    if (capacity_.empty()) capacity_.assign(lost.size(), 1.0);
    for (std::size_t k = 0; k < lost.size(); ++k) capacity_[k] *= lost[k];
  }
}

model::ThrustAllocationOptions UnitFailure::allocation(
    model::ThrustAllocationOptions options) const {
  for (const int a : actuators_) options.capacity(a) = 0.0;
  return options;
}

std::vector<std::string> UnitFailure::units(const VesselConfig& vessel) const {
  std::vector<std::string> out;
  for (const int a : actuators_)
    out.push_back(model::actuator_names()[static_cast<std::size_t>(a)]);
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
  for (const int a : actuators_) {
    switch (a) {
      case 0:
        u[Plant::kCmdPort] = 0.0;
        break;
      case 1:
        u[Plant::kCmdStb] = 0.0;
        break;
      case 2:
        u[Plant::kCmdRudderPort] = x[Plant::kRudderPort];
        break;
      case 3:
        u[Plant::kCmdRudderStb] = x[Plant::kRudderStb];
        break;
      default:
        u[Plant::kCmdTunnel] = 0.0;
        break;
    }
  }
}

}  // namespace dynpos::scenario
