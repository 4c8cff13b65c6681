// The cells of the text tables: a missing figure and one that overflowed read differently.

#include "dynpos/analysis/json_fields.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>

namespace dynpos::analysis {
namespace {

TEST(NumberCell, AnOverflowIsNotShownAsMissing) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(number_cell(std::nullopt, "{:.2f}"), "—");
  EXPECT_EQ(number_cell(std::nan(""), "{:.2f}"), "—");  // NaN is the library's missing value
  EXPECT_EQ(number_cell(kInf, "{:.2f}"), "inf");
  EXPECT_EQ(number_cell(-kInf, "{:.2f}"), "-inf");
  // The largest doubles squared (a variance of positions near 1e200 m) overflow to inf.
  EXPECT_EQ(number_cell(1e200 * 1e200, "{:.3f}"), "inf");
  EXPECT_EQ(number_cell(1.5, "{:.2f}"), "1.50");
}

}  // namespace
}  // namespace dynpos::analysis
