#pragma once
/// \file
/// The consequence of a single failure against a load: the largest factor λ of an environmental
/// load τ_env (BODY, the environment's push on the vessel) that the thrusters left after each
/// single failure still hold, i.e. for which they give −λ·τ_env. λ < 1: had that failure
/// happened under this load, the vessel would have lost position (the quasi-static balance of
/// quasi_static.hpp, on a given load rather than a weather table).
///
/// The cases are single_failures(vessel). A [[thruster]] layout is balanced by its allocation
/// (feasibility(), to 0.01 % of λ). The model's own actuators (the 2014 Gunnerus) by their exact
/// thrust region (thrust_region.hpp) at rest, as Level 1 has it: each thrust within its
/// rating, the rudders' lift only in their propellers' slipstream; λ by bisection to 0.01 %
/// (the region is a union of convex sets holding the origin, so every smaller multiple of a
/// load held is held too). λ is searched up to kMaxLoadFactor (capped there); a multiple of the
/// load below 10⁻³ of the allocation's force and moment scales is λ = 0, as feasibility() has it.

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "dynpos/capability/feasibility.hpp"
#include "dynpos/capability/thrust_region.hpp"
#include "dynpos/model/layout_allocator.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::capability {

/// The failure cases of a vessel and the factor of a load each holds (see the file comment).
class FailureConsequence {
 public:
  /// The intact case and the single failures of `vessel`. Throws core::InputError for a vessel
  /// whose thrusters do not validate.
  explicit FailureConsequence(const scenario::VesselConfig& vessel);

  /// The single failures' names (single_failures()), in the order of their index.
  const std::vector<std::string>& cases() const noexcept { return cases_; }

  /// λ of `load_b` (X [N], Y [N], N [N·m]) with case `k` lost: its load_factor, capped,
  /// limiting units (actuator_names() for the model) and failure name. Throws
  /// std::out_of_range unless k < cases().size().
  FeasibilityPoint load_factor(const Eigen::Vector3d& load_b, std::size_t k) const;

  /// Each case's λ of `load_b`, in the order of cases().
  std::vector<FeasibilityPoint> load_factors(const Eigen::Vector3d& load_b) const;

  /// The case of the smallest λ of `load_b` (the first of equal ones): the worst single failure.
  FeasibilityPoint worst(const Eigen::Vector3d& load_b) const;

  /// λ of `load_b` with every actuator as rated; failure "none".
  FeasibilityPoint intact(const Eigen::Vector3d& load_b) const;

 private:
  // λ in case c of failure_cases() / model_limits_ (0 intact, then cases_).
  FeasibilityPoint factor(const Eigen::Vector3d& load_b, std::size_t c) const;

  std::vector<std::string> cases_;
  // A layout: its allocator and failure_cases() (index 0 intact, then cases_).
  std::optional<model::LayoutAllocator> allocator_;
  std::vector<FailureCase> layout_cases_;
  // The model: the thrust region intact, then with each of cases_ lost.
  std::vector<ThrustLimits> model_limits_;
};

}  // namespace dynpos::capability
