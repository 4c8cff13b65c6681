#include "dynpos/hybrid/trace.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>

namespace dynpos::hybrid {
namespace {

TEST(Trace, LooksUpChannelsByName) {
  Trace trace;
  trace.t = {0.0, 1.0, 1.0};  // a jump at t = 1: two rows at one instant
  trace.channels.push_back({"x1", "m", core::Interp::kLinear, {1.0, 2.0, 2.0}});
  trace.channels.push_back({"V", "", core::Interp::kLinear, {5.0, 4.0, 3.0}});
  EXPECT_TRUE(trace.has("V"));
  EXPECT_FALSE(trace.has("x2"));
  EXPECT_EQ(trace.values("V")[2], 3.0);
  EXPECT_EQ(trace.channel("x1").unit, "m");
  EXPECT_EQ(trace.size(), 3u);
  try {
    (void)trace.channel("x2");
    FAIL() << "no exception";
  } catch (const std::out_of_range& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("no channel 'x2' (channels: x1, V)"));
  }
}

}  // namespace
}  // namespace dynpos::hybrid
