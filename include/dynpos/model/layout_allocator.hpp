#pragma once
/// \file
/// Thrust allocation for any layout of units (thruster_unit.hpp): from a desired generalised
/// force τ_d = (X, Y, N) [N, N, N·m] in BODY to each unit's force.
///
/// Variables, each over its unit's rated thrust s (x = f/s): an azimuth's force (F_x, F_y), a
/// tunnel's side force, a propeller's thrust, a propeller-with-rudder's thrust T and rudder
/// side force Y (over κ·s + c). τ = B·S·x with B's columns (1, 0, −y) for a surge force and
/// (0, 1, x) for a side force at (x, y) (2.2). The allocation solves the convex programme
///
///     min ρ‖Q^{½}D(B·S·x − τ_d)‖² + xᵀWx   s.t. each unit's region,
///
/// D the normalisation of (X, Y, N) by the force and moment scales, Q the priority, W the unit
/// weights, ρ = 10⁸: an attainable demand is met to 10⁻⁸ of the scales (the weighted effort
/// over ρ), and an unattainable one leaves the least priority-weighted unmet part (to the same
/// order). Regions:
///   - azimuth: the disc of radius s as an inscribed polygon of `polygon_sides` sides (the
///     thrust between two corners is short of s by at most 1 − cos(π/sides), 0.48 % at 32), cut
///     to one allowed arc of directions (allowed_arcs(): arcs of ≤ 180°, convex wedges);
///   - tunnel and propeller: [−reverse, ahead];
///   - propeller with rudder: T ∈ [0, ahead] with |Y| ≤ κ·T + c, or T ∈ [−reverse, 0] with
///     |Y| ≤ c (the rudder cone is convex within each sign of T, not across it).
/// The union of an azimuth's arcs and of a rudder's two signs is not convex. The allocation
/// first solves the convex relaxation (each azimuth's whole polygon, each rudder's T over both
/// signs with |Y| ≤ κ·ahead + c): when every unit's force lies in its true region, that is the
/// optimum. Otherwise it solves in the region each unit's relaxed force lies in or is nearest
/// to, and when that leaves the demand unmet, in every combination of regions (at most
/// `max_region_combinations`), keeping the least priority-weighted unmet part. An
/// attainable demand is therefore met (up to the polygon), and no azimuth ever points into a
/// forbidden sector. Each convex programme is solved by the primal active-set method from the
/// origin, which every region contains (attainable() with a warm start: from the last solution
/// of the same combination of regions).

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dynpos/model/azimuth_region.hpp"
#include "dynpos/model/thruster_unit.hpp"

namespace dynpos::model {

/// Options of the allocation for a layout.
struct LayoutAllocationOptions {
  /// Priority Q on the normalised (X, Y, N) residual [-]: heading first, then sway, then surge,
  /// as in DP and ThrustAllocationOptions.
  Eigen::Vector3d priority{1.0, 3.0, 10.0};
  /// Normalisation of τ: force scale [N] and moment scale [N·m], > 0.
  double force_scale = 1.0e5;
  double moment_scale = 1.3e6;
  /// Sides of the polygon inscribed in an azimuth's disc, 8…256.
  int polygon_sides = 32;
  /// Cost of a rudder's side force relative to its propeller's thrust [-], > 0: lift costs
  /// only drag.
  double rudder_weight = 0.3;
  /// Largest number of region combinations tried for a demand the first guess misses, ≥ 1.
  int max_region_combinations = 256;

