#include "dynpos/capability/feasibility.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "dynpos/core/error.hpp"

namespace dynpos::capability {

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
