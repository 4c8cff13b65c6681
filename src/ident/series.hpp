#pragma once
// Small numeric utilities on sampled series shared by the ident sources (private).

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace dynpos::ident::detail {

/// Throws core::InputError (naming `name`) unless t is finite and strictly increasing; checked
/// in pieces on `jobs` threads (0 = every core).
void check_time_axis(std::span<const double> t, const std::string& name, unsigned jobs);

/// How far a window bound computed from a log's times [s] may stray from them by rounding
/// alone: 16 ulps of the largest |time| (at least of 1 s). Relative to the time's size, not to
/// 10⁻⁹ of it: a clock with an origin of 6.4·10¹⁰ s (seconds since year 1) gives 2.3·10⁻⁴ s,
/// not 64 s, which would take the previous step's samples into a window.
double time_rounding_slack_s(double t_a, double t_b);

/// Throws core::InputError unless the two spans have the same length.
void check_same_length(std::size_t n_t, std::size_t n_x, const std::string& name);

/// Median of the values (the vector is reordered); NaN when empty.
double median(std::vector<double> values);
/// median(), reordering `values` instead of copying them (for a long series).
double median_in_place(std::span<double> values);

/// Robust noise standard deviation from first differences of consecutive valid samples:
/// σ̂ = 1.4826·MAD(Δx)/√2. 0 when fewer than 2 differences.
double difference_noise_sigma(std::span<const double> x);

/// Least-squares line y = a + b·x and the standard deviation of its residuals.
struct LineFit {
  double a = 0.0;
  double b = 0.0;
  double residual_sigma = 0.0;
};

/// Fits a line to (x, y); needs at least 2 points with distinct x (else b = 0, a = mean).
LineFit fit_line(std::span<const double> x, std::span<const double> y);

/// Formats a number with up to 4 significant digits for messages.
std::string fmt(double value);

}  // namespace dynpos::ident::detail
