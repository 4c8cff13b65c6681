#include "dynpos/capability/feasibility.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "dynpos/core/error.hpp"

namespace dynpos::capability {

std::vector<FailureCase> failure_cases(const std::vector<model::ThrusterUnit>& units) {
  std::vector<FailureCase> out;
  const std::vector<double> intact(units.size(), 1.0);
  out.push_back({"none", intact});
  for (std::size_t k = 0; k < units.size(); ++k) {
    FailureCase c{units[k].name, intact};
    c.capacity[k] = 0.0;
    out.push_back(std::move(c));
  }
  std::vector<std::string> groups;
  for (const model::ThrusterUnit& u : units) {
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

FailureCase failure_case(const std::vector<model::ThrusterUnit>& units, const std::string& name) {
  std::vector<std::string> names;
  for (FailureCase& c : failure_cases(units)) {
    if (c.name == name) return c;
    names.push_back(c.name);
  }
  throw core::InputError::for_option(
      "failure", fmt::format("no unit or group '{}' in the layout", name),
      fmt::format("use worst or one of: {}", fmt::join(names, ", ")));
}

FeasibilityPoint feasibility(const model::LayoutAllocator& allocator, const LoadCase& load,
                             const FailureCase& failure) {
  FeasibilityPoint out;
  out.direction_deg = load.direction_deg;
  out.failure = failure.name;
  const auto held = [&](double lambda) {
    return allocator.allocate(-lambda * load.load_b, failure.capacity);
  };
  model::LayoutAllocation at = held(kMaxLoadFactor);
  if (at.met) {
    out.load_factor = kMaxLoadFactor;
    out.capped = true;
  } else {
    double lo = 0.0, hi = kMaxLoadFactor;
    at = held(0.0);
    while (hi - lo > 1e-4 * hi) {
      const double mid = 0.5 * (lo + hi);
      model::LayoutAllocation a = held(mid);
      if (a.met) {
        lo = mid;
        at = std::move(a);
      } else {
        hi = mid;
      }
    }
    // A multiple so small that the allocation's tolerance of "met" (10⁻⁶ of the force and
    // moment scales) is more than 0.1 % of it is nothing held: at 10⁻⁴ a load the units cannot
    // hold at all came out at λ = 1.8·10⁻⁴ (a random layout against a linear programme,
    // python/tests/test_feasibility_lp.py).
    const auto& o = allocator.options();
    const double size = std::max({std::abs(load.load_b(0)) / o.force_scale,
                                  std::abs(load.load_b(1)) / o.force_scale,
                                  std::abs(load.load_b(2)) / o.moment_scale});
    out.load_factor = lo * size < 1e-3 ? 0.0 : lo;
  }
  for (std::size_t k = 0; k < at.units.size(); ++k) {
    if (at.units[k].at_limit) out.limiting.push_back(allocator.units()[k].name);
  }
  return out;
}

std::vector<FeasibilityPoint> worst_feasibility(const model::LayoutAllocator& allocator,
                                                const std::vector<LoadCase>& loads) {
  const std::vector<FailureCase> cases = failure_cases(allocator.units());
  std::vector<FeasibilityPoint> out;
  for (const LoadCase& load : loads) {
    FeasibilityPoint worst;
    for (std::size_t c = 1; c < cases.size(); ++c) {  // every case but the intact one
      FeasibilityPoint p = feasibility(allocator, load, cases[c]);
      if (c == 1 || p.load_factor < worst.load_factor) worst = std::move(p);
    }
    out.push_back(std::move(worst));
  }
  return out;
}

}  // namespace dynpos::capability
