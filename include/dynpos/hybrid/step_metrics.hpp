#pragma once
/// \file
/// Performance measures of a response to disturbance steps: settling time, integral of the
/// absolute error (IAE) and peak error, on sampled signals.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <optional>
#include <span>

namespace dynpos::hybrid {

/// The settling time of a step at t_step [s], judged on the samples with
/// t_step ≤ t[i] < t_end (the step's window, up to the next step): the time from t_step to the
/// first sample from which ratio ≤ 1 holds for every later sample of the window, where ratio is
/// |error| / allowed band. Absent when the last sample of the window is outside the band, or the
/// window has no samples. t must be non-decreasing; t and ratio of one size (extra values of
/// the longer are ignored). A NaN ratio counts as outside the band.
std::optional<double> settling_time(std::span<const double> t, std::span<const double> ratio,
                                    double t_step, double t_end);

/// IAE = ∫|e| dt by the trapezoidal rule over the samples (t non-decreasing); 0 with fewer than
/// two samples. NaN samples make the result NaN (missing data is not zero).
double integral_abs_error(std::span<const double> t, std::span<const double> e);

/// max |e| over the samples; NaN when there are none or one is NaN.
double peak_abs(std::span<const double> e);

/// The scale of each DOF's settling band for a vector step Δ: |Δ_j|, or max_k |Δ_k| for a DOF
/// the step leaves alone (Δ_j = 0), in that DOF's own unit (case_study.hpp).
template <int Dofs>
Eigen::Matrix<double, Dofs, 1> step_band_scale(const Eigen::Matrix<double, Dofs, 1>& delta) {
  Eigen::Matrix<double, Dofs, 1> scale = delta.cwiseAbs();
  const double largest = scale.maxCoeff();
  for (int j = 0; j < Dofs; ++j) {
    if (scale(j) == 0.0) scale(j) = largest;
  }
  return scale;
}

/// max_j |e_j| / (band·scale_j): at most 1 when every DOF of the error e is inside its band.
template <int Dofs>
double band_ratio(const Eigen::Matrix<double, Dofs, 1>& error,
                  const Eigen::Matrix<double, Dofs, 1>& scale, double band) {
  return (error.cwiseAbs().array() / (band * scale.array())).maxCoeff();
}

/// The fraction of a step Δ left in the error e: max_j |e_j| / |Δ_j|, over the band scale
/// (step_band_scale) for a DOF the step leaves alone.
template <int Dofs>
double step_residual(const Eigen::Matrix<double, Dofs, 1>& error,
                     const Eigen::Matrix<double, Dofs, 1>& delta,
                     const Eigen::Matrix<double, Dofs, 1>& scale) {
  const Eigen::Matrix<double, Dofs, 1> size = delta.cwiseAbs();
  double worst = 0.0;
  for (int j = 0; j < Dofs; ++j) {
    worst = std::max(worst, std::abs(error(j)) / (size(j) > 0.0 ? size(j) : scale(j)));
  }
  return worst;
}

}  // namespace dynpos::hybrid
