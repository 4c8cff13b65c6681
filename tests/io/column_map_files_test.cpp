// Roles read from files other than the main log: --col ROLE=COLUMN@FILE, --clock-offset and
// the TOML `file` key and [files] table (column_map.hpp).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "dynpos/io/column_map.hpp"
#include "io_test_util.hpp"

namespace dynpos::io {
namespace {

using ::testing::ContainsRegex;
using testing::input_error_message;
using testing::input_error_option;

TEST(ColumnMapFiles, CommandLineColumnAtFile) {
  ColumnMap map;
  apply_overrides(map, {"time=t", "heading=HDG@nav.csv", "time=stamp@nav.csv", "u=SOG@dir/gps.csv"},
                  {"heading=rad"});
  apply_clock_offset_override(map, "nav.csv=-0.25");
  ASSERT_NE(map.find("heading"), nullptr);
  EXPECT_EQ(map.find("heading")->column, "HDG");
  EXPECT_EQ(map.find("heading")->file, "nav.csv");
  EXPECT_EQ(map.find("heading")->unit, "rad");
  // time@FILE names that file's time column; the main log's time stays "t".
  EXPECT_EQ(map.find("time")->column, "t");
  EXPECT_TRUE(map.find("time")->file.empty());
  EXPECT_EQ(map.file_options("nav.csv").time_column, "stamp");
  EXPECT_EQ(map.file_options("nav.csv").clock_offset_s, -0.25);
  EXPECT_EQ(map.file_options("dir/gps.csv").time_column, "time");  // the default
  EXPECT_EQ(map.file_options("dir/gps.csv").clock_offset_s, 0.0);
  EXPECT_EQ(map.other_files(), (std::vector<std::string>{"nav.csv", "dir/gps.csv"}));
  EXPECT_NO_THROW(map.validate());

  // Each file's own map: its roles and its time column, nothing else.
  const ColumnMap nav = map.for_file("nav.csv");
  ASSERT_EQ(nav.roles().size(), 2u);
  EXPECT_EQ(nav.find("time")->column, "stamp");
  EXPECT_TRUE(nav.find("heading")->file.empty());
  EXPECT_EQ(nav.find("heading")->unit, "rad");
  const ColumnMap main = map.for_file("");
  ASSERT_EQ(main.roles().size(), 1u);
  EXPECT_EQ(main.find("time")->column, "t");

  // A later --col without @ moves the role back to the main log.
  apply_column_override(map, "u=speed");
  EXPECT_TRUE(map.find("u")->file.empty());
  EXPECT_EQ(map.other_files(), (std::vector<std::string>{"nav.csv"}));
}

TEST(ColumnMapFiles, CommandLineErrorsNameTheOption) {
  ColumnMap map;
  EXPECT_THAT(input_error_message([&] { apply_column_override(map, "heading=HDG@"); }),
              ContainsRegex("\\(col\\): malformed argument 'heading=HDG@': "
                            "expected ROLE=COLUMN@FILE"));
  EXPECT_THAT(input_error_message([&] { apply_column_override(map, "heading=@nav.csv"); }),
              ContainsRegex("expected ROLE=COLUMN@FILE"));
  EXPECT_THAT(input_error_message([&] { apply_clock_offset_override(map, "nav.csv"); }),
              ContainsRegex("\\(clock_offset\\): malformed argument 'nav.csv': "
                            "expected FILE=SECONDS"));
  EXPECT_THAT(input_error_message([&] { apply_clock_offset_override(map, "nav.csv=0.2s"); }),
              ContainsRegex("malformed argument 'nav.csv=0.2s'"));
  EXPECT_THAT(input_error_message([&] { apply_clock_offset_override(map, "nav.csv=inf"); }),
              ContainsRegex("clock offset inf s for 'nav.csv' is not finite"));
  // An offset for a file no role is read from is most likely a misspelt name.
  map.set_column("time", "t");
  apply_column_override(map, "heading=HDG@nav.csv");
  apply_clock_offset_override(map, "nva.csv=1");
  EXPECT_THAT(input_error_message([&] { map.validate(); }),
              ContainsRegex("\\(clock_offset\\): 'nva.csv=1': no role is read from 'nva.csv'"));
  EXPECT_EQ(input_error_option([&] { map.validate(); }), "clock_offset");
}

TEST(ColumnMapFiles, TomlFileKeysAreRelativeToTheMapFolder) {
  const ColumnMap map = parse_column_map(R"toml(
[roles]
time = "t"
heading = { column = "HDG", file = "nav.csv", unit = "deg" }
"rudder.port" = { column = "RUD", file = "/data/steer.csv" }
u = { column = "SOG", file = "../gps/gps.csv" }

[files."nav.csv"]
time = "stamp"
clock_offset = 0.25

[files."../gps/gps.csv"]
clock_offset = -2
)toml",
                                         "maps/trial.toml");
  EXPECT_EQ(map.find("heading")->file, "maps/nav.csv");
  EXPECT_EQ(map.find("heading")->unit, "deg");
  EXPECT_EQ(map.find("heading")->source.line, 4u);
  EXPECT_EQ(map.find("rudder.port")->file, "/data/steer.csv");  // absolute stays
  EXPECT_EQ(map.find("u")->file, "gps/gps.csv");
  EXPECT_EQ(map.file_options("maps/nav.csv").time_column, "stamp");
  EXPECT_EQ(map.file_options("maps/nav.csv").clock_offset_s, 0.25);
  EXPECT_EQ(map.file_options("gps/gps.csv").clock_offset_s, -2.0);  // an integer is fine
  EXPECT_EQ(map.file_options("/data/steer.csv").clock_offset_s, 0.0);
  EXPECT_NO_THROW(map.validate());

