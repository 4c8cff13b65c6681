#pragma once
/// \file
/// Performance measures of a response to disturbance steps: settling time, integral of the
/// absolute error (IAE) and peak error, on sampled signals.

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

}  // namespace dynpos::hybrid