  /// Throws core::InputError naming the first option out of range.
  void validate() const;
};

/// One unit's command.
struct UnitCommand {
  Eigen::Vector2d force_b = Eigen::Vector2d::Zero();  ///< (F_x, F_y) in BODY [N], rudder too
  /// Azimuth: thrust magnitude ≥ 0; tunnel: side force (+ starboard); propeller (with rudder):
  /// thrust (+ ahead) [N].
  double thrust_N = 0.0;
  /// Azimuth: thrust direction α [rad] in [0, 2π) (0 for no thrust); else 0.
  double angle_rad = 0.0;
  /// Propeller with rudder: the rudder's side force [N]; else 0.
  double rudder_force_N = 0.0;
  /// At a limit of its region (rated thrust, the edge of an allowed arc, the rudder's cone or
  /// largest force) within 0.2 % of its rating, with a force that is not zero.
  bool at_limit = false;
};

/// Outcome of one allocation.
struct LayoutAllocation {
  bool met = true;  ///< every residual within 10⁻⁶ of its scale
  std::vector<UnitCommand> units;
  Eigen::Vector3d tau_achieved_b = Eigen::Vector3d::Zero();
  Eigen::Vector3d tau_unmet_b = Eigen::Vector3d::Zero();  ///< τ_d − τ_achieved
  int programmes = 0;                                     ///< convex programmes solved
  int iterations = 0;  ///< active-set iterations over all of them
};

/// Rate limits of one allocation (LayoutAllocator::allocate): each force within its unit's
/// thrust_rate_N_per_s × dt_s of the previous allocation's (per variable, as the 2014
/// Gunnerus's ThrustAllocationOptions::rate_limits).
struct AllocationRates {
  const LayoutAllocation* previous = nullptr;  ///< the allocator's last allocation, same capacity
  double dt_s = 0.0;                           ///< the time since it [s], > 0
};

/// The last solution of each combination of regions an allocator solved, for the next demand to
/// start from (LayoutAllocator::attainable): a bisection's next question, close to the last,
/// then takes a step or two per programme instead of one per active constraint. The optimum is
/// the same from any start, up to round-off. Bound to the allocator and the capacity it was
/// filled with; another allocator or capacity empties it. Not shared between threads.
class AllocationWarmStart {
 public:
  AllocationWarmStart() = default;
  /// A copy keeps the solutions, not the cached programmes (each copy builds its own, so that
  /// copies used on two threads share nothing).
  AllocationWarmStart(const AllocationWarmStart& other)
      : owner_(other.owner_), capacity_(other.capacity_), by_regions_(other.by_regions_) {}
  AllocationWarmStart& operator=(const AllocationWarmStart& other) {
    if (this != &other) *this = AllocationWarmStart(other);
    return *this;
  }
  AllocationWarmStart(AllocationWarmStart&&) = default;
  AllocationWarmStart& operator=(AllocationWarmStart&&) = default;

 private:
  friend class LayoutAllocator;
  struct Solution {
    Eigen::VectorXd x;                  // the variables, each over its unit's rating
    std::vector<Eigen::Index> working;  // the constraints active there
  };
  const void* owner_ = nullptr;  // the allocator it was filled by
  std::vector<double> capacity_;
  std::map<std::vector<int>, Solution> by_regions_;
  // Each combination's programme but for its demand term (the allocator's Setup, which only
  // its source file knows): built once, not at every question.
  std::map<std::vector<int>, std::shared_ptr<void>> setups_;
};

/// The allocator of one layout: const, deterministic, never throws after construction.
class LayoutAllocator {
 public:
  /// Throws core::InputError naming the first bad unit or option (or two units of one name).
  explicit LayoutAllocator(std::vector<ThrusterUnit> units, LayoutAllocationOptions options = {});

  /// Allocates τ_d (see the file comment); `capacity` per unit in [0, 1] scales its rated thrust
  /// (0: failed), empty for all 1. A τ_d that is not finite gives zero commands, not met; one
  /// beyond 10⁶ times the force or moment scale is allocated at that size in its direction.
  LayoutAllocation allocate(const Eigen::Vector3d& tau_d_b,
                            const std::vector<double>& capacity = {}) const;

  /// allocate() with rate limits: the allocation above, then, in the regions it chose, the same
  /// programme with each variable within rate·dt of `rates.previous` (started from there, which
  /// every such box holds). The demand may then be unmet (met false) while the units ramp.
  /// Without a previous allocation of as many units, with dt ≤ 0, or when a unit's previous
  /// force lies outside the region now chosen (an azimuth that changes arc, a rudder propeller
  /// that reverses), the allocation above unchanged: a change of region is not rate-limited.
  LayoutAllocation allocate(const Eigen::Vector3d& tau_d_b, const std::vector<double>& capacity,
                            const AllocationRates& rates) const;

