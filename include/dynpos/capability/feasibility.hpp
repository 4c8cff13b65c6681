#pragma once
/// \file
/// Feasibility of a thruster layout: how many times a given environmental load the thrusters
/// can hold, intact and with a unit or a redundancy group lost (the calculation behind
/// `capability --loads`).
///
/// For a load τ_env (BODY, the environment's push on the vessel) the thrusters must give
/// −λ·τ_env. Every region of the layout allocation (model/layout_allocator.hpp) is convex and
/// holds the origin, so if λ·τ is held so is every smaller multiple: the largest λ is found by
/// bisection on "the allocation meets −λ·τ_env", to 0.01 % of λ. The units at a limit in the
/// allocation at that λ are the limiting ones.

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dynpos/model/failure_case.hpp"
#include "dynpos/model/layout_allocator.hpp"

namespace dynpos::capability {

/// The largest factor searched; a load held λ_max times is reported as λ_max and `capped`.
inline constexpr double kMaxLoadFactor = 100.0;

/// One row: where the load comes from (for reports) and the load to hold.
struct LoadCase {
  double direction_deg = 0.0;
  Eigen::Vector3d load_b = Eigen::Vector3d::Zero();  ///< (X [N], Y [N], N [N·m]) in BODY
};

/// The factor of one row in one failure case.
struct FeasibilityPoint {
  double direction_deg = 0.0;
  double load_factor = 0.0;           ///< largest λ with −λ·load held, to 0.01 %
  bool capped = false;                ///< held at kMaxLoadFactor: λ is at least that
  std::vector<std::string> limiting;  ///< units at a limit at λ, in layout order
  std::string failure = "none";       ///< "none", a unit's name or "group:NAME"
};

using model::failure_case;
using model::failure_cases;
using model::FailureCase;

/// The largest λ in [0, kMaxLoadFactor] for which holds(λ) (−λ·load_b within the thrusters'
/// limits): kMaxLoadFactor, capped, when that holds; else bisected to 0.01 % (every smaller
/// multiple of a held load is held), and 0 when that multiple is below 10⁻³ of the force and
/// moment scales [N, N·m] — the rounding of "held" is then more than 0.1 % of it: at 10⁻⁴ a load
/// the units cannot hold at all came out at λ = 1.8·10⁻⁴ (a random layout against a linear
/// programme, python/tests/test_feasibility_lp.py).
struct LoadFactor {
  double value = 0.0;
  bool capped = false;
};
LoadFactor largest_load_factor(const std::function<bool(double)>& holds,
                               const Eigen::Vector3d& load_b, double force_scale,
                               double moment_scale);

/// The factor of `load` with the capacities of `failure`. A zero load is held at any factor:
/// kMaxLoadFactor, capped. A factor whose multiple of the load is below 10⁻³ of the
/// allocation's force and moment scales is 0: the load cannot be held at all.
FeasibilityPoint feasibility(const model::LayoutAllocator& allocator, const LoadCase& load,
                             const FailureCase& failure);

/// Per row the smallest factor over every failure case (not the intact one), naming the case.
std::vector<FeasibilityPoint> worst_feasibility(const model::LayoutAllocator& allocator,
                                                const std::vector<LoadCase>& loads);

}  // namespace dynpos::capability
