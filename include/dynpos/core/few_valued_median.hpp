#pragma once
/// \file
/// The exact median of a long series that takes few distinct values, by counting them: the
/// spacings of a regularly sampled time axis, the differences of a piecewise-constant command.
/// One pass with no copy and no sort of the series; the same value a selection (nth_element)
/// gives, since a median is an order statistic of the values whatever their order.

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
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
/// nullopt when there are more than FewValues::kMaxDistinct, a NaN, or n = 0. Values are told
/// apart as == does (+0 and −0 are one value, kept as first seen).
template <class Value>
std::optional<FewValues> few_values(std::size_t n, Value&& value) {
  if (n == 0) return std::nullopt;
  FewValues out;
  out.n = n;
  auto& seen = out.counts;
  // An open-addressing table on the value's bits, twice as many slots as values: a value is
  // found in about one probe however many there are (a time axis' spacings alternate between a
  // few round-off variants, so the last value seen is often not the next one).
  constexpr std::size_t kSlots = 2 * FewValues::kMaxDistinct;
  constexpr std::uint8_t kEmpty = 0xFF;
  static_assert(FewValues::kMaxDistinct < kEmpty);
  std::array<std::uint64_t, kSlots> slot_bits{};
  std::array<std::uint8_t, kSlots> slot_index;
  slot_index.fill(kEmpty);
  std::size_t last = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double v = value(i);
    if (out.distinct > 0 && v == seen[last].first) {
      ++seen[last].second;
      continue;
    }
    if (v != v) return std::nullopt;  // NaN
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(v == 0.0 ? 0.0 : v);
    std::size_t h = static_cast<std::size_t>((bits * 0x9E3779B97F4A7C15ULL) >> 57);
    while (slot_index[h] != kEmpty && slot_bits[h] != bits) h = (h + 1) % kSlots;
    if (slot_index[h] == kEmpty) {
      if (out.distinct == FewValues::kMaxDistinct) return std::nullopt;
      slot_bits[h] = bits;
      slot_index[h] = static_cast<std::uint8_t>(out.distinct);
      seen[out.distinct++] = {v, 0};
    }
    last = slot_index[h];
    ++seen[last].second;
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
