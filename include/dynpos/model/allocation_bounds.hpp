#pragma once
/// \file
/// The bounds of the allocation variables f = (T₁, T₂, Y₁, Y₂, T₃) [N] of thrust_allocation.hpp
/// for one solve: the box (thrust ahead/astern, tunnel port/starboard) tightened by the rate
/// limits and the sign region of the main propellers, and the rudder cone that bounds each
/// rudder's side force by its propeller's thrust.

#include <algorithm>
#include <array>
#include <utility>

#include <Eigen/Core>

namespace dynpos::model {

/// The rudder cone |Y| ≤ κ·max(T, 0) + c: the side force the rudder model's linear lift gives at
/// the allocation's largest rudder angle, linear in the propeller thrust T⁺ (rudder.hpp).
struct RudderCone {
  double kappa = 0.0;  ///< κ, side force per unit of ahead thrust [-], ≥ 0
  double c_N = 0.0;    ///< c, side force from the ship's speed alone [N], ≥ 0
  /// The largest |Y| [N] at propeller thrust thrust_N [N].
  double limit(double thrust_N) const noexcept { return kappa * std::max(thrust_N, 0.0) + c_N; }
  /// (lower, upper) side force [N] at thrust thrust_N: the cone within the box [lo_N, hi_N].
  std::pair<double, double> bounds(double thrust_N, double lo_N, double hi_N) const noexcept {
    const double cone = limit(thrust_N);
    return {std::max(-cone, lo_N), std::min(cone, hi_N)};
  }
};

/// Sign region of the main propellers' thrusts (T₁, T₂), each 0 (either sign), +1 (ahead,
/// T ≥ 0) or −1 (astern, T ≤ 0). Within one region the rudder cones are convex.
using ThrustSignRegion = std::array<int, 2>;

/// The box bounds box = (lower, upper) on f [N] for one solve: with dt_s > 0 intersected with
/// the rate bounds f_prev ± ḟ_max·Δt (where they do not overlap the box wins, collapsed to the
/// point of the box nearest f_prev), then the main propellers' thrusts limited to `region`
/// (an empty side collapses to the bound nearest 0).
std::array<Eigen::Matrix<double, 5, 1>, 2> allocation_box(
    std::array<Eigen::Matrix<double, 5, 1>, 2> box, const Eigen::Matrix<double, 5, 1>& previous_N,
    const Eigen::Matrix<double, 5, 1>& rate_limits_N_s, double dt_s, ThrustSignRegion region);

}  // namespace dynpos::model
