#include "dynpos/core/circular_stats.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "dynpos/core/angle.hpp"

namespace dynpos::core {
namespace {

// Both overloads in one pass shape; `weight(i)` returns the weight of sample i (NaN = skip).
template <typename WeightFn>
CircularStats compute(std::span<const double> angles_rad, WeightFn weight) {
  CircularStats stats;
  double sum_c = 0.0;
  double sum_s = 0.0;
  for (std::size_t i = 0; i < angles_rad.size(); ++i) {
    const double w = weight(i);
    const double a = angles_rad[i];
    if (std::isnan(a) || std::isnan(w)) continue;
    sum_c += w * std::cos(a);
    sum_s += w * std::sin(a);
    stats.weight_sum += w;
    ++stats.count;
  }
  if (stats.count == 0 || !(stats.weight_sum > 0.0)) return stats;

  const double r_bar = std::hypot(sum_c, sum_s) / stats.weight_sum;
  if (r_bar < kMinResultantLength) {
    stats.resultant_length = r_bar;
    stats.std_rad =
        r_bar > 0.0 ? std::sqrt(-2.0 * std::log(r_bar)) : std::numeric_limits<double>::infinity();
    return stats;
  }
  const double mean = wrap_pi(std::atan2(sum_s, sum_c));
  stats.mean_rad = mean;

  // 1 − R̄ from the first pass cancels catastrophically for a tight spread (σ = 1e-8 rad gives
  // R̄ = 1 in double). About the mean direction R̄ = Σwᵢ cos(θᵢ − θ̄)/W exactly, and
  // 1 − cos d = 2 sin²(d/2) has no cancellation, so a second pass gets 1 − R̄ to full precision.
  double sum_one_minus_cos = 0.0;
  for (std::size_t i = 0; i < angles_rad.size(); ++i) {
    const double w = weight(i);
    const double a = angles_rad[i];
    if (std::isnan(a) || std::isnan(w)) continue;
    const double half = 0.5 * angle_diff(a, mean);
    sum_one_minus_cos += w * 2.0 * std::sin(half) * std::sin(half);
  }
  const double one_minus_r = std::min(sum_one_minus_cos / stats.weight_sum, 1.0);
  stats.resultant_length = 1.0 - one_minus_r;
  stats.std_rad = std::sqrt(-2.0 * std::log1p(-one_minus_r));
  return stats;
}

}  // namespace

CircularStats circular_stats(std::span<const double> angles_rad) {
  return compute(angles_rad, [](std::size_t) { return 1.0; });
}

CircularStats circular_stats(std::span<const double> angles_rad, std::span<const double> weights) {
  if (weights.size() != angles_rad.size()) {
    throw std::invalid_argument("circular_stats: " + std::to_string(weights.size()) +
                                " weights for " + std::to_string(angles_rad.size()) +
                                " angles; give one weight per angle");
  }
  for (std::size_t i = 0; i < weights.size(); ++i) {
    if (weights[i] < 0.0 || std::isinf(weights[i])) {
      throw std::invalid_argument("circular_stats: weight " + std::to_string(i) + " is " +
                                  std::to_string(weights[i]) +
                                  "; weights must be finite and >= 0 (NaN marks a missing sample)");
    }
  }
  return compute(angles_rad, [weights](std::size_t i) { return weights[i]; });
}

std::optional<double> circular_mean(std::span<const double> angles_rad) {
  return circular_stats(angles_rad).mean_rad;
}

}  // namespace dynpos::core
