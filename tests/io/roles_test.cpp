#include "dynpos/io/roles.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace dynpos::io {
namespace {

using core::Interp;
using core::Quantity;

struct FixedCase {
  const char* name;
  std::optional<Quantity> quantity;
  const char* default_unit;
  Interp interp;
};

class FixedRoles : public ::testing::TestWithParam<FixedCase> {};

TEST_P(FixedRoles, HaveQuantityDefaultUnitAndInterp) {
  const FixedCase& c = GetParam();
  const auto role = find_role(c.name);
  ASSERT_TRUE(role.has_value()) << c.name;
  EXPECT_EQ(role->name, c.name);
  EXPECT_EQ(role->quantity, c.quantity);
  EXPECT_EQ(role->default_unit, c.default_unit);
  EXPECT_EQ(role->interp, c.interp);
  // The default unit must be a known unit of the role's quantity, or conversion would fail.
  const auto unit = core::find_unit(role->default_unit);
  ASSERT_TRUE(unit.has_value()) << role->default_unit;
  if (role->quantity) {
    EXPECT_EQ(unit->quantity, *role->quantity);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Table, FixedRoles,
    ::testing::Values(FixedCase{"time", Quantity::kTime, "s", Interp::kLinear},
                      FixedCase{"north", Quantity::kLength, "m", Interp::kLinear},
                      FixedCase{"down", Quantity::kLength, "m", Interp::kLinear},
                      FixedCase{"lat", Quantity::kAngle, "deg", Interp::kLinear},
                      FixedCase{"height", Quantity::kLength, "m", Interp::kLinear},
                      FixedCase{"heading", Quantity::kAngle, "deg", Interp::kAngle},
                      FixedCase{"pitch", Quantity::kAngle, "deg", Interp::kAngle},
                      FixedCase{"r", Quantity::kAngularRate, "deg/s", Interp::kLinear},
                      FixedCase{"w", Quantity::kSpeed, "m/s", Interp::kLinear},
                      FixedCase{"wind_speed", Quantity::kSpeed, "m/s", Interp::kLinear},
                      FixedCase{"wind_dir", Quantity::kAngle, "deg", Interp::kAngle},
                      FixedCase{"setpoint.east", Quantity::kLength, "m", Interp::kHold},
                      FixedCase{"setpoint.heading", Quantity::kAngle, "deg", Interp::kHold},
                      FixedCase{"input", std::nullopt, "1", Interp::kHold},
                      FixedCase{"output", std::nullopt, "1", Interp::kLinear},
                      FixedCase{"trigger", std::nullopt, "1", Interp::kHold},
                      FixedCase{"command.rpm.port", Quantity::kShaftSpeed, "rpm", Interp::kHold},
                      FixedCase{"command.thrust.tunnel", Quantity::kForce, "kN", Interp::kHold},
                      FixedCase{"command.rudder.stb", Quantity::kAngle, "deg", Interp::kHold},
                      FixedCase{"mru2.roll", Quantity::kAngle, "deg", Interp::kAngle},
                      FixedCase{"mru1.q", Quantity::kAngularRate, "deg/s", Interp::kLinear}),
    // Test names from the role name ("command.rpm.port" → "command_rpm_port").
    [](const ::testing::TestParamInfo<FixedCase>& info) {
      std::string name = info.param.name;
      for (char& c : name) c = (c == '.') ? '_' : c;
      return name;
    });

TEST(Roles, PatternRolesTakeTheirNamePart) {
  const auto thrust = find_role("thrust.port");
  ASSERT_TRUE(thrust.has_value());
  EXPECT_EQ(thrust->name, "thrust.port");
  EXPECT_EQ(thrust->quantity, Quantity::kForce);
  EXPECT_EQ(thrust->default_unit, "kN");

  const auto rpm = find_role("rpm.tunnel_1");
  ASSERT_TRUE(rpm.has_value());
  EXPECT_EQ(rpm->quantity, Quantity::kShaftSpeed);
  EXPECT_EQ(rpm->default_unit, "rpm");

  const auto command = find_role("command.stbd");
  ASSERT_TRUE(command.has_value());
  EXPECT_EQ(command->quantity, Quantity::kFraction);
  EXPECT_TRUE(command->discrete());

  EXPECT_EQ(find_role("power.bow")->default_unit, "kW");
  EXPECT_EQ(find_role("rudder.port")->quantity, Quantity::kAngle);
  // An angle interpolates along the shorter arc and is continuous; its command is held.
  EXPECT_EQ(find_role("rudder.port")->interp, Interp::kAngle);
  EXPECT_FALSE(find_role("rudder.port")->discrete());
  EXPECT_EQ(find_role("command.rudder.port")->interp, Interp::kHold);
  EXPECT_EQ(find_role("azimuth.pod_port")->quantity, Quantity::kAngle);
  EXPECT_EQ(find_role("azimuth.pod_port")->interp, Interp::kAngle);
  EXPECT_EQ(find_role("gnss2.lon")->interp, Interp::kAngle);
  EXPECT_EQ(find_role("gnss2.lat")->interp, Interp::kLinear);
}

TEST(Roles, SensorRolesTakeAPositiveIndex) {
  const auto lat = find_role("gnss2.lat");
  ASSERT_TRUE(lat.has_value());
  EXPECT_EQ(lat->name, "gnss2.lat");
  EXPECT_EQ(lat->quantity, Quantity::kAngle);
  EXPECT_EQ(find_role("gnss12.height")->quantity, Quantity::kLength);
  EXPECT_EQ(find_role("gnss1.down")->default_unit, "m");
  const auto az = find_role("mru1.az");
  ASSERT_TRUE(az.has_value());
  EXPECT_EQ(az->quantity, Quantity::kAcceleration);
  EXPECT_EQ(az->default_unit, "m/s^2");
}

TEST(Roles, CommandRolesOfAKindTakeTheirNamePart) {
  EXPECT_FALSE(find_role("command.pitch.port").has_value());  // not a command kind
  EXPECT_FALSE(find_role("command.rpm.").has_value());
  EXPECT_FALSE(find_role("command.rpm.a.b").has_value());
  EXPECT_TRUE(find_role("command.surge").has_value());
  const auto azimuth = find_role("command.azimuth.main_port");
  ASSERT_TRUE(azimuth.has_value());
  EXPECT_EQ(azimuth->quantity, Quantity::kAngle);
  EXPECT_EQ(azimuth->interp, Interp::kHold);
}

TEST(Roles, RejectsMalformedNames) {
  for (const char* name :
       {"", "Heading", "heading ", "thrust", "thrust.", "thrust.a b", "thrust.a.b", "gnss.lat",
        "gnss0.lat", "gnss01.lat", "gnss1.ax", "mru1.lat", "mruK.ax", "gnssK.lat", "gnss-1.lat",
        "speed", "setpoint.u", "foo.bar"}) {
    EXPECT_FALSE(find_role(name).has_value()) << "'" << name << "'";
  }
}

TEST(Roles, CatalogueListsEveryRoleOnce) {
  std::set<std::string> names;
  for (const auto& role : role_catalogue()) {
    EXPECT_TRUE(names.insert(role.name).second) << role.name;
    EXPECT_FALSE(role.description.empty()) << role.name;
    EXPECT_TRUE(core::find_unit(role.default_unit).has_value()) << role.name;
  }
  for (const char* expected : {"time", "u", "thrust.NAME", "command.NAME", "gnssK.north", "mruK.ay",
                               "mruK.roll", "command.rpm.NAME", "setpoint.north", "trigger"}) {
    EXPECT_TRUE(names.contains(expected)) << expected;
  }
  EXPECT_EQ(names.size(), 51u);  // the table in docs/log-format.md
}

TEST(Roles, ClosestRoleSuggestsNearNames) {
  EXPECT_EQ(closest_role("heding"), "heading");
  EXPECT_EQ(closest_role("wind_sped"), "wind_speed");
  EXPECT_EQ(closest_role("zzzzzzzzzzzz"), "");
}

}  // namespace
}  // namespace dynpos::io
