#pragma once
/// \file
/// What the thrusters can hold: whether a steady force τ = (X, Y, N) in BODY is attainable by
/// the allocation variables f = (T₁, T₂, Y₁, Y₂, T₃) of model/thrust_configuration.hpp within
/// their limits — each thrust within its rated maximum ahead/astern, the tunnel within its
/// port/starboard maximum, each rudder's side force within its cone |Y| ≤ κ·max(T, 0) + c (lift
/// only in its propeller's slipstream, or from the inflow) — with any actuators failed.
///
/// Exact, not the allocation heuristic: B·f = τ leaves a two-dimensional family
/// f = f₀ + N·z (N the null space of B), and within each sign region of (T₁, T₂) the limits are
/// half-planes in z. τ is attainable when, in one region, their intersection is not empty; a
/// non-empty bounded polygon has a vertex where two limits meet, so every pair of limit lines
/// is tried (at most 16 lines, 120 pairs, per region). A vertex found is an allocation that
/// meets τ, and the limits it touches name the actuators that saturate.

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "dynpos/model/failure_case.hpp"
#include "dynpos/model/thrust_allocation.hpp"

namespace dynpos::capability {

using model::actuator_names;
using model::with_failures;

/// The actuators' limits at one inflow speed, with failures applied.
struct ThrustLimits {
  Eigen::Matrix<double, 3, 5> B;     ///< τ = B·f (model/thrust_configuration.hpp)
  Eigen::Matrix<double, 5, 1> lo_N;  ///< lower box bounds on f [N]
  Eigen::Matrix<double, 5, 1> hi_N;  ///< upper box bounds on f [N]
  model::RudderCone cone;            ///< both rudders' cone at this inflow
  std::array<bool, 5> failed{};      ///< capacity 0: its f is held at 0
};

/// The limits of `allocator` at surge inflow speed u [m/s] (≥ 0 ahead; the tunnel's speed
/// factor and the rudders' lift from the inflow), with its capacities
/// (model::ThrustAllocationOptions::capacity: 0 lost, 1 as rated). A lost propeller's rudder
/// keeps only the inflow's lift, through the cone. With propeller_inflow the main propellers'
/// limits are their thrust at full shaft speed with the inflow as advance speed (K_T falling
/// with J, (2.25) with (2.27)); without, their bollard thrust as the allocation takes it.
ThrustLimits thrust_limits(const model::ThrustAllocator& allocator, double surge_speed_mps,
                           bool propeller_inflow = false);

/// An allocation that meets τ within the limits, and the actuators at a limit in it.
struct Attainment {
  Eigen::Matrix<double, 5, 1> forces_N;  ///< f with B·f = τ
  /// Which f_k sit on a bound (box or cone), within 0.2 % of the largest bound, with a force
  /// that is not zero.
  std::array<bool, 5> at_limit{};
};

/// An allocation meeting τ_b = (X [N], Y [N], N [N·m]) within `limits`, or none when τ is not
/// attainable. A limit counts as met within 1e-9 of the largest bound (rounding).
std::optional<Attainment> attain(const ThrustLimits& limits, const Eigen::Vector3d& tau_b);

}  // namespace dynpos::capability
