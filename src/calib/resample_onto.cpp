#include "resample_onto.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace dynpos::calib::detail {

std::vector<double> resample_onto(const std::vector<double>& t, const std::vector<double>& v,
                                  const std::vector<double>& grid, bool unwrap) {
  std::vector<double> ts, vs;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!std::isfinite(v[i])) continue;
    double x = v[i];
    if (unwrap && !vs.empty()) {
      const double two_pi = 2.0 * std::numbers::pi;
      x -= two_pi * std::round((x - vs.back()) / two_pi);
    }
    ts.push_back(t[i]);
    vs.push_back(x);
  }
  std::vector<double> out(grid.size(), std::numeric_limits<double>::quiet_NaN());
  if (ts.empty()) return out;
  std::size_t j = 0;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const double g = grid[i];
    if (g < ts.front() || g > ts.back()) continue;
    while (j + 1 < ts.size() && ts[j + 1] < g) ++j;
    if (j + 1 >= ts.size()) {
      out[i] = vs.back();
      continue;
    }
    const double a = (g - ts[j]) / (ts[j + 1] - ts[j]);
    out[i] = (g <= ts[j]) ? vs[j] : (1.0 - a) * vs[j] + a * vs[j + 1];
  }
  return out;
}

}  // namespace dynpos::calib::detail
