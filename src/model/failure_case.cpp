#include "dynpos/model/failure_case.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "dynpos/core/error.hpp"

namespace dynpos::model {

std::vector<FailureCase> failure_cases(const std::vector<ThrusterUnit>& units) {
  std::vector<FailureCase> out;
  const std::vector<double> intact(units.size(), 1.0);
  out.push_back({"none", intact});
  for (std::size_t k = 0; k < units.size(); ++k) {
    FailureCase c{units[k].name, intact};
    c.capacity[k] = 0.0;
    out.push_back(std::move(c));
  }
  std::vector<std::string> groups;
  for (const ThrusterUnit& u : units) {
    if (!u.group.empty() && std::find(groups.begin(), groups.end(), u.group) == groups.end()) {
      groups.push_back(u.group);
    }
  }
  for (const std::string& g : groups) {
    FailureCase c{"group:" + g, intact};
    for (std::size_t k = 0; k < units.size(); ++k) {
      if (units[k].group == g) c.capacity[k] = 0.0;
    }
    out.push_back(std::move(c));
  }
  return out;
}

FailureCase failure_case(const std::vector<ThrusterUnit>& units, const std::string& name,
                         const char* option) {
  std::vector<std::string> names;
  for (FailureCase& c : failure_cases(units)) {
    if (c.name == name) return c;
    names.push_back(c.name);
  }
  throw core::InputError::for_option(
      option, fmt::format("no unit or group '{}' in the layout", name),
      fmt::format("use worst or one of: {}", fmt::join(names, ", ")));
}

const std::array<std::string, 5>& actuator_names() {
  static const std::array<std::string, 5> names = {"port", "stb", "rudder.port", "rudder.stb",
                                                   "tunnel"};
  return names;
}

int actuator_index(const std::string& name, const char* option) {
  const auto& names = actuator_names();
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) {
    throw core::InputError::for_option(option, "unknown actuator '" + name + "'",
                                       "name one of port, stb, rudder.port, rudder.stb, "
                                       "tunnel, or worst or none");
  }
  return static_cast<int>(it - names.begin());
}

ThrustAllocationOptions with_failures(ThrustAllocationOptions vessel_allocation,
                                      const std::vector<std::string>& failed) {
  for (const std::string& name : failed) vessel_allocation.capacity(actuator_index(name)) = 0.0;
  return vessel_allocation;
}

}  // namespace dynpos::model
