#include "dynpos/core/samples.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dynpos::core {

bool has_valid_sample(const std::vector<double>& x) noexcept {
  return std::any_of(x.begin(), x.end(), [](double v) { return !std::isnan(v); });
}

HeldSamples hold_samples(const std::vector<double>& t_s, const std::vector<double>& x,
                         double max_hold_s) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  HeldSamples out{std::vector<double>(x.size(), kNaN), std::vector<double>(x.size(), kNaN)};
  double last_t = -std::numeric_limits<double>::infinity(), last = kNaN;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isnan(x[i])) last_t = t_s[i], last = x[i];
    if (t_s[i] - last_t <= max_hold_s) out.value[i] = last, out.sampled_s[i] = last_t;
  }
  return out;
}

}  // namespace dynpos::core
