#pragma once
/// \file
/// Thrust allocation for R/V Gunnerus (thesis section 2.2.2): from a desired generalised force
/// τ_d = (X, Y, N) [N, N, N·m] in BODY to shaft speed commands for the two main propellers,
/// rudder angle commands and the tunnel thruster command.
///
/// Formulation (extended thrust): the variables are f = (T₁, T₂, Y₁, Y₂, T₃) of
/// thrust_configuration.hpp, with τ = B·f. Each is normalised by its scale s_i (its largest
/// magnitude), x_i = f_i/s_i, and the allocation solves
///
///     min ‖Q^{½}(B·S·x − τ_d)‖²   then, among the minimisers,   min xᵀW x
///     s.t. box bounds  x_min ≤ x ≤ x_max          (thrust fwd/reverse, tunnel port/stb)
///          rudder cone |Y_i| ≤ κ_i·max(T_i, 0) + c_i  (lift only with slipstream or speed)
///          optional rate bounds |f_i − f_i,prev| ≤ ḟ_i,max·Δt
///
/// by the redistributed pseudo-inverse (iterative clipping): solve the weighted minimum-norm
/// least-squares problem on the free variables with a complete orthogonal decomposition, fix
/// the most violated variable at its bound, repeat (≤ 5 fixes), then project the rudder forces
/// onto their cones with the final thrusts. A rudder force that hits its cone is not frozen but
/// tied to its thrust, Y_i = ±(κ_i·T_i + c_i), so the thrust can still grow to give it room. When
/// τ_d is attainable without any bound active this is the exact constrained optimum; with active
/// bounds it is the usual near-optimal heuristic of DP practice (not a full QP), deterministic and
/// allocation-free. The rudder cone is exact for the rudder model: its side force in the linear
/// region is linear in T⁺ (rudder.hpp).
///
/// Rudder drag is not linear in f and is left out of B. With rudder_drag_compensation > 0 the
/// allocation accounts for it by a fixed point: it predicts the drag the deflection of the
/// allocated rudders adds in their propellers' slipstream (the rudder model at zero ship speed;
/// surge force D_x,i and its moment −y_i·D_x,i, from (2.37)), solves again for τ_d − τ_drag, and
/// repeats until the prediction changes by less than half the tolerance of "met" (1e-6 of the
/// force and moment scales). The drag is small beside the lift (C_D/C_L ≈ 0.2–0.3 at 30°), so a
/// few passes converge. Without it, a joystick sway demand met with rudder lift leaves ≈ 13 % of
/// the sway force as an unmet astern force and the vessel drifts astern (thesis section 3.5:
/// sway steps).
///
/// Holding the previous split (hold_weight μ > 0, input hold_forces given): B has a
/// two-dimensional null space, so one τ_d has many splits between the thrusters, and the
/// minimum-norm split can jump from one branch to another (e.g. port ahead/starboard astern for a
/// yaw moment, or the reverse) between two allocations. With hold_forces f_h the allocation
/// instead minimises ‖x‖² + μ‖x − x_h‖² (scaled as W above) among the minimisers of the
/// residual, i.e. it solves for the shift from x_h·μ/(1+μ): the demand is met exactly as
/// before and only the split moves towards f_h. Holding also corrects the clipping's branch:
/// the rudder cone is not convex across T_i = 0 but is within each sign region of (T₁, T₂), and
/// one bound fixed at a time can end on a branch that misses a demand another branch meets
/// (port full astern with starboard ahead instead of starboard astern, with the weather from
/// astern). The candidates are the plain solve, the plain solve within each of the four sign
/// regions, and the pulled solve over both signs and within the region of f_h. Eligible are
/// those that meet τ_d, or, if none does, those whose Q-weighted unmet part is within 5 % of
/// the least (a band, so two saturated branches whose unmet parts cross do not alternate) and
/// no larger than the plain one's; the result is the eligible candidate nearest f_h (in the
/// weighted norm, each force over its box bound), the plain one on ties. So holding never
/// costs demand, and never moves the thrusters more than the plain split when that meets τ_d
/// as well. Without
/// hold_forces the allocation is the plain solve alone.
///
/// Shaft speeds come from the inverse bollard maps (3.17), rudder angles from the inverse
/// linear lift at the commanded thrust, the tunnel shaft speed from its map including the
/// speed factor.

#include <array>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "dynpos/model/allocation_bounds.hpp"
#include "dynpos/model/rudder.hpp"
#include "dynpos/model/thrust_configuration.hpp"
#include "dynpos/model/thruster.hpp"
#include "dynpos/model/tunnel_thruster.hpp"

