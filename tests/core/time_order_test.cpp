// core::first_unordered_time: the first sample of a time axis that is not finite or not later
// than the one before, against a plain loop, wherever it falls in the chunks it is checked in.

#include "dynpos/core/time_order.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace dynpos::core {
namespace {

std::size_t plain_loop(const std::vector<double>& t) {
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!std::isfinite(t[i]) || (i > 0 && !(t[i] > t[i - 1]))) return i;
  }
  return t.size();
}

std::vector<double> axis(std::size_t n) {
  std::vector<double> t(n);
  for (std::size_t i = 0; i < n; ++i) t[i] = 0.01 * static_cast<double>(i);
  return t;
}

TEST(FirstUnorderedTime, AnIncreasingAxisHasNone) {
  EXPECT_EQ(first_unordered_time({}), 0u);
  for (std::size_t n : {1u, 2u, 2048u, 2049u, 10'000u}) {
    EXPECT_EQ(first_unordered_time(axis(n)), n) << n;
  }
}

TEST(FirstUnorderedTime, EveryDefectAtEveryPlaceOfAChunk) {
  const double nan = std::nan("");
  const double inf = std::numeric_limits<double>::infinity();
  for (std::size_t at : {0u, 1u, 2u, 1000u, 2047u, 2048u, 2049u, 4096u, 4097u, 9999u}) {
    for (int defect = 0; defect < 5; ++defect) {
      std::vector<double> t = axis(10'000);
      switch (defect) {
        case 0:
          t[at] = nan;
          break;
        case 1:
          t[at] = inf;
          break;
        case 2:
          t[at] = -inf;
          break;
        case 3:
          t[at] = at > 0 ? t[at - 1] : nan;
          break;  // a repeated time
        default:
          t[at] = at > 0 ? t[at - 1] - 1.0 : inf;
          break;  // back in time
      }
      EXPECT_EQ(first_unordered_time(t), plain_loop(t)) << "defect " << defect << " at " << at;
    }
  }
}

}  // namespace
}  // namespace dynpos::core
