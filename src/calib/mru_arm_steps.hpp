#pragma once
// Steps of estimate_mru_arms() that stand on their own: the span of samples used, the noise
// correlation of the least-squares residuals, and the excitation G(t) along the log.

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "dynpos/calib/mru_observer.hpp"

namespace dynpos::calib::detail {

/// Samples [begin, end) of a series.
struct SampleSpan {
  std::size_t begin = 0;
  std::size_t end = 0;
  std::size_t size() const noexcept { return end - begin; }
};

/// The samples of the increasing times `t_s` at least `edge_s` from both ends, where the
/// smoother's window is cut off.
SampleSpan used_span(const std::vector<double>& t_s, double edge_s);

/// Variance inflation (1 + ρ)/(1 − ρ) of an AR(1) noise, ρ the lag-1 autocorrelation of the
/// residual vectors clamped to [0, 0.999]: the smoother correlates neighbouring residuals, so
/// they count as fewer independent samples. 1 for white or alternating residuals.
double variance_inflation(const std::vector<Eigen::Vector3d>& residuals);

/// G(t) (4.77) every `stride` samples of `span`: its smallest singular value, rank and
/// condition into `out` (t_s, g_min_sv, g_rank, rank3_fraction, the medians). Returns the number
/// of samples where G has rank 3 (Proposition 3: none, and no arm is determined).
int g_excitation(const MruSignals& s, SampleSpan span, std::size_t stride, MruExcitation& out);

}  // namespace dynpos::calib::detail
