#include "dynpos/io/column_map.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <string>

#include "../source_dir.hpp"
#include "io_test_util.hpp"

namespace dynpos::io {
namespace {

using ::testing::ContainsRegex;
using testing::input_error_message;
using testing::input_error_option;
using testing::TempDir;

constexpr const char* kFullMap = R"toml(
# Gunnerus trial logger
[csv]
delimiter = ";"
comment = "%"
missing = ["NA", "NaN"]

[roles]
time = "Time [s]"
heading = { column = "HDG", unit = "rad" }
thrust.port = { column = "PS thrust", unit = "kN", scale = 2.0 }

[roles."rpm.stbd"]
column = "SB rpm"

[roles.gnss1]
lat = "Lat1"
lon = { column = "Lon1", unit = "deg" }
)toml";

TEST(ColumnMap, ParsesTheDocumentedSchema) {
  TempDir dir;
  const ColumnMap map = load_column_map(dir.write("map.toml", kFullMap));
  EXPECT_EQ(map.format().delimiter, ';');
  EXPECT_EQ(map.format().comment_prefix, "%");
  EXPECT_EQ(map.format().missing_tokens, (std::vector<std::string>{"NA", "NaN"}));
  ASSERT_EQ(map.roles().size(), 6u);

  ASSERT_NE(map.find("time"), nullptr);
  EXPECT_EQ(map.find("time")->column, "Time [s]");
  EXPECT_FALSE(map.find("time")->unit.has_value());

  const RoleColumn* heading = map.find("heading");
  ASSERT_NE(heading, nullptr);
  EXPECT_EQ(heading->column, "HDG");
  EXPECT_EQ(heading->unit, "rad");
  EXPECT_EQ(heading->scale, 1.0);
  EXPECT_EQ(heading->source.line, 10u);

  const RoleColumn* thrust = map.find("thrust.port");
  ASSERT_NE(thrust, nullptr);
  EXPECT_EQ(thrust->column, "PS thrust");
  EXPECT_EQ(thrust->scale, 2.0);

  EXPECT_EQ(map.find("rpm.stbd")->column, "SB rpm");
  EXPECT_EQ(map.find("gnss1.lat")->column, "Lat1");
  EXPECT_EQ(map.find("gnss1.lon")->unit, "deg");
  EXPECT_NO_THROW(map.validate());
}

TEST(ColumnMap, DefaultsAreAutoDelimiterHashCommentsAndNoTokens) {
  const ColumnMap map = parse_column_map("[roles]\ntime = \"t\"\n", "m.toml");
  EXPECT_FALSE(map.format().delimiter.has_value());
  EXPECT_EQ(map.format().comment_prefix, "#");
  EXPECT_TRUE(map.format().missing_tokens.empty());
  EXPECT_EQ(parse_column_map("[csv]\ndelimiter = \"tab\"\n", "m").format().delimiter, '\t');
  EXPECT_EQ(parse_column_map("[csv]\ndelimiter = \"\\t\"\n", "m").format().delimiter, '\t');
}

TEST(ColumnMap, CommandLineWinsOverTheFile) {
  ColumnMap map = parse_column_map(kFullMap, "map.toml");
  apply_overrides(map, {"heading=Heading (deg)", "u = Speed"}, {"heading=deg", "u=kn"});
  const RoleColumn* heading = map.find("heading");
  EXPECT_EQ(heading->column, "Heading (deg)");
  EXPECT_EQ(heading->unit, "deg");
  EXPECT_EQ(map.find("u")->column, "Speed");
  EXPECT_EQ(map.find("u")->unit, "kn");
  // A new column drops the unit and scale the file declared for the old one.
  apply_column_override(map, "thrust.port=Thrust PS");
  EXPECT_FALSE(map.find("thrust.port")->unit.has_value());
  EXPECT_EQ(map.find("thrust.port")->scale, 1.0);
  // A column name may itself contain '='.
  apply_column_override(map, "r=ROT=deg/min");
  EXPECT_EQ(map.find("r")->column, "ROT=deg/min");
}

TEST(ColumnMap, ErrorsInTheFileNameLineAndColumn) {
  const auto parse = [](const std::string& text) { return parse_column_map(text, "map.toml"); };
  EXPECT_THAT(input_error_message([&] { parse("[roles]\ntime = \"t\"\nheding = \"HDG\"\n"); }),
              ContainsRegex("^map\\.toml:3:1: unknown role 'heding'; did you mean 'heading'"));
  EXPECT_THAT(
      input_error_message(
          [&] { parse("[roles]\nheading = { column = \"H\", unit = \"m/s\" }\n"); }),
      ContainsRegex("^map\\.toml:2:[0-9]+: unit 'm/s' measures speed, but role 'heading' is "
                    "angle; use one of: .*rad.*deg"));
  EXPECT_THAT(input_error_message(
                  [&] { parse("[roles]\nheading = { column = \"H\", unit = \"dgr\" }\n"); }),
              ContainsRegex("^map\\.toml:2:[0-9]+: unknown unit 'dgr' for role 'heading'; accepted "
                            "spellings for angle \\(heading\\): .*deg"));
  EXPECT_THAT(input_error_message([&] { parse("[roles]\ntime = 3\n"); }),
              ContainsRegex("^map\\.toml:2:8: role 'time' must be a column name or a table"));
  EXPECT_THAT(input_error_message([&] { parse("[roles]\nheading = { unit = \"deg\" }\n"); }),
              ContainsRegex("^map\\.toml:2:1: role 'heading' needs column"));
  EXPECT_THAT(
      input_error_message([&] { parse("[roles]\nheading = { column = \"H\", scal = 2 }\n"); }),
      ContainsRegex("^map\\.toml:2:[0-9]+: unknown key 'scal' for role 'heading'"));
  EXPECT_THAT(
      input_error_message([&] { parse("[roles]\nheading = { column = \"H\", scale = 0 }\n"); }),
      ContainsRegex("^map\\.toml:2:[0-9]+: scale 0 for role 'heading' must be finite"));
  EXPECT_THAT(input_error_message([&] { parse("[column]\ntime = \"t\"\n"); }),
              ContainsRegex("^map\\.toml:1:2: unknown table or key 'column'.*\\[csv\\], "
                            "\\[roles\\], \\[files\\] and \\[time\\]"));
  EXPECT_THAT(input_error_message([&] { parse("[csv]\ndelimiter = \"|\"\n"); }),
              ContainsRegex("^map\\.toml:2:13: csv.delimiter must be"));
  EXPECT_THAT(input_error_message([&] { parse("[roles]\ntime = \"t\n"); }),
              ContainsRegex("^map\\.toml:2:[0-9]+: TOML syntax error"));
}

TEST(ColumnMap, MissingFileIsAnInputError) {
  TempDir dir;
  EXPECT_THAT(input_error_message([&] { load_column_map(dir / "absent.toml"); }),
              ContainsRegex("absent\\.toml: cannot open the column map file"));
}

// A column map is a few lines: a file of more than 16 MiB is refused by its size, unread.
TEST(ColumnMap, AFileOfMoreThan16MiBIsRefused) {
  TempDir dir;
  const auto big = dir.write("big.toml", "[roles]\ntime = \"t\"\n");
  std::filesystem::resize_file(big, (std::uintmax_t{16} << 20) + 1);
  EXPECT_THAT(input_error_message([&] { load_column_map(big); }),
              ContainsRegex("big\\.toml: more than 16 MiB \\(16777217 bytes\\)"));
}

TEST(ColumnMap, ErrorsOnTheCommandLineNameTheOption) {
  ColumnMap map;
  EXPECT_THAT(input_error_message([&] { apply_column_override(map, "heading"); }),
              ContainsRegex("\\(col\\): malformed argument 'heading': expected ROLE=COLUMN"));
  EXPECT_THAT(input_error_message([&] { apply_column_override(map, "=HDG"); }),
              ContainsRegex("malformed argument '=HDG'"));
  EXPECT_THAT(input_error_message([&] { apply_unit_override(map, "heading="); }),
              ContainsRegex("\\(unit\\): malformed argument 'heading=': expected ROLE=UNIT"));
  EXPECT_THAT(input_error_message([&] { apply_column_override(map, "yaw=HDG"); }),
              ContainsRegex("\\(col\\): 'yaw=HDG': unknown role 'yaw'"));
  EXPECT_THAT(input_error_message([&] { apply_unit_override(map, "heading=m/s"); }),
              ContainsRegex("\\(unit\\): 'heading=m/s': unit 'm/s' measures speed, but role "
                            "'heading' is angle"));
  EXPECT_THAT(input_error_message([&] { apply_unit_override(map, "thrust.port=kNN"); }),
              ContainsRegex("unknown unit 'kNN' for role 'thrust.port'; accepted spellings for "
                            "force.*kN"));
}

// A role given twice on the command line is an error, not the last one kept; the times of
// other files (time=COLUMN@FILE) are one role per file.
TEST(ColumnMap, ARoleGivenTwiceOnTheCommandLineIsAnError) {
  ColumnMap map;
  EXPECT_THAT(input_error_message([&] {
                apply_overrides(map, {"input=A", " input = B"}, {});
              }),
              ContainsRegex("\\(col\\): role 'input' is given twice: 'input=A' "
                            "and ' input = B'; give each role once with --col"));
  EXPECT_THAT(input_error_message([&] {
                apply_overrides(map, {}, {"u=kn", "u=m/s"});
              }),
              ContainsRegex("role 'u' is given twice"));
  EXPECT_NO_THROW(apply_overrides(
      map,
      {"time=t", "time=stamp@nav.csv", "heading=HDG@nav.csv", "time=s@gyro.csv", "r=ROT@gyro.csv"},
      {"heading=deg"}));
}

TEST(ColumnMap, GenericRolesAcceptAnyKnownUnit) {
  ColumnMap map;
  EXPECT_NO_THROW(apply_unit_override(map, "input=%"));
  EXPECT_NO_THROW(apply_unit_override(map, "output=m/s"));
  EXPECT_THAT(input_error_message([&] { apply_unit_override(map, "output=furlong"); }),
              ContainsRegex("unknown unit 'furlong' for role 'output'"));
}

TEST(ColumnMap, ValidateNeedsTimeAndAColumnForEveryUnit) {
  ColumnMap map;
  map.set_column("heading", "HDG");
  EXPECT_THAT(input_error_message([&] { map.validate(); }),
              ContainsRegex("no 'time' column; map it with --col time=COLUMN"));
  map.set_column("time", "t");
  EXPECT_NO_THROW(map.validate());
  apply_unit_override(map, "u=kn");
  EXPECT_THAT(input_error_message([&] { map.validate(); }),
              ContainsRegex("\\(unit\\): 'u=kn': role 'u' has a unit or scale but no column"));
  // The error is the option's, found later: each front end spells the key its own way.
  EXPECT_EQ(input_error_option([&] { map.validate(); }), "unit");
}

}  // namespace
}  // namespace dynpos::io

