// The plateaus of a step detector's input scanned in pieces, one per thread, and joined: the same
// plateaus as one scan of the whole input, however the pieces' edges fall against steps, holds
// and drifts.

#include "plateaus.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "synthetic.hpp"

namespace dynpos::ident::detail {
namespace {

using testing::sample;
using testing::time_axis;

void expect_same_plateaus(const std::vector<Plateau>& a, const std::vector<Plateau>& b,
                          const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].begin, b[k].begin) << what << " plateau " << k;
    EXPECT_EQ(a[k].end, b[k].end) << what << " plateau " << k;
    EXPECT_EQ(a[k].start_level, b[k].start_level) << what << " plateau " << k;
    EXPECT_EQ(a[k].end_level, b[k].end_level) << what << " plateau " << k;
    EXPECT_EQ(a[k].head_level, b[k].head_level) << what << " plateau " << k;
    EXPECT_EQ(a[k].tail_level, b[k].tail_level) << what << " plateau " << k;
  }
}

// Where a piece starts inside a drift, its own scan starts a plateau at another level than the
// whole scan's, and splits it elsewhere: the join must scan on until both hold the same level.
// A piece inside a noisy hold never meets such a point and is scanned again whole.
TEST(Plateaus, SameOnAnyNumberOfThreads) {
  const std::vector<double> t = time_axis(0.0, 0.01, 400'001, 0.3, 23);  // 4000 s at 100 Hz
  const std::vector<double> u = sample(
      t,
      [](double x) {
        if (x < 300.0) return 0.0;
        if (x < 1500.0) return 0.2 + 4e-5 * (x - 300.0);  // a drift of 0.048 over 1200 s
        if (x < 1510.0) return 0.1;
        if (x < 2600.0) return 0.1 + 0.01 * std::sin(x / 50.0);  // a slow swing
        return 0.4;                                              // a hold of 1400 s
      },
      0.002, 29);
  const double h = 0.01, w = 3.0;
  const std::vector<Plateau> serial = find_plateaus(t, u, h, w, 1);
  ASSERT_GE(serial.size(), 8u);  // the drift and the swing split their plateaus
  for (unsigned jobs : {2u, 3u, 5u, 8u, 16u, 24u}) {
    expect_same_plateaus(serial, find_plateaus(t, u, h, w, jobs), std::to_string(jobs));
  }
}

// The plateaus by their definition, window by window, each window's extremes taken whole: the
// rule of the file comment of step_detector.hpp (begin and end of each plateau).
std::vector<std::pair<std::size_t, std::size_t>> plateaus_by_definition(
    const std::vector<double>& t, const std::vector<double>& u, double h, double w) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  double ref = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    std::size_t last = i;
    double lo = u[i], hi = u[i];
    while (last + 1 < t.size() && t[last + 1] <= t[i] + w) {
      ++last;
      lo = std::min(lo, u[last]);
      hi = std::max(hi, u[last]);
    }
    if (t[last] - t[i] < 0.5 * w || hi - lo > 2.0 * h) continue;
    const double mid = 0.5 * (hi + lo);
    if (!out.empty() && i <= out.back().second + 1 && std::abs(mid - ref) <= h) {
      out.back().second = std::max(out.back().second, last);
      continue;
    }
    const std::size_t begin = out.empty() ? i : std::max(i, out.back().second + 1);
    if (begin > last) continue;
    out.emplace_back(begin, last);
    ref = mid;
  }
  return out;
}

void expect_definition(const std::vector<double>& t, const std::vector<double>& u, double h,
                       double w, const std::string& what) {
  const auto expected = plateaus_by_definition(t, u, h, w);
  for (unsigned jobs : {1u, 3u}) {
    const std::vector<Plateau> found = find_plateaus(t, u, h, w, jobs);
    ASSERT_EQ(found.size(), expected.size()) << what << " on " << jobs;
    for (std::size_t k = 0; k < found.size(); ++k) {
      EXPECT_EQ(found[k].begin, expected[k].first) << what << " on " << jobs << ", " << k;
      EXPECT_EQ(found[k].end, expected[k].second) << what << " on " << jobs << ", " << k;
    }
  }
}

// Blocks of held level are passed without their windows' extremes: the plateaus are still those
// of the definition, through gaps, steps, a drift, and levels so large that a window's
// mid-level 0.5·(hi + lo) overflows (there the rule splits every window off, and so must the
// scan).
TEST(Plateaus, TheDefinitionsWindowByWindow) {
  const std::vector<double> t = time_axis(0.0, 0.01, 60'001, 0.3, 31);  // 600 s at 100 Hz
  std::vector<double> gaps = t;
  for (std::size_t i = 20'000; i < gaps.size(); ++i) gaps[i] += i < 40'000 ? 2.5 : 9.0;
  const std::vector<double> u = sample(
      t, [](double x) { return x < 200.0 ? 0.1 : (x < 400.0 ? 0.3 + 5e-5 * (x - 400.0) : 0.2); },
      0.002, 37);
  expect_definition(t, u, 0.01, 3.0, "steps and a drift");
  expect_definition(gaps, u, 0.01, 3.0, "gaps");
  std::vector<double> huge(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    huge[i] = i < 10'000 ? 0.0 : (i < 20'000 ? 0.85e308 : 0.9e308);
  }
  expect_definition(t, huge, 0.06e308, 3.0, "levels near the largest double");
}

}  // namespace
}  // namespace dynpos::ident::detail
