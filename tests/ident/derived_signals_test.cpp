#include "dynpos/ident/derived_signals.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "dynpos/core/error.hpp"
#include "synthetic.hpp"

namespace dynpos::ident {
namespace {

TEST(DerivedSignals, TotalSpeedOf319) {
  const std::vector<double> u{3.0, -3.0, 0.0, std::nan("")};
  const std::vector<double> v{4.0, -4.0, -2.0, 1.0};
  const std::vector<double> speed = total_speed(u, v);
  EXPECT_DOUBLE_EQ(speed[0], 5.0);
  EXPECT_DOUBLE_EQ(speed[1], 5.0);
  EXPECT_DOUBLE_EQ(speed[2], 2.0);
  EXPECT_TRUE(std::isnan(speed[3]));  // missing stays missing
  EXPECT_THROW_MATCHING(total_speed(u, std::vector<double>{1.0}), core::InputError,
                        "has 1 samples but the time axis has 4");
}

TEST(DerivedSignals, YawRateInDegreesPerSecond) {
  const std::vector<double> r{std::numbers::pi / 180.0, -std::numbers::pi, std::nan("")};
  const std::vector<double> deg = yaw_rate_deg_s(r);
  EXPECT_NEAR(deg[0], 1.0, 1e-15);
  EXPECT_NEAR(deg[1], -180.0, 1e-13);
  EXPECT_TRUE(std::isnan(deg[2]));
}

TEST(DerivedSignals, AddsChannelsToALog) {
  core::Log log(std::vector<double>{0.0, 1.0});
  log.add_channel("u", "m/s", {3.0, 0.0});
  log.add_channel("v", "m/s", {4.0, 1.0});
  log.add_channel("r", "rad/s", {0.0, std::numbers::pi / 18.0});
  add_total_speed(log, "u", "v");
  add_yaw_rate_deg_s(log, "r");
  EXPECT_EQ(log.channel("U").unit, "m/s");
  EXPECT_DOUBLE_EQ(log.values("U")[0], 5.0);
  EXPECT_EQ(log.channel("r_deg_s").unit, "deg/s");
  EXPECT_NEAR(log.values("r_deg_s")[1], 10.0, 1e-14);
  EXPECT_THROW(add_total_speed(log, "u", "w"), std::out_of_range);
  EXPECT_THROW(add_total_speed(log, "u", "v"), std::invalid_argument);  // "U" is taken
}

}  // namespace
}  // namespace dynpos::ident
