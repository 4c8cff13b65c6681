#include "dynpos/core/samples.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace dynpos::core {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(Samples, HasAValidSampleOnlyWithANumber) {
  EXPECT_FALSE(has_valid_sample({}));
  EXPECT_FALSE(has_valid_sample({kNaN, kNaN}));
  EXPECT_TRUE(has_valid_sample({kNaN, 0.0}));
}

TEST(Samples, HeldForAtMostTheHoldAfterEachSample) {
  const HeldSamples h =
      hold_samples({0.0, 1.0, 2.0, 3.5, 4.0, 6.0}, {kNaN, 5.0, kNaN, kNaN, 7.0, kNaN}, 2.0);
  EXPECT_TRUE(std::isnan(h.value[0]) && std::isnan(h.sampled_s[0]));  // no sample yet
  EXPECT_EQ(h.value[1], 5.0);
  EXPECT_EQ(h.value[2], 5.0);  // 1 s old
  EXPECT_EQ(h.sampled_s[2], 1.0);
  EXPECT_TRUE(std::isnan(h.value[3]) && std::isnan(h.sampled_s[3]));  // 2.5 s old
  EXPECT_EQ(h.value[4], 7.0);
  EXPECT_EQ(h.value[5], 7.0);  // exactly the hold
  EXPECT_EQ(h.sampled_s[5], 4.0);
}

}  // namespace
}  // namespace dynpos::core
