#pragma once
/// \file
/// Tick positions for plot axes: "nice" steps of 1, 2 or 5 times a power of ten.
///
/// A tick value is always computed as k·step from an integer k, never by accumulating
/// step after step, so labels come out as 0.1, 0.2, 0.3 and not 0.30000000000000004.

#include <string>
#include <vector>

namespace dynpos::report {

/// The ticks of one axis.
struct AxisTicks {
  double lo = 0.0;             ///< lower end of the axis (≤ the first tick)
  double hi = 1.0;             ///< upper end of the axis (≥ the last tick), > lo
  double step = 0.2;           ///< distance between ticks, 1, 2 or 5 × 10ⁿ, > 0
  std::vector<double> values;  ///< the ticks in [lo, hi], increasing
  int decimals = 1;            ///< digits after the point that show every tick exactly
};

/// The nice step nearest above span/target: the smallest s = m·10ⁿ, m ∈ {1, 2, 5}, with
/// s ≥ span/target. span > 0 and target ≥ 1; otherwise returns 1.
double nice_step(double span, int target);

/// Ticks for data in [lo, hi] with about `target` (≥ 2) intervals. With expand, the axis ends
/// move out to the nearest multiples of the step (auto-ranged axes); without, the axis is
/// exactly [lo, hi] and only the ticks inside it are kept (a fixed range, e.g. a zoom).
/// A degenerate range (lo = hi) is widened around the value; non-finite input gives [0, 1].
AxisTicks nice_ticks(double lo, double hi, int target = 6, bool expand = true);

/// A tick label with `decimals` digits after the point, using a Unicode minus and never
/// printing "−0".
std::string format_tick(double value, int decimals);

}  // namespace dynpos::report
