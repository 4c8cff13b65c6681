#include "dynpos/core/time_spacing.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace dynpos::core {
namespace {

TEST(MedianSpacing, OddCountTakesTheMiddleSpacing) {
  // Spacings 0.1, 0.1, 5 (a gap): the median ignores the gap.
  EXPECT_DOUBLE_EQ(median_spacing_s({0.0, 0.1, 0.2, 5.2}, 1), 0.1);
}

TEST(MedianSpacing, EvenCountAveragesTheTwoMiddleSpacings) {
  // Spacings 1, 2, 3, 10: (2 + 3) / 2.
  EXPECT_DOUBLE_EQ(median_spacing_s({0.0, 1.0, 3.0, 6.0, 16.0}, 1), 2.5);
}

TEST(MedianSpacing, NeedsTwoTimes) {
  EXPECT_THROW(median_spacing_s({1.0}, 1), std::invalid_argument);
  EXPECT_DOUBLE_EQ(median_spacing_s({1.0, 1.5}, 1), 0.5);
}

}  // namespace
}  // namespace dynpos::core
