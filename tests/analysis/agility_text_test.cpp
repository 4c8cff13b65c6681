// identify agility's --window and --current as the command line gives them.

#include "dynpos/analysis/agility_text.hpp"

#include <gtest/gtest.h>

#include "input_error_capture.hpp"

namespace dynpos::analysis {
namespace {

using testing::input_error;

TEST(AgilityText, AWindowOfThreeToFiveNumbers) {
  const ident::AgilityWindow w3 = parse_agility_window("10,40,90");
  EXPECT_EQ(w3.t_step, 10.0);
  EXPECT_EQ(w3.t_end, 40.0);
  EXPECT_EQ(w3.direction_deg, 90.0);
  EXPECT_EQ(w3.magnitude_pct, 100.0);  // thrust 100 % when not given
  EXPECT_FALSE(w3.yaw_pct.has_value());
  const ident::AgilityWindow w5 = parse_agility_window("10,40,-45,50,20");
  EXPECT_EQ(w5.direction_deg, -45.0);
  EXPECT_EQ(w5.magnitude_pct, 50.0);
  EXPECT_EQ(w5.yaw_pct, 20.0);
  EXPECT_FALSE(parse_agility_window("1,2,3,4").yaw_pct.has_value());
}

TEST(AgilityText, AWindowOfAnotherCountOrANonNumberIsAWindowError) {
  const core::InputError few = input_error([] { parse_agility_window("10,40"); });
  EXPECT_EQ(few.option(), "window");
  EXPECT_EQ(few.problem(), "'10,40' needs 3 to 5 numbers, has 2");
  EXPECT_EQ(few.hint(), "--window T_STEP,T_END,DIR_DEG[,THRUST_PCT[,YAW_PCT]]");
  EXPECT_EQ(input_error([] { parse_agility_window("1,2,3,4,5,6"); }).problem(),
            "'1,2,3,4,5,6' needs 3 to 5 numbers, has 6");
  const core::InputError bad = input_error([] { parse_agility_window("10,forty,90"); });
  EXPECT_EQ(bad.option(), "window");
  EXPECT_EQ(bad.problem(), "'forty' in '10,forty,90' is not a number");
}

TEST(AgilityText, TheCurrentIsSpeedAndDirection) {
  const ObservedCurrent c = parse_observed_current("0.2,318");
  EXPECT_EQ(c.speed_mps, 0.2);
  EXPECT_EQ(c.to_deg, 318.0);
  const core::InputError e = input_error([] { parse_observed_current("0.2"); });
  EXPECT_EQ(e.option(), "current");
  EXPECT_EQ(e.problem(), "'0.2' is not SPEED,TO_DEG");
  EXPECT_EQ(e.hint(), "e.g. --current 0.2,318 (0.2 m/s towards 318°, as observed)");
  EXPECT_EQ(input_error([] { parse_observed_current("0.2,north"); }).option(), "current");
}

}  // namespace
}  // namespace dynpos::analysis
