#include "dynpos/report/decimate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace dynpos::report {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(MinmaxDecimate, KeepsAtMostFourPointsPerColumn) {
  std::vector<double> x(100000), y(100000);
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] = static_cast<double>(i) * 1e-3;
    y[i] = std::sin(x[i]);
  }
  const auto keep = minmax_decimate(x, y, 0.0, 100.0, 500);
  EXPECT_LE(keep.size(), 4u * 500u + 8u);
  EXPECT_GE(keep.size(), 500u);
  EXPECT_TRUE(std::is_sorted(keep.begin(), keep.end()));
  EXPECT_EQ(keep.front(), 0u);
  EXPECT_EQ(keep.back(), x.size() - 1);
}

TEST(MinmaxDecimate, KeepsASinglePointSpike) {
  std::vector<double> x(10000), y(10000, 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = static_cast<double>(i);
  y[4321] = 7.0;   // a one-sample peak, lost by every-n-th-point decimation
  y[8765] = -3.0;  // and a trough
  const auto keep = minmax_decimate(x, y, 0.0, 9999.0, 100);
  EXPECT_NE(std::find(keep.begin(), keep.end(), 4321u), keep.end());
  EXPECT_NE(std::find(keep.begin(), keep.end(), 8765u), keep.end());
}

TEST(MinmaxDecimate, KeepsOneMarkerPerGap) {
  const std::vector<double> x = {0, 1, 2, 3, 4, 5, 6, 7};
  const std::vector<double> y = {1, 1, kNaN, kNaN, kNaN, 2, 2, 2};
  const auto keep = minmax_decimate(x, y, 0.0, 7.0, 1);
  // Columns: one for all finite points, but the gap splits the runs: {0, 1}, gap 2, {5, 6, 7}.
  const std::vector<std::size_t> expected = {0, 1, 2, 5, 7};
  EXPECT_EQ(keep, expected);
}

TEST(MinmaxDecimate, PointsOutsideTheRangeKeepTheirEdges) {
  std::vector<double> x(1000), y(1000);
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] = static_cast<double>(i);
    y[i] = static_cast<double>(i % 7);
  }
  const auto keep = minmax_decimate(x, y, 400.0, 600.0, 10);
  // The last point before 400 and the first after 600 are kept, so lines reach the edges.
  EXPECT_NE(std::find(keep.begin(), keep.end(), 399u), keep.end());
  EXPECT_NE(std::find(keep.begin(), keep.end(), 601u), keep.end());
  EXPECT_LT(keep.size(), 60u);  // 12 columns (10 + outside left/right) × ≤ 4
}

TEST(MinmaxDecimate, EmptyAndMismatchedInput) {
  EXPECT_TRUE(minmax_decimate({}, {}, 0.0, 1.0, 10).empty());
  const std::vector<double> x = {0.0, 1.0, 2.0};
  const std::vector<double> y = {5.0};
  EXPECT_EQ(minmax_decimate(x, y, 0.0, 2.0, 10).size(), 1u);
}

}  // namespace
}  // namespace dynpos::report
