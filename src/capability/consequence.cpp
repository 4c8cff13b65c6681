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

// The largest λ ≤ kMaxLoadFactor with −λ·load in `limits`, to 0.01 % (feasibility()'s rule),
// and the actuators at a limit there.
FeasibilityPoint region_factor(const ThrustLimits& limits, const Eigen::Vector3d& load_b) {
  FeasibilityPoint out;
  const auto held = [&](double lambda) { return attain(limits, -lambda * load_b); };
  std::optional<Attainment> at = held(kMaxLoadFactor);
  if (at) {
    out.load_factor = kMaxLoadFactor;
    out.capped = true;
  } else {
    double lo = 0.0, hi = kMaxLoadFactor;
    at = held(0.0);
    while (hi - lo > 1e-4 * hi) {
      const double mid = 0.5 * (lo + hi);
      if (std::optional<Attainment> a = held(mid)) {
        lo = mid;
        at = std::move(a);
      } else {
        hi = mid;
      }
    }
    // feasibility()'s rule, on the layout allocation's default scales (`capability --loads`
    // on the model's units): a multiple below 10⁻³ of them is nothing held, the bisection
    // having run down to the region's rounding tolerance.
    const model::LayoutAllocationOptions o;
    const double size =
        std::max({std::abs(load_b(0)) / o.force_scale, std::abs(load_b(1)) / o.force_scale,
                  std::abs(load_b(2)) / o.moment_scale});
    out.load_factor = lo * size < 1e-3 ? 0.0 : lo;
  }
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