  // The time of another file may also be given in [roles], like --col time=COLUMN@FILE.
  const ColumnMap other = parse_column_map(R"toml(
[roles]
time = { column = "stamp", file = "nav.csv" }
heading = { column = "HDG", file = "nav.csv" }
)toml",
                                           "m.toml");
  EXPECT_EQ(other.file_options("nav.csv").time_column, "stamp");
  EXPECT_EQ(other.find("time"), nullptr);  // the main log's time keeps its default
}

TEST(ColumnMapFiles, TomlErrorsNameLineAndColumn) {
  const auto parse = [](std::string_view text) { return parse_column_map(text, "map.toml"); };
  EXPECT_THAT(input_error_message([&] { parse("[files.\"nav.csv\"]\nclock_offset = \"x\"\n"); }),
              ContainsRegex("^map\\.toml:2:16: clock_offset must be a number of seconds"));
  EXPECT_THAT(input_error_message([&] { parse("[files.\"nav.csv\"]\nclock_offset = nan\n"); }),
              ContainsRegex("^map\\.toml:2:16: clock offset nan s for 'nav.csv' is not finite"));
  EXPECT_THAT(input_error_message([&] { parse("[files.\"nav.csv\"]\noffset = 1\n"); }),
              ContainsRegex("^map\\.toml:2:1: unknown key 'offset' in \\[files.\"nav.csv\"\\]; "
                            "the keys are time and clock_offset"));
  EXPECT_THAT(
      input_error_message([&] { parse("[roles]\nheading = { column = \"H\", file = 3 }\n"); }),
      ContainsRegex("^map\\.toml:2:[0-9]+: file must be a non-empty string"));
  EXPECT_THAT(input_error_message([&] { parse("files = 1\n"); }),
              ContainsRegex("^map\\.toml:1:1: 'files' must be a table"));
  // Options for a file no role comes from: an error at the file's table.
  const ColumnMap unused = parse("[roles]\ntime = \"t\"\n[files.\"nav.csv\"]\nclock_offset = 1\n");
  EXPECT_THAT(input_error_message([&] { unused.validate(); }),
              ContainsRegex("^map\\.toml:4:16: no role is read from 'nav.csv'"));
}

}  // namespace
}  // namespace dynpos::io
