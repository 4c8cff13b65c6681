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
#include <vector>

#include "dynpos/core/parallel_for.hpp"

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

  /// The median of the counted values (the mean of the two middle ones for an even n); n > 0.
  double median() const {
    const std::size_t mid = n / 2;
    const double upper = at_rank(mid);
    return n % 2 == 1 ? upper : 0.5 * (at_rank(mid - 1) + upper);
  }

  /// The counts of f(v) for the counted values v, or nullopt when f gives a NaN, as a count of
  /// f over the series itself would: values that f maps to equal results (as == tells them
  /// apart) are merged. For an f whose results are never −0 (a square, an absolute value):
  /// which zero a merged value keeps is otherwise the first counted, not the first in the series.
  template <class F>
  std::optional<FewValues> mapped(F&& f) const {
    FewValues out;
    out.n = n;
    for (std::size_t k = 0; k < distinct; ++k) {
      const double y = f(counts[k].first);
      if (y != y) return std::nullopt;  // NaN
      std::size_t j = 0;
      while (j < out.distinct && !(out.counts[j].first == y)) ++j;
      if (j == out.distinct) out.counts[out.distinct++] = {y, 0};
      out.counts[j].second += counts[k].second;
    }
    std::sort(out.counts.begin(), out.counts.begin() + static_cast<std::ptrdiff_t>(out.distinct));
    return out;
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

/// The counts of a series from those of its first part and of the rest: the same as counting it
/// whole (a value seen in both keeps the first part's zero sign), nullopt when they hold more than
/// FewValues::kMaxDistinct values together.
inline std::optional<FewValues> joined_counts(const FewValues& first, const FewValues& rest) {
  FewValues out;
  out.n = first.n + rest.n;
  std::size_t a = 0, b = 0;
  while (a < first.distinct || b < rest.distinct) {
    if (out.distinct == FewValues::kMaxDistinct) return std::nullopt;
    const bool take_a = b == rest.distinct ||
                        (a < first.distinct && !(rest.counts[b].first < first.counts[a].first));
    const bool take_b = a == first.distinct ||
                        (b < rest.distinct && !(first.counts[a].first < rest.counts[b].first));
    out.counts[out.distinct] = take_a ? first.counts[a] : rest.counts[b];
    if (take_a && take_b) out.counts[out.distinct].second += rest.counts[b].second;
    ++out.distinct;
    a += take_a ? 1 : 0;
    b += take_b ? 1 : 0;
  }
  return out;
}

/// few_values() of a long series counted in pieces on `jobs` threads (0 = every core), then
/// joined: the same result, whatever the number of threads.
template <class Value>
std::optional<FewValues> few_values(std::size_t n, unsigned jobs, const Value& value) {
  constexpr std::size_t kShortest = 1 << 18;  // a piece is counted in about a millisecond
  const std::size_t pieces = piece_count(n, job_count(jobs, n), kShortest);
  if (pieces <= 1) return few_values(n, value);
  std::vector<std::optional<FewValues>> counted(pieces);
  parallel_for(pieces, jobs, [&](std::size_t k) {
    const std::pair<std::size_t, std::size_t> piece = piece_of(n, pieces, k);
    const std::size_t begin = piece.first, end = piece.second;  // captured below: no binding
    counted[k] = few_values(end - begin, [&](std::size_t i) { return value(begin + i); });
  });
  std::optional<FewValues> out = counted.front();
  for (std::size_t k = 1; k < pieces && out; ++k) {
    out = counted[k] ? joined_counts(*out, *counted[k]) : std::nullopt;
  }
  return out;
}

/// The median of value(0) … value(n − 1) (the mean of the two middle ones for an even n), or
/// nullopt when there are more than FewValues::kMaxDistinct distinct values, a NaN, or n = 0:
/// then select.
template <class Value>
std::optional<double> few_valued_median(std::size_t n, Value&& value) {
  const std::optional<FewValues> few = few_values(n, std::forward<Value>(value));
  if (!few) return std::nullopt;
  return few->median();
}

}  // namespace dynpos::core
