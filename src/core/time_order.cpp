#include "dynpos/core/time_order.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dynpos::core {
namespace {

bool finite(double x) { return std::abs(x) <= std::numeric_limits<double>::max(); }

}  // namespace

std::size_t first_unordered_time(std::span<const double> t) noexcept {
  if (t.empty()) return 0;
  if (!finite(t[0])) return 0;
  constexpr std::size_t kChunk = 2048;
  for (std::size_t begin = 1; begin < t.size(); begin += kChunk) {
    const std::size_t end = std::min(t.size(), begin + kChunk);
    unsigned ok = 1;
    for (std::size_t i = begin; i < end; ++i) {
      ok &= static_cast<unsigned>(finite(t[i])) & static_cast<unsigned>(t[i] > t[i - 1]);
    }
    if (ok != 0) continue;
    for (std::size_t i = begin; i < end; ++i) {
      if (!finite(t[i]) || !(t[i] > t[i - 1])) return i;
    }
  }
  return t.size();
}

}  // namespace dynpos::core