  /// Whether some combination of regions meets τ_d (every residual within 10⁻⁶ of its scale),
  /// sooner than allocate(): a demand the convex relaxation misses is not solved again, and the
  /// combinations are searched by branch and bound (a unit's region fixed at a time, the units
  /// after it relaxed: a programme that misses the demand cuts all below it; after the
  /// relaxation and the first guess, at most twice max_region_combinations programmes),
  /// stopping at the first combination that meets it. For the many yes-or-no questions of a
  /// capability rose. It answers as allocate(τ_d, capacity).met does except within the 10⁻⁶
  /// tolerance (allocate() keeps the combination of the least priority-weighted unmet part,
  /// which may miss a component by a hair where another combination meets them all) and for
  /// layouts with more combinations than either search's cap. `warm`, when given, starts each
  /// programme from the last solution of its combination of regions and keeps the new one.
  bool attainable(const Eigen::Vector3d& tau_d_b, const std::vector<double>& capacity = {},
                  AllocationWarmStart* warm = nullptr) const;

  const std::vector<ThrusterUnit>& units() const noexcept { return units_; }
  const LayoutAllocationOptions& options() const noexcept { return options_; }

 private:
  struct Setup;  // the programme of one region combination
  Setup setup(const Eigen::Vector3d& tau_d_b, const std::vector<double>& capacity,
              const std::vector<int>& regions) const;
  // setup(), from `warm`'s cache when given (its demand term set to τ_d).
  std::shared_ptr<const Setup> setup(const Eigen::Vector3d& tau_d_b,
                                     const std::vector<double>& capacity,
                                     const std::vector<int>& regions,
                                     AllocationWarmStart* warm) const;
  // One region combination; least_effort: when unmet, the least effort for what is achieved.
  LayoutAllocation solve(const Setup& s, const Eigen::Vector3d& tau_d_b, bool least_effort = false,
                         AllocationWarmStart* warm = nullptr,
                         const Eigen::VectorXd* x0 = nullptr) const;
  void project(const Setup& s, Eigen::VectorXd& x) const;  // each unit into its region
  // attainable()'s question.
  struct Question {
    const Eigen::Vector3d& tau_d_b;
    const std::vector<double>& capacity;
    AllocationWarmStart* warm;
  };
  // Branch and bound over the regions of the units from `from` on (those before it fixed in
  // `regions`, those after it relaxed): true when a combination meets the demand. A node whose
  // programme misses the demand cuts every combination below it; at most `budget` programmes.
  bool search_regions(const Question& q, std::vector<int>& regions, std::size_t from,
                      int& budget) const;
  std::vector<int> nearest_regions(const LayoutAllocation& relaxed) const;
  // Whether unit k's command lies in its true region (its arcs, cone, and loss table's pieces).
  bool in_region(std::size_t k, const UnitCommand& c) const;
  // Each side (outward normal, distance over the rating) of unit k's polygon in `region`.
  void for_each_side(std::size_t k, int region,
                     const std::function<void(const Eigen::Vector2d&, double)>& side) const;
  int region_count(std::size_t unit) const;

  std::vector<ThrusterUnit> units_;
  LayoutAllocationOptions options_;
  std::vector<std::vector<AllowedArc>> arcs_;  // per unit (azimuths), else empty
  // An azimuth with a loss table: its convex pieces (arcs_ holds their wedges) and the
  // relaxation's radius, its largest factor; else empty and 1.
  std::vector<std::vector<ConvexPiece>> pieces_;
  std::vector<double> relaxed_radius_;
  // The inscribed polygon of an azimuth's disc over its radius: each side's outward normal and
  // its distance from the centre, cos(π/sides).
  std::vector<Eigen::Vector2d> side_normals_;
  double side_distance_ = 1.0;
};

}  // namespace dynpos::model
