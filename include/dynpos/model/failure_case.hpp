#pragma once
/// \file
/// Failure cases: which thrust capacity a failure leaves. A [[thruster]] layout fails by unit or
/// by redundancy group (units sharing a non-empty `group`: a switchboard, an engine room); the
/// model's own actuators by name (actuator_names()). The capability analyses and the simulator's
/// failures as they happen read the same cases.

#include <array>
#include <string>
#include <vector>

#include "dynpos/model/thrust_allocation.hpp"
#include "dynpos/model/thruster_unit.hpp"

namespace dynpos::model {

/// A failure case: its name and each unit's capacity (0 lost, 1 as rated).
struct FailureCase {
  std::string name;
  std::vector<double> capacity;
};

/// The intact case, then each unit alone, then each redundancy group (units sharing a non-empty
/// `group`), in layout order.
std::vector<FailureCase> failure_cases(const std::vector<ThrusterUnit>& units);

/// The case named `name` ("none", a unit's name or "group:NAME"); throws core::InputError
/// (option `option`, default "failure") naming the cases for an unknown one.
FailureCase failure_case(const std::vector<ThrusterUnit>& units, const std::string& name,
                         const char* option = "failure");

/// The model's allocation variables' names in the order of f: "port", "stb", "rudder.port",
/// "rudder.stb", "tunnel".
const std::array<std::string, 5>& actuator_names();

/// The index of the model's actuator `name` in actuator_names(); throws core::InputError
/// (option `option`) for an unknown name.
int actuator_index(const std::string& name, const char* option = "failure");

/// `vessel_allocation` with the actuators named in `failed` (actuator_names()) lost: capacity 0.
/// Throws core::InputError (option "failure") for an unknown name.
ThrustAllocationOptions with_failures(ThrustAllocationOptions vessel_allocation,
                                      const std::vector<std::string>& failed);

}  // namespace dynpos::model
