#include "dynpos/capability/feasibility.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "dynpos/core/error.hpp"

namespace dynpos::capability {

LoadFactor largest_load_factor(const std::function<bool(double)>& holds,
                               const Eigen::Vector3d& load_b, double force_scale,
                               double moment_scale) {
  if (holds(kMaxLoadFactor)) return {kMaxLoadFactor, true};
  (void)holds(0.0);  // the callers' last held result is at least the calm's
  double lo = 0.0, hi = kMaxLoadFactor;
  while (hi - lo > 1e-4 * hi) {
    const double mid = 0.5 * (lo + hi);
    (holds(mid) ? lo : hi) = mid;
  }
  const double size =
      std::max({std::abs(load_b(0)) / force_scale, std::abs(load_b(1)) / force_scale,
                std::abs(load_b(2)) / moment_scale});
  return {lo * size < 1e-3 ? 0.0 : lo, false};
}

FeasibilityPoint feasibility(const model::LayoutAllocator& allocator, const LoadCase& load,
                             const FailureCase& failure) {
  FeasibilityPoint out;
  out.direction_deg = load.direction_deg;
  out.failure = failure.name;
  model::LayoutAllocation at;  // the allocation at the largest factor held
  const auto holds = [&](double lambda) {
    model::LayoutAllocation a = allocator.allocate(-lambda * load.load_b, failure.capacity);
    const bool met = a.met;
    if (met) at = std::move(a);
    return met;
  };
  const auto& o = allocator.options();
  const LoadFactor f = largest_load_factor(holds, load.load_b, o.force_scale, o.moment_scale);
  out.load_factor = f.value;
  out.capped = f.capped;
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
