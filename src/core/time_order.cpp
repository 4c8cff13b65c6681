#include "dynpos/core/time_order.hpp"

#include <cmath>
#include <limits>

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

}  // namespace dynpos::core