namespace dynpos::model {

/// Options of the allocation.
struct ThrustAllocationOptions {
  /// Weights W on the normalised variables (T₁, T₂, Y₁, Y₂, T₃) [-]. Source:
  /// reasoned — equal cost per fraction of capacity for thrusters; rudder force is cheap
  /// (only drag), so 0.3; tunnel 1.5 to prefer the more efficient main propellers.
  Eigen::Matrix<double, 5, 1> weights{1.0, 1.0, 0.3, 0.3, 1.5};
  /// Priority Q on the normalised residual of (X, Y, N) [-], used only when τ_d is
  /// not attainable. Source: reasoned — heading (N) first, then sway, then surge, as in DP.
  Eigen::Vector3d priority{1.0, 3.0, 10.0};
  /// Normalisation of τ for the priority: force scale [N] and moment scale [N·m].
  double force_scale = 1.0e5;
  double moment_scale = 1.3e6;
  /// Largest usable rudder angle for allocation [rad]. Source: reasoned — keep in
  /// the linear lift region (the rudder stall angle, 30°).
  double max_rudder_angle = 30.0 * 3.14159265358979323846 / 180.0;
  /// Rate limits [N/s] on (T₁, T₂, Y₁, Y₂, T₃), used only when a previous allocation and
  /// Δt are given. Source: reasoned — full thrust in ≈ 10 s for the main propellers (the shaft
  /// reference rate 0.3 rps/s), ≈ 4 s for the tunnel thruster; rudder force from 0 to full
  /// in ≈ 5 s (servo 6.3°/s over 30°).
  Eigen::Matrix<double, 5, 1> rate_limits{7.5e3, 7.5e3, 8.0e3, 8.0e3, 6.0e3};
  /// Fraction of the predicted rudder drag the allocation compensates [-]; 0 leaves
  /// drag out (τ_achieved = B·f). Source: reasoned — 1, the rudder model is the plant's own;
  /// calibrated against the sway steps (tables 3.28, 3.30), whose surge drift it removes.
  double rudder_drag_compensation = 1.0;
  /// Weight μ of the pull towards hold_forces [-]; 0 disables it (file comment). Each
  /// allocation moves μ/(1+μ) of the way to the held split, so μ = 4 keeps 80 % of the last
  /// split per step: at 10 Hz a split change is spread over ≈ 0.5 s, about the propellers'
  /// dead time. Source: reasoned, and measured with the weather from astern (pure DP at
  /// 180°, docs/virtual-gunnerus.md).
  double hold_weight = 4.0;
  /// Capacity of each variable of f (T₁, T₂, Y₁, Y₂, T₃) as a factor on its rated bounds [-]:
  /// 1 as rated, 0 lost (a failed thruster or rudder, held at zero). Not a vessel-file key: the
  /// failure cases of a capability analysis set it.
  Eigen::Matrix<double, 5, 1> capacity = Eigen::Matrix<double, 5, 1>::Ones();

