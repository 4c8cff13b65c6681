#include "dynpos/report/axis_ticks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace dynpos::report {
namespace {

// Tick values are k·step with an integer k, so they must equal the decimal literals to within
// one rounding of the multiplication (a few ulp): 1e-12 relative to the step is far tighter
// than any label needs and far looser than the rounding.
void expect_ticks(const AxisTicks& t, const std::vector<double>& expected) {
  ASSERT_EQ(t.values.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(t.values[i], expected[i], 1e-12 * t.step) << "tick " << i;
  }
}

TEST(NiceStep, PicksOneTwoFiveTimesAPowerOfTen) {
  EXPECT_DOUBLE_EQ(nice_step(10.0, 5), 2.0);
  EXPECT_DOUBLE_EQ(nice_step(10.0, 10), 1.0);
  EXPECT_DOUBLE_EQ(nice_step(60.0, 10), 10.0);  // 6 → 10
  EXPECT_DOUBLE_EQ(nice_step(0.3, 6), 0.05);
  EXPECT_DOUBLE_EQ(nice_step(4.5e5, 5), 1.0e5);  // 9e4 → 1e5
  EXPECT_DOUBLE_EQ(nice_step(3.0, 1), 5.0);
  EXPECT_DOUBLE_EQ(nice_step(0.0, 5), 1.0);  // degenerate span
}

TEST(NiceTicks, ExpandsToWholeSteps) {
  const AxisTicks t = nice_ticks(0.3, 9.2, 5);
  EXPECT_DOUBLE_EQ(t.step, 2.0);
  EXPECT_DOUBLE_EQ(t.lo, 0.0);
  EXPECT_DOUBLE_EQ(t.hi, 10.0);
  expect_ticks(t, {0, 2, 4, 6, 8, 10});
  EXPECT_EQ(t.decimals, 0);
}

TEST(NiceTicks, FixedRangeKeepsOnlyTicksInside) {
  const AxisTicks t = nice_ticks(4.9, 7.3, 6, false);
  EXPECT_DOUBLE_EQ(t.lo, 4.9);
  EXPECT_DOUBLE_EQ(t.hi, 7.3);
  EXPECT_DOUBLE_EQ(t.step, 0.5);
  expect_ticks(t, {5.0, 5.5, 6.0, 6.5, 7.0});
  EXPECT_EQ(t.decimals, 1);
}

TEST(NiceTicks, NegativeAndTinyRanges) {
  // 155/6 ≈ 25.8 rounds up to the nice step 50.
  expect_ticks(nice_ticks(-52.0, 103.0, 6), {-100, -50, 0, 50, 100, 150});
  const AxisTicks tiny = nice_ticks(1e-4, 3e-4, 4);
  EXPECT_DOUBLE_EQ(tiny.step, 5e-5);
  EXPECT_EQ(tiny.decimals, 5);
  expect_ticks(tiny, {1e-4, 1.5e-4, 2e-4, 2.5e-4, 3e-4});
}

TEST(NiceTicks, DegenerateAndNonFiniteRanges) {
  const AxisTicks flat = nice_ticks(5.0, 5.0, 5);
  EXPECT_LT(flat.lo, 5.0);
  EXPECT_GT(flat.hi, 5.0);
  const AxisTicks zero = nice_ticks(0.0, 0.0, 5);
  EXPECT_LE(zero.lo, -1.0);
  EXPECT_GE(zero.hi, 1.0);
  const AxisTicks nan = nice_ticks(std::nan(""), 1.0, 5);
  EXPECT_DOUBLE_EQ(nan.lo, 0.0);
  EXPECT_DOUBLE_EQ(nan.hi, 1.0);
  const AxisTicks swapped = nice_ticks(10.0, 0.0, 5);
  EXPECT_DOUBLE_EQ(swapped.lo, 0.0);
  EXPECT_DOUBLE_EQ(swapped.hi, 10.0);
}

TEST(NiceTicks, NoAccumulatedRounding) {
  // 0.1 added seven times is 0.7000000000000001; k·step formatted must read 0.7.
  const AxisTicks t = nice_ticks(0.0, 1.0, 10);
  ASSERT_EQ(t.values.size(), 11u);
  EXPECT_EQ(format_tick(t.values[7], t.decimals), "0.7");
  EXPECT_EQ(format_tick(t.values[3], t.decimals), "0.3");
}

TEST(FormatTick, MinusSignAndNegativeZero) {
  EXPECT_EQ(format_tick(-2.5, 1), "\u22122.5");
  EXPECT_EQ(format_tick(-0.0, 1), "0.0");
  EXPECT_EQ(format_tick(-0.00001, 2), "0.00");
  EXPECT_EQ(format_tick(1500.0, 0), "1500");
}

}  // namespace
}  // namespace dynpos::report
