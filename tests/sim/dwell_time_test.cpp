#include "dynpos/sim/dwell_time.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "dynpos/sim/sim_time.hpp"

namespace dynpos::sim {
namespace {

TEST(DwellTime, FirstJumpIsAlwaysAllowed) {
  const DwellTime dwell(2.0);
  EXPECT_TRUE(dwell.allows(-1e9));
  EXPECT_TRUE(dwell.allows(0.0));
  EXPECT_FALSE(dwell.last_jump_time().has_value());
}

TEST(DwellTime, JumpsAreAtLeastTheDwellTimeApart) {
  DwellTime dwell(2.0);
  dwell.record_jump(10.0);
  ASSERT_TRUE(dwell.last_jump_time().has_value());
  EXPECT_EQ(*dwell.last_jump_time(), 10.0);
  EXPECT_FALSE(dwell.allows(10.0));
  EXPECT_FALSE(dwell.allows(11.999));
  EXPECT_TRUE(dwell.allows(12.0));
  EXPECT_TRUE(dwell.allows(30.0));
  dwell.reset();
  EXPECT_TRUE(dwell.allows(10.0));
}

TEST(DwellTime, ZeroSlackComparesExactlyAndSlackAbsorbsTickRounding) {
  // On the grid t_k = k·0.01 s, t_205 − t_5 rounds to just below 2 s.
  const TimeGrid grid(0.01);
  const double t0 = grid.time(5), t1 = grid.time(205);
  ASSERT_LT(t1 - t0, 2.0);
  DwellTime exact(2.0);
  exact.record_jump(t0);
  EXPECT_FALSE(exact.allows(t1));
  DwellTime slack(2.0, 1e-6 * grid.dt());
  slack.record_jump(t0);
  EXPECT_TRUE(slack.allows(t1));
  EXPECT_FALSE(slack.allows(grid.time(204)));
}

TEST(DwellTime, ZeroDwellAllowsJumpsAtTheSameInstant) {
  DwellTime dwell(0.0);
  dwell.record_jump(1.0);
  EXPECT_TRUE(dwell.allows(1.0));
}

TEST(DwellTime, RejectsNegativeOrNonFiniteTimes) {
  EXPECT_THROW(DwellTime(-1.0), std::invalid_argument);
  EXPECT_THROW(DwellTime(1.0, -1e-9), std::invalid_argument);
  EXPECT_THROW(DwellTime(std::numeric_limits<double>::infinity()), std::invalid_argument);
}

}  // namespace
}  // namespace dynpos::sim
