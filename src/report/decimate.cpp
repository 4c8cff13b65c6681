#include "dynpos/report/decimate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace dynpos::report {

std::vector<std::size_t> minmax_decimate(std::span<const double> x, std::span<const double> y,
                                         double x_lo, double x_hi, int columns) {
  const std::size_t n = std::min(x.size(), y.size());
  std::vector<std::size_t> keep;
  if (n == 0) return keep;
  columns = std::max(columns, 1);
  const double width = x_hi > x_lo ? x_hi - x_lo : 1.0;
  // Column of a finite point: −1 left of the range, `columns` right of it.
  const auto column_of = [&](double xv) -> std::int64_t {
    if (xv < x_lo) return -1;
    if (xv > x_hi) return columns;
    return std::min<std::int64_t>(
        static_cast<std::int64_t>(std::floor((xv - x_lo) / width * columns)), columns - 1);
  };
  keep.reserve(std::min<std::size_t>(n, 4 * static_cast<std::size_t>(columns) + 16));

  std::size_t i = 0;
  while (i < n) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) {
      // One gap marker per run of non-finite points.
      if (keep.empty() || (std::isfinite(x[keep.back()]) && std::isfinite(y[keep.back()]))) {
        keep.push_back(i);
      }
      ++i;
      continue;
    }
    const std::int64_t column = column_of(x[i]);
    std::size_t first = i, last = i, lo = i, hi = i;
    ++i;
    while (i < n && std::isfinite(x[i]) && std::isfinite(y[i]) && column_of(x[i]) == column) {
      if (y[i] < y[lo]) lo = i;
      if (y[i] > y[hi]) hi = i;
      last = i;
      ++i;
    }
    std::size_t run[4] = {first, lo, hi, last};
    std::sort(run, run + 4);
    for (std::size_t k = 0; k < 4; ++k) {
      if (k == 0 || run[k] != run[k - 1]) keep.push_back(run[k]);
    }
  }
  return keep;
}

}  // namespace dynpos::report
