// Request keys as the command line spells them, and the message both front ends show.

#include "dynpos/analysis/option_spelling.hpp"

#include <gtest/gtest.h>

#include "dynpos/analysis/options.hpp"

namespace dynpos::analysis {
namespace {

TEST(OptionSpelling, KeysBecomeTheOptionsAUserTypes) {
  EXPECT_EQ(option_spelling("min_step"), "--min-step");
  EXPECT_EQ(option_spelling("method"), "--method");
  EXPECT_EQ(option_spelling("col:output"), "--col output=COLUMN");
  EXPECT_EQ(option_spelling("unit:u"), "--unit u=UNIT");
  EXPECT_EQ(option_spelling("from/to"), "--from/--to");
}

TEST(OptionSpelling, TheMessageNamesTheOptionAndKeepsTheFile) {
  const core::InputError e = option_error_in_file("log.csv", "max_time_offset", "too large", "x");
  EXPECT_EQ(cli_message(e), "log.csv (--max-time-offset): too large; x");
  EXPECT_EQ(e.option(), "max_time_offset");
  const core::InputError in_file({"log.csv", 3, 2, "speed"}, "not a number");
  EXPECT_EQ(cli_message(in_file), in_file.what());
}

}  // namespace
}  // namespace dynpos::analysis
