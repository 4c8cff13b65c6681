#pragma once
/// \file
/// The exact median of a long series that takes few distinct values, by counting them: the
/// spacings of a regularly sampled time axis, the differences of a piecewise-constant command.
/// One pass with no copy and no sort of the series; the same value a selection (nth_element)
/// gives, since a median is an order statistic of the values whatever their order.

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <utility>

namespace dynpos::core {

/// The distinct values of a series, sorted, each with how often it occurs.
struct FewValues {
  static constexpr std::size_t kMaxDistinct = 64;
  std::array<std::pair<double, std::size_t>, kMaxDistinct> counts{};  ///< value, count
  std::size_t distinct = 0;
  std::size_t n = 0;  ///< the series' length: the sum of the counts

  /// The value of rank `rank` (0-based) in sorted order; rank < n.
  double at_rank(std::size_t rank) const {
    std::size_t below = 0;
    for (std::size_t k = 0; k < distinct; ++k) {
      below += counts[k].second;
      if (rank < below) return counts[k].first;
    }
    return counts[distinct - 1].first;
  }
};

/// The distinct values of value(0) … value(n − 1) with their counts, in one pass with no copy;
/// nullopt when there are more than FewValues::kMaxDistinct, a NaN, or n = 0.
template <class Value>
std::optional<FewValues> few_values(std::size_t n, Value&& value) {
  if (n == 0) return std::nullopt;
  FewValues out;
  out.n = n;
  auto& seen = out.counts;
  std::size_t last = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double v = value(i);
    if (out.distinct > 0 && v == seen[last].first) {
      ++seen[last].second;
      continue;
    }
    if (v != v) return std::nullopt;  // NaN
    std::size_t k = 0;
    while (k < out.distinct && !(seen[k].first == v)) ++k;
    if (k == out.distinct) {
      if (out.distinct == FewValues::kMaxDistinct) return std::nullopt;
      seen[out.distinct++] = {v, 0};
    }
    ++seen[k].second;
    last = k;
  }
  std::sort(seen.begin(), seen.begin() + static_cast<std::ptrdiff_t>(out.distinct));
  return out;
}

/// The median of value(0) … value(n − 1) (the mean of the two middle ones for an even n), or
/// nullopt when there are more than FewValues::kMaxDistinct distinct values, a NaN, or n = 0:
/// then select.
template <class Value>
std::optional<double> few_valued_median(std::size_t n, Value&& value) {
  const std::optional<FewValues> few = few_values(n, std::forward<Value>(value));
  if (!few) return std::nullopt;
  const std::size_t mid = n / 2;
  const double upper = few->at_rank(mid);
  return n % 2 == 1 ? upper : 0.5 * (few->at_rank(mid - 1) + upper);
}

}  // namespace dynpos::core
