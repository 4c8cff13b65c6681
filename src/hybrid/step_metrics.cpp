#include "dynpos/hybrid/step_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dynpos::hybrid {

std::optional<double> settling_time(std::span<const double> t, std::span<const double> ratio,
                                    double t_step, double t_end) {
  const std::size_t n = std::min(t.size(), ratio.size());
  const auto first =
      std::lower_bound(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(n), t_step);
  const auto last = std::lower_bound(first, t.begin() + static_cast<std::ptrdiff_t>(n), t_end);
  if (first == last) return std::nullopt;
  const std::size_t begin = static_cast<std::size_t>(first - t.begin());
  const std::size_t end = static_cast<std::size_t>(last - t.begin());
  // Walk back from the window's end while inside the band.
  std::size_t i = end;
  while (i > begin && ratio[i - 1] <= 1.0) --i;
  if (i == end) return std::nullopt;  // outside at the end of the window (or NaN)
  return t[i] - t_step;
}

double integral_abs_error(std::span<const double> t, std::span<const double> e) {
  const std::size_t n = std::min(t.size(), e.size());
  double sum = 0.0;
  for (std::size_t i = 1; i < n; ++i) {
    sum += 0.5 * (std::abs(e[i - 1]) + std::abs(e[i])) * (t[i] - t[i - 1]);
  }
  return sum;
}

double peak_abs(std::span<const double> e) {
  if (e.empty()) return std::numeric_limits<double>::quiet_NaN();
  double peak = 0.0;
  for (const double v : e) {
    if (std::isnan(v)) return std::numeric_limits<double>::quiet_NaN();
    peak = std::max(peak, std::abs(v));
  }
  return peak;
}

}  // namespace dynpos::hybrid