namespace dynpos::io {
namespace {

// The example map in docs/log-format.md must stay valid.
TEST(ColumnMap, TheDocumentedExampleParses) {
  std::ifstream in(std::filesystem::path(DYNPOS_SOURCE_DIR) / "docs" / "log-format.md");
  ASSERT_TRUE(in.good());
  std::string line;
  std::string toml;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line == "```toml") {
      inside = true;
    } else if (inside && line == "```") {
      break;
    } else if (inside) {
      toml += line + "\n";
    }
  }
  ASSERT_FALSE(toml.empty());
  const ColumnMap map = parse_column_map(toml, "log-format.md");
  EXPECT_EQ(map.format().delimiter, ';');
  EXPECT_EQ(map.find("gnss1.height")->unit, "m");
  EXPECT_EQ(map.find("rpm.tunnel")->scale, 0.1);
  EXPECT_EQ(map.find("rudder.port")->scale, -1.0);
  EXPECT_EQ(map.find("command.port")->column, "PS cmd [%]");
  EXPECT_NO_THROW(map.validate());
}

}  // namespace
}  // namespace dynpos::io

namespace dynpos::io {
namespace {

// The library names a bad override by its option key; each front end spells it (--col, col=).
TEST(ColumnMap, OverrideErrorsAreOptionErrorsOfTheirKey) {
  ColumnMap map;
  const auto option_of = [](const std::function<void()>& f) {
    try {
      f();
    } catch (const core::InputError& e) {
      return e.option();
    }
    return std::string("no error");
  };
  EXPECT_EQ(option_of([&] { apply_column_override(map, "yaw=HDG"); }), "col");
  EXPECT_EQ(option_of([&] { apply_unit_override(map, "heading=furlong"); }), "unit");
  EXPECT_EQ(option_of([&] { apply_clock_offset_override(map, "nav.csv"); }), "clock_offset");
  EXPECT_EQ(option_of([&] { apply_overrides(map, {"u=A", "u=B"}, {}); }), "col");
  EXPECT_EQ(option_of([&] { apply_time_overrides(map, "xx", "", ""); }), "time_format");
  EXPECT_EQ(option_of([&] { apply_time_overrides(map, "", "", "xx"); }), "time_order");
}

}  // namespace
}  // namespace dynpos::io
