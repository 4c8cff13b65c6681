#include "dynpos/report/axis_ticks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace dynpos::report {

double nice_step(double span, int target) {
  if (!(span > 0.0) || !std::isfinite(span) || target < 1) return 1.0;
  const double raw = span / target;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double normalized = raw / magnitude;
  // A small slack so that e.g. span/target = 2.0000000001 × 10ⁿ still picks 2, not 5.
  constexpr double kSlack = 1e-9;
  for (const double m : {1.0, 2.0, 5.0}) {
    if (normalized <= m * (1.0 + kSlack)) return m * magnitude;
  }
  return 10.0 * magnitude;
}

AxisTicks nice_ticks(double lo, double hi, int target, bool expand) {
  AxisTicks out;
  if (!std::isfinite(lo) || !std::isfinite(hi)) return nice_ticks(0.0, 1.0, target, expand);
  if (lo > hi) std::swap(lo, hi);
  if (lo == hi) {
    const double pad = lo == 0.0 ? 1.0 : 0.1 * std::abs(lo);
    lo -= pad;
    hi += pad;
  }
  target = std::max(target, 2);
  const double step = nice_step(hi - lo, target);
  // Tick k·step lies in [lo, hi] for k in [k_lo, k_hi]; the tolerance keeps an end that is a
  // multiple of step up to rounding.
  const double tolerance = 1e-9 * step;
  const double k_lo =
      expand ? std::floor((lo + tolerance) / step) : std::ceil((lo - tolerance) / step);
  const double k_hi =
      expand ? std::ceil((hi - tolerance) / step) : std::floor((hi + tolerance) / step);
  out.step = step;
  out.lo = expand ? k_lo * step : lo;
  out.hi = expand ? k_hi * step : hi;
  for (double k = k_lo; k <= k_hi; k += 1.0) {
    const double v = k * step;
    out.values.push_back(v == 0.0 ? 0.0 : v);  // no −0
  }
  out.decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  return out;
}

std::string format_tick(double value, int decimals) {
  std::string text = fmt::format("{:.{}f}", value, std::max(decimals, 0));
  if (text.front() == '-') {
    // "-0.0" is zero: print it without a sign; otherwise use the typographic minus.
    if (text.find_first_not_of("-0.") == std::string::npos) return text.substr(1);
    return "\u2212" + text.substr(1);
  }
  return text;
}

}  // namespace dynpos::report
