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

// A long axis is checked in pieces, one per thread: the first defect is found wherever it falls
// against the pieces' edges, and an earlier defect in a later piece's thread still wins.
TEST(FirstUnorderedTime, InPiecesOnAnyNumberOfThreads) {
  const std::size_t n = 4 * (std::size_t{1} << 18) + 5;
  const std::vector<double> clean = axis(n);
  EXPECT_EQ(first_unordered_time(clean, 4), n);
  std::vector<std::size_t> places = {0, 1, n - 1};
  for (std::size_t pieces = 2; pieces <= 4; ++pieces) {
    for (std::size_t k = 1; k < pieces; ++k) {
      const std::size_t edge = n * k / pieces;
      for (std::size_t at : {edge - 1, edge, edge + 1}) places.push_back(at);
    }
  }
  for (const std::size_t at : places) {
    for (const bool repeat : {false, true}) {
      std::vector<double> t = clean;
      t[at] = repeat && at > 0 ? t[at - 1] : std::nan("");
      for (unsigned jobs : {1u, 2u, 3u, 4u, 0u}) {
        EXPECT_EQ(first_unordered_time(t, jobs), plain_loop(t)) << at << " on " << jobs;
      }
    }
  }
  std::vector<double> two = clean;  // defects in the first and the last piece
  two[n - 10] = std::nan("");
  two[10] = two[9];
  for (unsigned jobs : {2u, 3u, 4u}) EXPECT_EQ(first_unordered_time(two, jobs), 10u);
}

}  // namespace
}  // namespace dynpos::core
