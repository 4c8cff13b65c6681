#include "dynpos/capability/consequence.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dynpos/capability/quasi_static.hpp"

namespace dynpos::capability {
namespace {

// The model's exact region with the actuators `failed` lost, at rest (Level 1).
ThrustLimits model_limits(const scenario::VesselConfig& v, const std::vector<std::string>& failed) {
  const model::ThrustAllocator allocator(
      model::Thruster(v.propeller), model::Rudder(v.rudder), model::TunnelThruster(v.tunnel),
      model::ThrustConfiguration(v.layout), with_failures(v.allocation, failed));
  return thrust_limits(allocator, 0.0);
}

// The largest λ with −λ·load in `limits` (largest_load_factor(), on the layout allocation's
// default scales, as `capability --loads` has the model's units), and the actuators at a limit
// there.
FeasibilityPoint region_factor(const ThrustLimits& limits, const Eigen::Vector3d& load_b) {
  FeasibilityPoint out;
  std::optional<Attainment> at;  // at the largest factor held
  const auto holds = [&](double lambda) {
    std::optional<Attainment> a = attain(limits, -lambda * load_b);
    const bool met = a.has_value();
    if (met) at = std::move(a);
    return met;
  };
  const model::LayoutAllocationOptions o;
  const LoadFactor f = largest_load_factor(holds, load_b, o.force_scale, o.moment_scale);
  out.load_factor = f.value;
  out.capped = f.capped;
  for (std::size_t k = 0; at && k < at->at_limit.size(); ++k) {
    if (at->at_limit[k]) out.limiting.push_back(actuator_names()[k]);
  }
  return out;
}

}  // namespace

FailureConsequence::FailureConsequence(const scenario::VesselConfig& vessel)
    : cases_(single_failures(vessel)) {
  if (!vessel.thrusters.empty()) {
    allocator_.emplace(vessel.thrusters);
    layout_cases_ = failure_cases(vessel.thrusters);
    return;
  }
  model_limits_.push_back(model_limits(vessel, {}));
  for (const std::string& name : cases_) model_limits_.push_back(model_limits(vessel, {name}));
}

FeasibilityPoint FailureConsequence::factor(const Eigen::Vector3d& load_b, std::size_t c) const {
  if (allocator_) return feasibility(*allocator_, {0.0, load_b}, layout_cases_[c]);
  FeasibilityPoint p = region_factor(model_limits_[c], load_b);
  p.failure = c == 0 ? "none" : cases_[c - 1];
  return p;
}

FeasibilityPoint FailureConsequence::load_factor(const Eigen::Vector3d& load_b,
                                                 std::size_t k) const {
  if (k >= cases_.size()) throw std::out_of_range("FailureConsequence: no such failure case");
  return factor(load_b, k + 1);
}

std::vector<FeasibilityPoint> FailureConsequence::load_factors(
    const Eigen::Vector3d& load_b) const {
  std::vector<FeasibilityPoint> out;
  for (std::size_t k = 0; k < cases_.size(); ++k) out.push_back(factor(load_b, k + 1));
  return out;
}

FeasibilityPoint FailureConsequence::worst(const Eigen::Vector3d& load_b) const {
  std::vector<FeasibilityPoint> all = load_factors(load_b);
  std::size_t w = 0;
  for (std::size_t k = 1; k < all.size(); ++k) {
    if (all[k].load_factor < all[w].load_factor) w = k;
  }
  return all.at(w);
}

FeasibilityPoint FailureConsequence::intact(const Eigen::Vector3d& load_b) const {
  return factor(load_b, 0);
}

}  // namespace dynpos::capability
