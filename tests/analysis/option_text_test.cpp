// Option values given as text: NAME=VALUE pairs, lists of numbers, seeds, lever arms, and X,Y,Z
// written back for the help.

#include "dynpos/analysis/option_text.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

#include "dynpos/analysis/option_spelling.hpp"
#include "dynpos/analysis/options.hpp"
#include "input_error_capture.hpp"

namespace dynpos::analysis {
namespace {

using testing::input_error;

TEST(OptionText, AnAssignmentSplitsAtItsFirstEqualsSign) {
  const auto pair = split_assignment("gnss1=a=b.csv");
  ASSERT_TRUE(pair.has_value());
  EXPECT_EQ(pair->first, "gnss1");
  EXPECT_EQ(pair->second, "a=b.csv");
  EXPECT_FALSE(split_assignment("gnss1").has_value());
  EXPECT_FALSE(split_assignment("gnss1=").has_value());
  EXPECT_FALSE(split_assignment("=FILE").has_value());
  EXPECT_FALSE(split_assignment("").has_value());
}

TEST(OptionText, NumbersAreCommaSeparatedWithTrailingSpacesAllowed) {
  EXPECT_EQ(parse_numbers("1,2.5,-3e2", "window"), (std::vector<double>{1.0, 2.5, -300.0}));
  EXPECT_EQ(parse_numbers(" 4 ,5 ", "window"), (std::vector<double>{4.0, 5.0}));
  EXPECT_TRUE(parse_numbers("", "window").empty());
}

TEST(OptionText, AnItemThatIsNoNumberNamesItselfTheTextAndTheKey) {
  const core::InputError e = input_error([] { parse_numbers("1,2x,3", "current"); });
  EXPECT_EQ(e.option(), "current");
  EXPECT_EQ(e.problem(), "'2x' in '1,2x,3' is not a number");
  EXPECT_EQ(e.hint(), "give comma-separated numbers");
  EXPECT_EQ(input_error([] { parse_numbers("1,,3", "window"); }).problem(),
            "'' in '1,,3' is not a number");
}

TEST(OptionText, ASeedIsADecimalNumberUpToTwoToTheSixtyFourMinusOne) {
  EXPECT_EQ(parse_seed("0"), 0u);
  EXPECT_EQ(parse_seed("42"), 42u);
  EXPECT_EQ(parse_seed("0007"), 7u);
  EXPECT_EQ(parse_seed("18446744073709551615"), std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ(parse_seed("000018446744073709551615"), std::numeric_limits<std::uint64_t>::max());
  for (const char* bad : {"", "-1", "+1", " 1", "1 ", "1.0", "0x10", "18446744073709551616",
                          "99999999999999999999999"}) {
    EXPECT_FALSE(parse_seed(bad).has_value()) << "'" << bad << "'";
  }
}

TEST(OptionText, AVectorIsWrittenAsParseVec3ReadsIt) {
  EXPECT_EQ(vec3_text(Eigen::Vector3d(0.02, 0.02, 20.0)), "0.02,0.02,20");
  EXPECT_EQ(vec3_text(Eigen::Vector3d(-1.5, 0.0, 1e-7)), "-1.5,0,1e-07");
  const Eigen::Vector3d v(0.1, -2.0 / 3.0, 123456.789);
  EXPECT_EQ(parse_vec3(vec3_text(v), "w1", "1,2,3"), v);  // exact: the shortest exact form
}

TEST(OptionText, AnArmHasTwoOrThreeNumbers) {
  EXPECT_FALSE(arm_from_numbers({}, "arm").has_value());
  EXPECT_EQ(arm_from_numbers({0.2, -0.6}, "arm"), Eigen::Vector3d(0.2, -0.6, 0.0));
  EXPECT_EQ(arm_from_numbers({0.2, -0.6, -13.9}, "arm"), Eigen::Vector3d(0.2, -0.6, -13.9));
  const core::InputError e = input_error([] { arm_from_numbers({1.0}, "arm"); });
  EXPECT_EQ(cli_message(e), "(--arm): 1 numbers are not an arm; give X,Y or X,Y,Z [m]");
  EXPECT_EQ(input_error([] {
              arm_from_numbers({1, 2, 3, 4}, "arm");
            }).problem(),
            "4 numbers are not an arm");
}

}  // namespace
}  // namespace dynpos::analysis
