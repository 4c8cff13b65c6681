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

/// The median of value(0) … value(n − 1) (the mean of the two middle ones for an even n), or
/// nullopt when there are more than kMaxDistinct distinct values, a NaN, or n = 0: then select.
template <class Value>
std::optional<double> few_valued_median(std::size_t n, Value&& value) {
  constexpr std::size_t kMaxDistinct = 64;
  if (n == 0) return std::nullopt;
  std::array<std::pair<double, std::size_t>, kMaxDistinct> seen{};  // value, count
  std::size_t distinct = 0, last = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double v = value(i);
    if (distinct > 0 && v == seen[last].first) {
      ++seen[last].second;
      continue;
    }
    if (v != v) return std::nullopt;  // NaN
    std::size_t k = 0;
    while (k < distinct && !(seen[k].first == v)) ++k;
    if (k == distinct) {
      if (distinct == kMaxDistinct) return std::nullopt;
      seen[distinct++] = {v, 0};
    }
    ++seen[k].second;
    last = k;
  }
  std::sort(seen.begin(), seen.begin() + static_cast<std::ptrdiff_t>(distinct));
  // The values of rank `rank` (0-based) in sorted order.
  const auto at_rank = [&](std::size_t rank) {
    std::size_t below = 0;
    for (std::size_t k = 0; k < distinct; ++k) {
      below += seen[k].second;
      if (rank < below) return seen[k].first;
    }
    return seen[distinct - 1].first;
  };
  const std::size_t mid = n / 2;
  const double upper = at_rank(mid);
  return n % 2 == 1 ? upper : 0.5 * (at_rank(mid - 1) + upper);
}

}  // namespace dynpos::core
