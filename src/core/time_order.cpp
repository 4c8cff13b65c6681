#include "dynpos/core/time_order.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "dynpos/core/parallel_for.hpp"

namespace dynpos::core {
namespace {

bool finite(double x) { return std::abs(x) <= std::numeric_limits<double>::max(); }

}  // namespace

std::size_t first_unordered_time(std::span<const double> t) noexcept {
  if (t.empty()) return 0;
  if (!finite(t[0])) return 0;
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (!finite(t[i]) || !(t[i] > t[i - 1])) return i;
  }
  return t.size();
}

std::size_t first_unordered_time(std::span<const double> t, unsigned jobs) {
  constexpr std::size_t kShortest = 1 << 18;  // a piece is checked in about half a millisecond
  const std::size_t n = t.size();
  const std::size_t pieces = piece_count(n, job_count(jobs, n), kShortest);
  if (pieces <= 1) return first_unordered_time(t);
  std::vector<std::size_t> first(pieces);
  parallel_for(pieces, jobs, [&](std::size_t k) {
    // Piece k compares its samples with the ones before them, the first with the last of k − 1.
    const auto [begin, end] = piece_of(n, pieces, k);
    const std::size_t from = begin == 0 ? 0 : begin - 1;
    const std::size_t i = first_unordered_time(t.subspan(from, end - from));
    first[k] = i == end - from ? n : (k == 0 ? i : std::max<std::size_t>(from + i, begin));
  });
  return *std::min_element(first.begin(), first.end());
}

}  // namespace dynpos::core