  /// Throws core::InputError naming the first option outside its range (param_fields).
  void validate() const;
};

/// The options as the keys of the vessel file's [allocation] section, each with its unit and range
/// (core/param_range.hpp): the one table validate(), the file reader and the docs use.
std::vector<core::ParamField> param_fields(ThrustAllocationOptions& options);

/// Inputs of one allocation.
struct ThrustAllocationInput {
  /// Desired τ_d = (X [N], Y [N], N [N·m]) in BODY.
  Eigen::Vector3d tau_d_b = Eigen::Vector3d::Zero();
  /// Vessel surge speed through the water u [m/s] (rudder inflow, tunnel speed factor).
  double surge_speed = 0.0;
  /// Previous allocated forces f (for rate limits); used only when dt > 0.
  Eigen::Matrix<double, 5, 1> previous_forces = Eigen::Matrix<double, 5, 1>::Zero();
  /// Time since the previous allocation Δt [s]; ≤ 0 disables rate limits.
  double dt = 0.0;
  /// Split to hold (forces f [N]) within the null space of the demand, weighted by
  /// hold_weight; empty or hold_weight 0: the minimum-norm split (file comment).
  std::optional<Eigen::Matrix<double, 5, 1>> hold_forces;
};

/// Outcome of an allocation.
enum class AllocationStatus {
  kOk,           ///< τ_d met (each residual below 1e-6 of force_scale / moment_scale)
  kSaturated,    ///< a bound prevented meeting τ_d; tau_unmet_b ≠ 0
  kInvalidInput  ///< τ_d or the speed was not finite; all commands are zero
};

/// Result of one allocation.
struct ThrustAllocationResult {
  AllocationStatus status = AllocationStatus::kOk;
  std::string message;  ///< empty when kOk; otherwise what happened
  /// Allocated forces f = (T₁, T₂, Y₁, Y₂, T₃) [N].
  Eigen::Matrix<double, 5, 1> forces = Eigen::Matrix<double, 5, 1>::Zero();
  /// B·f plus the predicted rudder drag tau_rudder_drag_b.
  Eigen::Vector3d tau_achieved_b = Eigen::Vector3d::Zero();
  /// Rudder drag (X [N], 0, N [N·m]) the allocation predicts at its commands and compensates;
  /// zero when rudder_drag_compensation is 0.
  Eigen::Vector3d tau_rudder_drag_b = Eigen::Vector3d::Zero();
  Eigen::Vector3d tau_unmet_b = Eigen::Vector3d::Zero();  ///< τ_d − tau_achieved_b
  /// Which variable ended at a bound (box, cone or rate), in the order of f.
  std::array<bool, 5> saturated{};
  double n_port = 0.0;         ///< port propeller shaft speed command [rps]
  double n_stb = 0.0;          ///< starboard propeller shaft speed command [rps]
  double rudder_port = 0.0;    ///< port rudder angle command [rad]
  double rudder_stb = 0.0;     ///< starboard rudder angle command [rad]
  double n_tunnel = 0.0;       ///< tunnel shaft speed command [rps]
  double tunnel_thrust = 0.0;  ///< tunnel side force command [N]
  int iterations = 0;          ///< least-squares solves used
};

/// The allocator: const, owns copies of the actuator models it inverts.
class ThrustAllocator {
 public:
  /// Throws core::InputError on invalid options.
  explicit ThrustAllocator(const Thruster& propeller = Thruster{}, const Rudder& rudder = Rudder{},
                           const TunnelThruster& tunnel = TunnelThruster{},
                           const ThrustConfiguration& configuration = ThrustConfiguration{},
                           const ThrustAllocationOptions& options = {});

  /// Allocates τ_d (see file comment). Deterministic; never throws; no NaN out.
  ThrustAllocationResult allocate(const ThrustAllocationInput& input) const;

  /// Box bounds (lower, upper) on f [N] at surge speed u before cones and rate limits, each
  /// scaled by its capacity.
  std::array<Eigen::Matrix<double, 5, 1>, 2> bounds(double surge_speed) const noexcept;
  /// The rudder cone at surge speed u [m/s] from the rudder model's linear lift at the
  /// allocation's largest rudder angle.
  RudderCone rudder_cone(double surge_speed) const noexcept;

  const ThrustConfiguration& configuration() const noexcept { return configuration_; }
  const Thruster& propeller() const noexcept { return propeller_; }
  const ThrustAllocationOptions& options() const noexcept { return options_; }

 private:
  // Sign region of the main propellers' thrusts (allocation_bounds.hpp).
  using SignRegion = ThrustSignRegion;
  // One allocation with the rudder-drag fixed point; `hold` applies input.hold_forces.
  ThrustAllocationResult allocate_with_drag(const ThrustAllocationInput& input, SignRegion region,
                                            bool hold) const;
  // One allocation of τ_d without rudder drag: τ_achieved = B·f.
  ThrustAllocationResult solve(const ThrustAllocationInput& input, SignRegion region,
                               bool hold) const;
  // Priority-weighted squared unmet demand Σ Q_i (τ_unmet,i / scale_i)² [-].
  double weighted_unmet(const ThrustAllocationResult& r) const;
  // The rudder drag (X, 0, N) the rudder model predicts for the commands of r, scaled by the
  // compensation fraction.
  Eigen::Vector3d rudder_drag(const ThrustAllocationResult& r) const;
  // τ_unmet over the force and moment scales (X, Y, N) [-].
  Eigen::Vector3d normalised_unmet(const ThrustAllocationResult& r) const;
  // Marks r saturated, with a message, when τ_unmet is not within the tolerance of "met".
  void set_met_status(ThrustAllocationResult& r) const;
  // Shaft speed, rudder angle and tunnel commands for the forces of r at surge speed u [m/s].
  void set_commands(ThrustAllocationResult& r, double surge_speed) const;

  Thruster propeller_;
  Rudder rudder_;
  TunnelThruster tunnel_;
  ThrustConfiguration configuration_;
  ThrustAllocationOptions options_;
};

}  // namespace dynpos::model
