#include "dynpos/ident/control_origin.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace dynpos::ident {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(ControlOrigin, MovesTheAntennaByItsArmTurnedByTheHeading) {
  // An antenna 2 m forward and 1 m to starboard; heading east, the vessel's bow points east:
  // the antenna is 2 m east and 1 m south of the control origin.
  std::vector<double> north = {10.0, 10.0, 10.0}, east = {20.0, 20.0, 20.0};
  const double nan = std::nan("");
  const std::vector<double> heading = {nan, kPi / 2.0, nan};
  move_to_control_origin(north, east, heading, 2.0, 1.0);
  EXPECT_TRUE(std::isnan(north[0]) && std::isnan(east[0]));  // no heading yet
  EXPECT_NEAR(north[1], 11.0, 1e-12);
  EXPECT_NEAR(east[1], 18.0, 1e-12);
  EXPECT_NEAR(north[2], 11.0, 1e-12);  // the heading held
  EXPECT_NEAR(east[2], 18.0, 1e-12);
}

TEST(ControlOrigin, AZeroArmChangesNothing) {
  std::vector<double> north = {1.0}, east = {2.0};
  move_to_control_origin(north, east, {std::nan("")}, 0.0, 0.0);
  EXPECT_EQ(north[0], 1.0);
  EXPECT_EQ(east[0], 2.0);
}

}  // namespace
}  // namespace dynpos::ident
