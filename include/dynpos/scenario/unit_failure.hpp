#pragma once
/// \file
/// A failure as it happens in a run (ScenarioSpec::failure): at its time the failed units'
/// drives are cut on the vessel itself, every simulator tick from then on (a breaker opens: no
/// dead time), so each shaft runs down with its own dynamics and a steering unit stays where it
/// points. The DP system goes on ordering them until it flags the fault from their feedback,
/// kDetection_s later; its allocation has them at capacity 0 from then on.
///
/// A [[thruster]] layout fails by unit or redundancy group (model/failure_case.hpp); the model's
/// own actuators by name (port, stb, tunnel, rudder.port, rudder.stb). Names joined by "+" fail
/// together (a switchboard feeding several units, e.g. "stb+tunnel").

#include <string>
#include <vector>

#include "dynpos/model/thrust_allocation.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/vessel_config.hpp"
#include "dynpos/sim/hybrid_system.hpp"

namespace dynpos::scenario {

/// The time a DP system takes to flag a tripped unit from its feedback leaving its order [s].
/// Source: reasoned — thruster fault detection compares feedback and order over a few seconds
/// before it alarms and takes the unit out of the allocation.
inline constexpr double kDetection_s = 3.0;

/// One failure of a run (see the file comment).
class UnitFailure {
 public:
  /// `event` on `vessel`; throws core::InputError (option `key`) for a name (or a part of a
  /// "+" name) the vessel does not have.
  UnitFailure(const FailureEvent& event, const VesselConfig& vessel, const char* key = "failure");

  double time_s() const noexcept { return time_s_; }
  const std::string& name() const noexcept { return name_; }
  /// True from the failure time on, at scenario time t [s].
  bool failed_at(double t) const noexcept { return t >= time_s_; }
  /// True from the DP system's flagging of the failure on (kDetection_s after it).
  bool detected_at(double t) const noexcept { return t >= time_s_ + kDetection_s; }
  /// A layout's capacity factor per unit (0 lost, 1 intact); empty for the model's actuators.
  const std::vector<double>& capacity() const noexcept { return capacity_; }
  /// `options` with the model's failed actuator at capacity 0 (unchanged for a layout).
  model::ThrustAllocationOptions allocation(model::ThrustAllocationOptions options) const;
  /// The names of the units lost (layout order, or the model's actuator).
  std::vector<std::string> units(const VesselConfig& vessel) const;

  /// From the failure on (scenario time t [s]): the failed units' shaft speed commands 0 and
  /// their steering commands held at the plant state x's angles, in the held input u.
  void cut(double t, const sim::ConstVectorRef& x, sim::VectorRef u) const;

 private:
  double time_s_;
  std::string name_;
  std::vector<double> capacity_;  // a layout's
  std::vector<int> actuators_;    // the model's (model::actuator_names())
};

}  // namespace dynpos::scenario
