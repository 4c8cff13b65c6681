// The steps of estimate_gnss_arms() on their own: the time-offset search on a cost profile and
// the statistics over the converged interval.

#include "gnss_arm_steps.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace dynpos::calib::detail {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(GnssArmSteps, BestOffsetIsTheLowestFiniteCost) {
  EXPECT_EQ(best_offset_index({3.0, 1.0, 2.0, 1.0}), 1U);  // the first of equal costs
  EXPECT_EQ(best_offset_index({kNaN, 5.0, kNaN, 4.0}), 3U);
  EXPECT_EQ(best_offset_index({kNaN, kNaN}), 0U);
}

TEST(GnssArmSteps, SortOffsetScanSortsAndDropsRepeats) {
  // A coarse scan then a fine one around its best point: the fine scan repeats two δ.
  std::vector<double> x = {-0.1, 0.0, 0.1, -0.05, 0.0 + 1e-12, 0.05};
  std::vector<double> c = {3.0, 1.0, 2.0, 1.5, 9.0, 1.2};
  sort_offset_scan(x, c);
  ASSERT_EQ(x.size(), 5U);
  EXPECT_EQ(x, (std::vector<double>{-0.1, -0.05, 0.0, 0.05, 0.1}));
  EXPECT_EQ(c, (std::vector<double>{3.0, 1.5, 1.0, 1.2, 2.0}));  // the first cost of δ = 0 kept
}

TEST(GnssArmSteps, RefineOffsetFindsTheVertexOfAParabola) {
  // cost = 2·(δ − 0.013)² + 1 on a 10 ms grid: the vertex and the curvature 4 exactly (up to
  // rounding of the grid values).
  std::vector<double> x, c;
  for (int i = -5; i <= 5; ++i) {
    x.push_back(0.01 * i);
    c.push_back(2.0 * (0.01 * i - 0.013) * (0.01 * i - 0.013) + 1.0);
  }
  const std::size_t best = best_offset_index(c);
  EXPECT_DOUBLE_EQ(x[best], 0.01);
  const auto r = refine_offset(x, c, best);
  ASSERT_TRUE(r.has_value());
  EXPECT_NEAR(r->offset_s, 0.013, 1e-12);
  EXPECT_NEAR(r->curvature, 4.0, 1e-9);
}

TEST(GnssArmSteps, RefineOffsetNeedsTwoFiniteEquallySpacedNeighboursAndACup) {
  const std::vector<double> x = {0.0, 0.1, 0.2};
  EXPECT_FALSE(refine_offset(x, {1.0, 0.0, 1.0}, 0).has_value());  // at the end of the scan
  EXPECT_FALSE(refine_offset(x, {kNaN, 0.0, 1.0}, 1).has_value());
  EXPECT_FALSE(refine_offset({0.0, 0.1, 0.3}, {1.0, 0.0, 1.0}, 1).has_value());
  EXPECT_FALSE(refine_offset(x, {0.0, 1.0, 0.0}, 1).has_value());  // a cap, not a cup
  // The vertex stays within one grid step of the best point.
  const auto r = refine_offset(x, {1.0, 0.5, 1e-9}, 1);
  ASSERT_TRUE(r.has_value());
  EXPECT_LE(r->offset_s, 0.2 + 1e-15);
}

TEST(GnssArmSteps, IntervalStatisticsSkipsTheTransientAndNonFiniteSamples) {
  const std::vector<double> t = {0, 1, 2, 3, 4, 5};
  const std::vector<Eigen::Vector3d> h = {{100, 100, 100}, {100, 100, 100}, {1, 2, 3},
                                          {3, 2, 1},       {kNaN, 0, 0},    {2, 2, 2}};
  const IntervalStats s = interval_statistics(t, h, 2.0);
  EXPECT_NEAR(s.mean(0), 2.0, 1e-12);
  EXPECT_NEAR(s.mean(1), 2.0, 1e-12);
  EXPECT_NEAR(s.mean(2), 2.0, 1e-12);
  EXPECT_NEAR(s.std(0), 1.0, 1e-12);  // sample std of 1, 3, 2
  EXPECT_NEAR(s.std(1), 0.0, 1e-12);
  const IntervalStats one = interval_statistics(t, h, 5.0);
  EXPECT_NEAR(one.mean(0), 2.0, 1e-12);
  EXPECT_TRUE(std::isnan(one.std(0)));  // one sample: no spread
  EXPECT_TRUE(std::isnan(interval_statistics(t, h, 6.0).mean(0)));
}

}  // namespace
}  // namespace dynpos::calib::detail
