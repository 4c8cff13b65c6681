#pragma once
// Steps of estimate_gnss_arms() that stand on their own: the search of the GNSS time offset on
// the least-squares cost profile, and the statistics of an estimate over the converged interval.

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <vector>

namespace dynpos::calib::detail {

/// Index of the lowest finite cost in `cost_per_row` (the first one on ties); 0 when none is
/// finite.
std::size_t best_offset_index(const std::vector<double>& cost_per_row);

/// Sorts a scan of the time offset by δ and drops repeated δ (closer than 1e-9 s), keeping the
/// first cost found for each.
void sort_offset_scan(std::vector<double>& offset_s, std::vector<double>& cost_per_row);

/// The vertex of the parabola through the three scan points around the best one and the cost's
/// curvature there.
struct OffsetRefinement {
  double offset_s = 0.0;   ///< within one grid step of the best scan point
  double curvature = 0.0;  ///< d²cost/dδ² [1/s²], > 0
};

/// The parabola's vertex around `best` on an equally spaced, sorted scan; nullopt at the ends
/// of the scan, on unequal spacing, a non-finite neighbour or a curvature that is not > 0.
std::optional<OffsetRefinement> refine_offset(const std::vector<double>& offset_s,
                                              const std::vector<double>& cost_per_row,
                                              std::size_t best);

/// Mean and sample standard deviation of an estimate over an interval.
struct IntervalStats {
  Eigen::Vector3d mean;  ///< NaN when no sample is in the interval
  Eigen::Vector3d std;   ///< NaN with fewer than two samples
};

/// Statistics of the finite samples of `history` taken at t_s ≥ from_s (the thesis' tables
/// 4.2–4.5 average an observer's estimate over its converged interval).
IntervalStats interval_statistics(const std::vector<double>& t_s,
                                  const std::vector<Eigen::Vector3d>& history, double from_s);

}  // namespace dynpos::calib::detail
