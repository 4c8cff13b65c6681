#include "dynpos/core/log_align.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace dynpos::core {
namespace {

TEST(AddAligned, OffsetShiftsSourceSamplesOntoTheTargetClock) {
  Log target(std::vector<double>{10.0, 10.5, 11.0, 11.5, 12.0, 12.5});
  target.add_channel("x", "m", {0.0, 1.0, 2.0, 3.0, 4.0, 5.0});
  // Source clock 10.5 s behind: its samples at 0, 1 s are at 10.5, 11.5 s on the target clock.
  Log source(std::vector<double>{0.0, 1.0});
  source.add_channel("y", "m", {3.0, 5.0});
  source.add_channel("mode", "1", {7.0, 8.0}, Interp::kHold);
  add_aligned(target, source, 10.5);
  const std::vector<double>& y = target.values("y");
  EXPECT_TRUE(std::isnan(y[0]));             // before the source's first sample: no extrapolation
  EXPECT_EQ(y[1], 3.0);                      // exactly on sample 0
  EXPECT_EQ(y[2], 4.0);                      // midway, linear (exact in binary)
  EXPECT_EQ(y[3], 5.0);                      // exactly on sample 1
  EXPECT_TRUE(std::isnan(y[4]));             // after the last sample
  EXPECT_EQ(target.values("mode")[2], 7.0);  // held
  EXPECT_EQ(target.channel("mode").interp, Interp::kHold);
  EXPECT_EQ(target.values("x")[5], 5.0);  // the target's own channels are untouched
}

TEST(AddAligned, RejectsABadOffsetAndATakenName) {
  Log target(std::vector<double>{0.0, 1.0});
  target.add_channel("x", "m", {0.0, 1.0});
  Log source(std::vector<double>{0.0, 1.0});
  source.add_channel("x", "m", {0.0, 1.0});
  EXPECT_THROW(add_aligned(target, source, 0.0), std::invalid_argument);
  EXPECT_THROW(add_aligned(target, source, std::numeric_limits<double>::quiet_NaN()),
               std::invalid_argument);
}

}  // namespace
}  // namespace dynpos::core
