#include "dynpos/sim/sim_time.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace dynpos::sim {
namespace {

using ::testing::HasSubstr;

TEST(TimeGrid, RejectsNonPositiveOrNonFiniteStep) {
  for (double dt : {0.0, -0.01, std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_THROW(TimeGrid{dt}, std::invalid_argument) << "dt = " << dt;
  }
}

TEST(TimeGrid, TimeIsTickTimesStepWithoutAccumulatedDrift) {
  const TimeGrid grid(0.01);
  double accumulated = 0.0;
  constexpr Tick kSteps = 1'000'000;
  for (Tick k = 0; k < kSteps; ++k) accumulated += grid.dt();
  // One multiplication is correctly rounded: 10⁶ · fl(0.01) rounds to exactly 10⁴.
  EXPECT_EQ(grid.time(kSteps), 10000.0);
  // Summing t += dt drifts by many ulps; this is what the tick grid avoids.
  EXPECT_GT(std::abs(accumulated - 10000.0), 1e-9);
  for (Tick k : {Tick{0}, Tick{1}, Tick{7}, Tick{123456}, Tick{999999}}) {
    EXPECT_EQ(grid.time(k), static_cast<double>(k) * 0.01);
  }
}

TEST(TimeGrid, TicksOfPeriodsAndRates) {
  const TimeGrid grid(0.01);
  EXPECT_EQ(grid.ticks_for_rate(100.0), 1);
  EXPECT_EQ(grid.ticks_for_rate(50.0), 2);
  EXPECT_EQ(grid.ticks_for_rate(10.0), 10);
  EXPECT_EQ(grid.ticks_for_rate(1.0), 100);
  // The thesis' sampling period T_s = 0.03 s (5.80): 0.03/0.01 = 2.9999999999999996 in floating
  // point, within the 1e-9 relative tolerance of 3.
  EXPECT_EQ(grid.ticks_for_period(0.03), 3);
  EXPECT_EQ(grid.ticks(0.0), 0);
  EXPECT_EQ(grid.ticks(3600.0), 360000);
}

TEST(TimeGrid, RejectsPeriodsOffTheGrid) {
  const TimeGrid grid(0.01);
  EXPECT_THAT([&] { (void)grid.ticks_for_rate(30.0, "gnss rate"); },
              ::testing::ThrowsMessage<std::invalid_argument>(
                  ::testing::AllOf(HasSubstr("gnss rate"), HasSubstr("not an integer multiple"))));
  EXPECT_THROW((void)grid.ticks_for_period(0.015), std::invalid_argument);
  // Off by 1e-8 relative: outside the 1e-9 relative tolerance.
  EXPECT_THROW((void)grid.ticks_for_period(0.1 * (1.0 + 1e-8)), std::invalid_argument);
  // Off by 1e-11 relative: rounding noise, accepted.
  EXPECT_EQ(grid.ticks_for_period(0.1 * (1.0 + 1e-11)), 10);
  EXPECT_THROW((void)grid.ticks_for_period(0.0), std::invalid_argument);
  EXPECT_THROW((void)grid.ticks(-0.01), std::invalid_argument);
  EXPECT_THROW((void)grid.ticks_for_rate(0.0), std::invalid_argument);
  EXPECT_THROW((void)grid.ticks_for_rate(std::numeric_limits<double>::quiet_NaN()),
               std::invalid_argument);
}

TEST(PeriodicSchedule, FiresAtOffsetAndEveryPeriodAfter) {
  struct Case {
    Tick period;
    Tick offset;
    Tick k;
    bool fires;
    Tick next;
  };
  const Case cases[] = {
      {1, 0, 0, true, 0},     {1, 0, 17, true, 17},      {10, 0, 0, true, 0},
      {10, 0, 9, false, 10},  {10, 0, 10, true, 10},     {10, 3, 0, false, 3},
      {10, 3, 3, true, 3},    {10, 3, 12, false, 13},    {10, 3, 13, true, 13},
      {10, 3, 14, false, 23}, {7, 5, 1000, false, 1006},
  };
  for (const Case& c : cases) {
    const PeriodicSchedule schedule{c.period, c.offset};
    EXPECT_EQ(schedule.fires_at(c.k), c.fires) << c.period << " " << c.offset << " " << c.k;
    EXPECT_EQ(fires_at(c.k, c.period, c.offset), c.fires);
    EXPECT_EQ(schedule.next_at_or_after(c.k), c.next) << c.period << " " << c.offset << " " << c.k;
    EXPECT_TRUE(schedule.fires_at(schedule.next_at_or_after(c.k)));
  }
}

}  // namespace
}  // namespace dynpos::sim
