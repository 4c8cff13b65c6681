#include "dynpos/io/csv_reader.hpp"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "io_test_util.hpp"

namespace dynpos::io {
namespace {

using ::testing::ContainsRegex;
using testing::input_error_message;
using testing::TempDir;

constexpr double kDeg = std::numbers::pi / 180.0;

ColumnMap map_of(std::initializer_list<std::pair<const char*, const char*>> columns) {
  ColumnMap map;
  for (const auto& [role, column] : columns) map.set_column(role, column);
  return map;
}

TEST(CsvReader, MergedRatesKeepBlankCellsAsMissingNotZero) {
  const auto path = testing::fixture("merged_100hz_1hz.csv");
  const ColumnMap map = map_of({{"time", "Time [s]"},
                                {"heading", "Heading (deg)"},
                                {"roll", "Roll"},
                                {"north", "North GNSS [m]"},
                                {"east", "East GNSS"}});
  const core::Log log = read_csv(path, map);
  ASSERT_EQ(log.size(), 201u);
  EXPECT_EQ(log.channel_names(), (std::vector<std::string>{"heading", "roll", "north", "east"}));
  const auto& north = log.values("north");
  const auto& east = log.values("east");
  for (std::size_t i = 0; i < log.size(); ++i) {
    if (i % 100 == 0) {
      EXPECT_EQ(north[i], 100.0 + static_cast<double>(i / 100)) << i;
      EXPECT_EQ(east[i], -20.0 - static_cast<double>(i / 100)) << i;
    } else {
      EXPECT_TRUE(core::is_missing(north[i])) << i;
      EXPECT_TRUE(core::is_missing(east[i])) << i;
    }
    EXPECT_FALSE(core::is_missing(log.values("heading")[i])) << i;
  }
  EXPECT_EQ(log.time()[37], 0.37);
  EXPECT_EQ(log.channel("heading").unit, "rad");
  EXPECT_EQ(log.channel("north").unit, "m");
  // deg → rad is one multiplication by π/180: a few ulp of the result.
  EXPECT_DOUBLE_EQ(log.values("heading")[200], 360.0 * kDeg);
  EXPECT_DOUBLE_EQ(log.values("roll")[0], -1.25 * kDeg);
}

TEST(CsvReader, ConvertsUnitsToSiAtLoad) {
  TempDir dir;
  const auto path = dir.write("units.csv",
                              "t,HDG (deg),SOG [kn],PS shaft [rpm],PS cmd [%],PS thrust [kN],"
                              "PS power [kW],ROT\n"
                              "0,90,10,120,50,12.5,300,6\n"
                              "0.5,180,-2,-60,-25,-4,0,-3\n");
  const ColumnMap map = map_of({{"time", "t"},
                                {"heading", "HDG"},
                                {"u", "SOG"},
                                {"rpm.port", "PS shaft"},
                                {"command.port", "PS cmd"},
                                {"thrust.port", "PS thrust"},
                                {"power.port", "PS power"},
                                {"r", "ROT"}});
  const core::Log log = read_csv(path, map);
  ASSERT_EQ(log.size(), 2u);
  // Each conversion is a single multiplication by the unit's factor: compare within 4 ulp.
  EXPECT_DOUBLE_EQ(log.values("heading")[0], std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(log.values("heading")[1], std::numbers::pi);
  EXPECT_DOUBLE_EQ(log.values("u")[0], 10.0 * 1852.0 / 3600.0);
  EXPECT_DOUBLE_EQ(log.values("u")[1], -2.0 * 1852.0 / 3600.0);
  EXPECT_DOUBLE_EQ(log.values("rpm.port")[0], 2.0);
  EXPECT_DOUBLE_EQ(log.values("rpm.port")[1], -1.0);
  EXPECT_DOUBLE_EQ(log.values("command.port")[0], 0.5);
  EXPECT_DOUBLE_EQ(log.values("command.port")[1], -0.25);
  EXPECT_DOUBLE_EQ(log.values("thrust.port")[0], 12500.0);
  EXPECT_DOUBLE_EQ(log.values("thrust.port")[1], -4000.0);
  EXPECT_DOUBLE_EQ(log.values("power.port")[0], 300e3);
  // No unit anywhere for ROT: the role default deg/s applies.
  EXPECT_DOUBLE_EQ(log.values("r")[0], 6.0 * kDeg);
  EXPECT_EQ(log.channel("u").unit, "m/s");
  EXPECT_EQ(log.channel("rpm.port").unit, "rps");
  EXPECT_EQ(log.channel("command.port").unit, "1");
  EXPECT_EQ(log.channel("thrust.port").unit, "N");
  EXPECT_EQ(log.channel("power.port").unit, "W");
  EXPECT_EQ(log.channel("r").unit, "rad/s");
  EXPECT_EQ(log.channel("command.port").interp, core::Interp::kHold);
  EXPECT_EQ(log.channel("u").interp, core::Interp::kLinear);
}

TEST(CsvReader, DeclaredUnitBeatsHeaderUnitBeatsRoleDefault) {
  TempDir dir;
  const auto path = dir.write("order.csv", "Time [min],A [rad],B,C [rad]\n1,1,1,1\n2,2,2,2\n");
  ColumnMap map = map_of({{"time", "Time"}, {"heading", "A"}, {"roll", "B"}, {"pitch", "C"}});
  apply_unit_override(map, "pitch=deg");
  const core::Log log = read_csv(path, map);
  EXPECT_EQ(log.time(), (std::vector<double>{60.0, 120.0}));
  EXPECT_EQ(log.values("heading")[1], 2.0);              // header [rad]
  EXPECT_DOUBLE_EQ(log.values("roll")[1], 2.0 * kDeg);   // role default deg; 4 ulp
  EXPECT_DOUBLE_EQ(log.values("pitch")[1], 2.0 * kDeg);  // declared deg beats [rad]; 4 ulp
}

TEST(CsvReader, ScaleMultipliesTheRawValueBeforeConversion) {
  TempDir dir;
  const auto path = dir.write("scale.csv", "t;hdg_centideg;rpm_x10\n0;9000;1200\n1;-4500;-600\n");
  ColumnMap map = parse_column_map(R"([roles]
time = "t"
heading = { column = "hdg_centideg", unit = "deg", scale = 0.01 }
"rpm.bow" = { column = "rpm_x10", scale = 0.1 }
)",
                                   "map.toml");
  const core::Log log = read_csv(path, map);
  // 9000 × 0.01 = 90 deg, then one multiplication by π/180: within 4 ulp.
  EXPECT_DOUBLE_EQ(log.values("heading")[0], std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(log.values("heading")[1], -std::numbers::pi / 4);
  EXPECT_DOUBLE_EQ(log.values("rpm.bow")[0], 2.0);  // 1200 × 0.1 rpm = 2 rps
  EXPECT_DOUBLE_EQ(log.values("rpm.bow")[1], -1.0);
}

TEST(CsvReader, HandlesCrlfBomQuotesCommentsAndBlankLines) {
  TempDir dir;
  const auto path =
      dir.write("crlf.csv",
                "\xEF\xBB\xBF# exported by the trial logger\r\n"
                "\r\n"
                "\"Time, UTC [s]\",Note,\"Pos \"\"N\"\" [m]\",Speed over ground [kn]\r\n"
                "0.5,\"calm, sunny\",\"1.25\",  2 \r\n"
                "# a comment between rows\r\n"
                "\r\n"
                "1.5,\"two\r\nlines\",-3e2,\r\n"
                "2.5,,+4,0\r\n");
  const ColumnMap map =
      map_of({{"time", "Time, UTC [s]"}, {"north", "Pos \"N\""}, {"u", "Speed over ground [kn]"}});
  const core::Log log = read_csv(path, map);
  EXPECT_EQ(log.time(), (std::vector<double>{0.5, 1.5, 2.5}));
  EXPECT_EQ(log.values("north")[0], 1.25);
  EXPECT_EQ(log.values("north")[1], -300.0);
  EXPECT_EQ(log.values("north")[2], 4.0);
  EXPECT_DOUBLE_EQ(log.values("u")[0], 2.0 * 1852.0 / 3600.0);  // one multiplication: 4 ulp
  EXPECT_TRUE(core::is_missing(log.values("u")[1]));
  EXPECT_EQ(log.values("u")[2], 0.0);
}

TEST(CsvReader, DetectsSemicolonAndTabDelimiters) {
  TempDir dir;
  for (const char delimiter : {';', '\t'}) {
    const std::string text = fmt::format("time{0}x [m]{0}y\n0{0}1{0}2\n1{0}3{0}4\n", delimiter);
    const auto path = dir.write("delim.csv", text);
    const core::Log log = read_csv(path, map_of({{"time", "time"}, {"north", "x [m]"}}));
    EXPECT_EQ(log.values("north"), (std::vector<double>{1.0, 3.0})) << int{delimiter};
  }
}

TEST(CsvReader, DeclaredMissingTokensAreMissing) {
  TempDir dir;
  const auto path = dir.write("na.csv", "t,x\n0,NA\n1,NaN\n2, \n3,7\n");
  ColumnMap map = map_of({{"time", "t"}, {"north", "x"}});
  map.format().missing_tokens = {"NA", "NaN"};
  const core::Log log = read_csv(path, map);
  const auto& x = log.values("north");
  ASSERT_EQ(x.size(), 4u);
  EXPECT_TRUE(core::is_missing(x[0]));
  EXPECT_TRUE(core::is_missing(x[1]));
  EXPECT_TRUE(core::is_missing(x[2]));
  EXPECT_EQ(x[3], 7.0);
}

TEST(CsvReader, WindowKeepsOnlyRowsInsideItInclusive) {
  const auto path = testing::fixture("merged_100hz_1hz.csv");
  const ColumnMap map = map_of({{"time", "Time"}, {"north", "North GNSS"}});
  CsvReadOptions options;
  options.t_from_s = 0.5;
  options.t_to_s = 1.0;
  const core::Log log = read_csv(path, map, options);
  ASSERT_EQ(log.size(), 51u);
  EXPECT_EQ(log.time().front(), 0.5);
  EXPECT_EQ(log.time().back(), 1.0);
  EXPECT_EQ(log.values("north").back(), 101.0);

  options.t_from_s = 5.0;
  options.t_to_s = 6.0;
  EXPECT_THAT(input_error_message([&] { read_csv(path, map, options); }),
              ContainsRegex("merged_100hz_1hz\\.csv: no rows inside the window \\[5, 6\\] s; the "
                            "log starts at 0 s and ends at 2 s"));
  options.t_from_s = 2.0;
  options.t_to_s = 1.0;
  EXPECT_THAT(input_error_message([&] { read_csv(path, map, options); }),
              ContainsRegex("the time window \\[2, 1\\] s is empty"));
}

TEST(CsvReader, OnlyMappedColumnsAreParsed) {
  TempDir dir;
  // The unmapped column holds text and a literal nan; neither matters.
  const auto path = dir.write("unmapped.csv", "t,junk,x\n0,abc,1\n1,nan,2\n");
  const core::Log log = read_csv(path, map_of({{"time", "t"}, {"east", "x"}}));
  EXPECT_EQ(log.values("east"), (std::vector<double>{1.0, 2.0}));
}

TEST(CsvReader, TwoRolesMayShareAColumn) {
  TempDir dir;
  const auto path = dir.write("shared.csv", "t,cmd [%]\n0,10\n1,20\n");
  const core::Log log =
      read_csv(path, map_of({{"time", "t"}, {"command.port", "cmd"}, {"input", "cmd"}}));
  EXPECT_DOUBLE_EQ(log.values("command.port")[1], 0.2);  // 20 × 0.01: within 4 ulp
  EXPECT_DOUBLE_EQ(log.values("input")[1], 0.2);         // header [%] applies to generic roles
}

// --- errors: each names file:line:column (header) where the data allows -------------------

class CsvReaderErrors : public ::testing::Test {
 protected:
  std::string error_for(const std::string& text, ColumnMap map) {
    const auto path = dir_.write("bad.csv", text);
    return input_error_message([&] { read_csv(path, map); });
  }
  ColumnMap time_and_x() const { return map_of({{"time", "t"}, {"north", "x [m]"}}); }
  TempDir dir_;
};

TEST_F(CsvReaderErrors, TextInANumberCell) {
  EXPECT_THAT(error_for("t,x [m]\n0,1\n1,1.5m\n", time_and_x()),
              ContainsRegex("bad\\.csv:3:2 \\(x \\[m\\]\\): '1\\.5m' is not a number; numbers "
                            "use '\\.' as the decimal point"));
}

TEST_F(CsvReaderErrors, DecimalCommaGetsItsOwnHint) {
  EXPECT_THAT(error_for("t;x [m]\n0;1,5\n", time_and_x()),
              ContainsRegex("bad\\.csv:2:2 \\(x \\[m\\]\\): '1,5' is not a number; decimal "
                            "commas are not supported"));
}

TEST_F(CsvReaderErrors, LiteralNanOrInfUnlessDeclaredMissing) {
  EXPECT_THAT(error_for("t,x [m]\n0,nan\n", time_and_x()),
              ContainsRegex("bad\\.csv:2:2 \\(x \\[m\\]\\): 'nan' is not a finite number; leave "
                            "the cell blank.*missing = \\[\"nan\"\\]"));
  EXPECT_THAT(error_for("t,x [m]\n0,1\n1,-inf\n", time_and_x()),
              ContainsRegex("bad\\.csv:3:2 \\(x \\[m\\]\\): '-inf' is not a finite number"));
  EXPECT_THAT(error_for("t,x [m]\n0,1e999\n", time_and_x()),
              ContainsRegex("bad\\.csv:2:2 \\(x \\[m\\]\\): '1e999' is out of the range"));
}

TEST_F(CsvReaderErrors, TimeMissingRepeatedOrDecreasing) {
  EXPECT_THAT(error_for("x [m],t\n1,0\n2,\n", time_and_x()),
              ContainsRegex("bad\\.csv:3:2 \\(t\\): the time cell is blank"));
  EXPECT_THAT(error_for("t,x [m]\n0,1\n# note\n0.5,1\n0.5,2\n", time_and_x()),
              ContainsRegex("bad\\.csv:5:1 \\(t\\): time 0\\.5 s repeats the previous row's "
                            "0\\.5 s \\(line 4\\); time must be strictly increasing"));
  EXPECT_THAT(error_for("t,x [m]\n0,1\n2,1\n1,2\n", time_and_x()),
              ContainsRegex("bad\\.csv:4:1 \\(t\\): time 1 s goes back from the previous row's "
                            "2 s \\(line 3\\)"));
  EXPECT_THAT(error_for("t,x [m]\nstart,1\n", time_and_x()),
              ContainsRegex("bad\\.csv:2:1 \\(t\\): 'start' is not a time stamp"));
}

TEST_F(CsvReaderErrors, EmptyFileHeaderOnlyAndCommentsOnly) {
  EXPECT_THAT(error_for("", time_and_x()),
              ContainsRegex("bad\\.csv: the log is empty: no header line"));
  EXPECT_THAT(error_for("# only\n\n# comments\n", time_and_x()),
              ContainsRegex("bad\\.csv: the log is empty: no header line"));
  EXPECT_THAT(error_for("t,x [m]\n", time_and_x()),
              ContainsRegex("bad\\.csv: the log has a header but no data rows"));
  EXPECT_THAT(error_for("t,x [m]\r\n\r\n# end\r\n", time_and_x()),
              ContainsRegex("bad\\.csv: the log has a header but no data rows"));
}

TEST_F(CsvReaderErrors, MappedColumnNotInTheHeaderListsTheColumns) {
  ColumnMap map = map_of({{"time", "t"}});
  apply_column_override(map, "heading=Heading");
  EXPECT_THAT(
      error_for("# c\nt,HEADING [deg],Roll\n0,1,2\n", map),
      ContainsRegex("bad\\.csv:2 \\(heading\\): column 'Heading' for role 'heading' is "
                    "not in the header; did you mean 'HEADING \\[deg\\]'\\? the columns "
                    "are: t, HEADING \\[deg\\], Roll \\(mapped by --col heading=Heading\\)"));
}

TEST_F(CsvReaderErrors, AmbiguousColumn) {
  EXPECT_THAT(error_for("t,x [m],x [ft]\n0,1,2\n", map_of({{"time", "t"}, {"north", "x"}})),
              ContainsRegex("bad\\.csv:1 \\(north\\): column 'x' for role 'north' appears more "
                            "than once in the header \\(columns 2 and 3\\)"));
}

TEST_F(CsvReaderErrors, WrongFieldCount) {
  EXPECT_THAT(error_for("t,x [m]\n0,1\n1,2,3\n", time_and_x()),
              ContainsRegex("bad\\.csv:3: the row has 3 fields but the header \\(line 1\\) has 2; "
                            "check the delimiter \\(using ','\\)"));
}

TEST_F(CsvReaderErrors, HeaderUnitOfTheWrongQuantityOrUnknown) {
  EXPECT_THAT(error_for("t,HDG [m/s]\n0,1\n", map_of({{"time", "t"}, {"heading", "HDG"}})),
              ContainsRegex("bad\\.csv:1:2 \\(HDG \\[m/s\\]\\): unit 'm/s' measures speed, but "
                            "role 'heading' is angle \\(from the header\\); use one of: .*; or "
                            "declare the unit with --unit heading=UNIT"));
  EXPECT_THAT(error_for("t,HDG (true)\n0,1\n", map_of({{"time", "t"}, {"heading", "HDG"}})),
              ContainsRegex("bad\\.csv:1:2 \\(HDG \\(true\\)\\): unknown unit 'true' for role "
                            "'heading' \\(from the header\\); accepted spellings for angle"));
  // A declared unit replaces the header's, so the same file reads fine with one.
  ColumnMap map = map_of({{"time", "t"}, {"heading", "HDG"}});
  apply_unit_override(map, "heading=deg");
  const auto path = dir_.write("ok.csv", "t,HDG (true)\n0,90\n");
  EXPECT_DOUBLE_EQ(read_csv(path, map).values("heading")[0], std::numbers::pi / 2);  // 4 ulp
}

TEST_F(CsvReaderErrors, UnterminatedQuote) {
  EXPECT_THAT(error_for("t,x [m]\n0,\"1\n", time_and_x()),
              ContainsRegex("bad\\.csv:2:2: unterminated quoted field"));
}

TEST_F(CsvReaderErrors, MissingFile) {
  EXPECT_THAT(input_error_message([&] { read_csv(dir_ / "nope.csv", time_and_x()); }),
              ContainsRegex("nope\\.csv: cannot open the log: No such file or directory"));
}

TEST(SplitHeaderCell, SeparatesATrailingBracketedUnit) {
  const auto check = [](const char* cell, const char* name, const char* unit) {
    const HeaderCell split = split_header_cell(cell);
    EXPECT_EQ(split.name, name) << cell;
    EXPECT_EQ(split.unit, unit) << cell;
  };
  check("Speed [kn]", "Speed", "kn");
  check(" Heading (deg) ", "Heading", "deg");
  check("Speed over ground [ m/s ]", "Speed over ground", "m/s");
  check("Pos (GNSS 1) [m]", "Pos (GNSS 1)", "m");
  check("Thrust", "Thrust", "");
  check("[deg]", "[deg]", "");
  check("a[b", "a[b", "");
}

// --- read_csv_all ----------------------------------------------------------------------------

TEST(CsvReadAll, LoadsEveryNumericColumnUnderItsHeaderName) {
  const core::Log log = read_csv_all(testing::fixture("merged_100hz_1hz.csv"));
  ASSERT_EQ(log.size(), 201u);
  // "Status" holds text from its first row on: skipped, not an error.
  EXPECT_EQ(log.channel_names(),
            (std::vector<std::string>{"Heading", "Roll", "North GNSS", "East GNSS"}));
  EXPECT_EQ(log.channel("Heading").unit, "rad");
  EXPECT_DOUBLE_EQ(log.values("Heading")[0], 350.0 * kDeg);  // one multiplication: 4 ulp
  EXPECT_TRUE(core::is_missing(log.values("North GNSS")[1]));
}

TEST(CsvReadAll, KeepsUnknownUnitsAsLoggedAndUsesRoleInterpolation) {
  TempDir dir;
  const auto path = dir.write("all.csv",
                              "time [ms],command.port [%],gain [furlong],plain\n"
                              "0,50,3,4\n"
                              "500,,5,6\n");
  const core::Log log = read_csv_all(path);
  EXPECT_EQ(log.time(), (std::vector<double>{0.0, 0.5}));
  EXPECT_EQ(log.channel("command.port").interp, core::Interp::kHold);
  EXPECT_EQ(log.channel("command.port").unit, "1");
  EXPECT_EQ(log.values("command.port")[0], 0.5);
  EXPECT_TRUE(core::is_missing(log.values("command.port")[1]));
  EXPECT_EQ(log.channel("gain").unit, "furlong");
  EXPECT_EQ(log.values("gain"), (std::vector<double>{3.0, 5.0}));
  EXPECT_EQ(log.channel("plain").unit, "");
  EXPECT_EQ(log.channel("plain").interp, core::Interp::kLinear);
}

TEST(CsvReadAll, TextAfterNumbersIsAnError) {
  TempDir dir;
  const auto path = dir.write("mixed.csv", "time [s],x [m]\n0,1\n1,oops\n");
  EXPECT_THAT(input_error_message([&] { read_csv_all(path); }),
              ContainsRegex("mixed\\.csv:3:2 \\(x \\[m\\]\\): 'oops' is not a number"));
  const auto bad_time = dir.write("badtime.csv", "time [m],x\n0,1\n");
  EXPECT_THAT(input_error_message([&] { read_csv_all(bad_time); }),
              ContainsRegex("badtime\\.csv:1:1 \\(time \\[m\\]\\): the first column is time, but "
                            "its unit 'm' is not a time unit"));
  const auto twice = dir.write("twice.csv", "time,x [m],x [ft]\n0,1,2\n");
  EXPECT_THAT(input_error_message([&] { read_csv_all(twice); }),
              ContainsRegex("twice\\.csv:1:3 \\(x \\[ft\\]\\): channel 'x' appears twice"));
}

TEST(CsvReadHeader, ListsTheTrimmedCells) {
  EXPECT_EQ(read_csv_header(testing::fixture("merged_100hz_1hz.csv")),
            (std::vector<std::string>{"Time [s]", "Heading (deg)", "Roll [deg]", "North GNSS [m]",
                                      "East GNSS [m]", "Status"}));
}

// --- streaming a large file -------------------------------------------------------------------

TEST(CsvReader, StreamsALargeFileLoadingOnlyThreeColumns) {
  TempDir dir;
  constexpr int kRows = 200'000;
  constexpr int kColumns = 40;
  const auto path = dir / "large.csv";
  {
    std::ofstream out(path, std::ios::binary);
    std::string line = "time [s]";
    for (int c = 1; c < kColumns; ++c) line += fmt::format(",ch{} [m]", c);
    out << line << '\n';
    for (int i = 0; i < kRows; ++i) {
      line = fmt::format("{}", i / 100.0);
      for (int c = 1; c < kColumns; ++c) {
        // Every 7th row of ch17 is blank; other cells are short exact decimals.
        if (c == 17 && i % 7 == 0) {
          line += ',';
        } else {
          line += fmt::format(",{}", (i % 1000) * 0.5 + c);
        }
      }
      out << line << '\n';
    }
    ASSERT_TRUE(out.good());
  }
  const ColumnMap map =
      map_of({{"time", "time"}, {"north", "ch3"}, {"east", "ch17"}, {"down", "ch39"}});
  const core::Log log = read_csv(path, map);
  ASSERT_EQ(log.size(), static_cast<std::size_t>(kRows));
  EXPECT_EQ(log.channels().size(), 3u);
  std::size_t missing = 0;
  for (int i = 0; i < kRows; ++i) {
    const auto k = static_cast<std::size_t>(i);
    ASSERT_EQ(log.time()[k], i / 100.0) << i;
    ASSERT_EQ(log.values("north")[k], (i % 1000) * 0.5 + 3) << i;
    ASSERT_EQ(log.values("down")[k], (i % 1000) * 0.5 + 39) << i;
    if (i % 7 == 0) {
      ASSERT_TRUE(core::is_missing(log.values("east")[k])) << i;
      ++missing;
    } else {
      ASSERT_EQ(log.values("east")[k], (i % 1000) * 0.5 + 17) << i;
    }
  }
  EXPECT_EQ(missing, static_cast<std::size_t>((kRows + 6) / 7));

  CsvReadOptions window;
  window.t_from_s = 100.0;
  window.t_to_s = 100.5;
  const core::Log part = read_csv(path, map, window);
  ASSERT_EQ(part.size(), 51u);
  EXPECT_EQ(part.time().front(), 100.0);
  EXPECT_EQ(part.values("north").front(), (10'000 % 1000) * 0.5 + 3);
}

// A line beyond kMaxCsvRecordBytes (a file without line ends, a binary file) is an error naming
// it, whether it is the header, a row the block parser meets, or a record that a quote never
// closed joins; the reader holds no more than the limit of it.
TEST(CsvReader, ALineBeyondTheLimitIsAnErrorNamingIt) {
  TempDir dir;
  const std::string long_cell(kMaxCsvRecordBytes + 1, '7');
  std::string rows = "time,x\n";
  for (int i = 0; i < 500; ++i) rows += fmt::format("{},1\n", i);
  const auto header = dir.write("header.csv", "time," + long_cell + "\n0,1\n");
  const auto row = dir.write("row.csv", rows + "500," + long_cell + "\n501,1\n");
  const auto quote = dir.write("quote.csv", rows + "500,\"" + std::string(100, '\n') +
                                                std::string(kMaxCsvRecordBytes, 'q') + "\n");
  const ColumnMap map = map_of({{"time", "time"}, {"input", "x"}});
  for (const unsigned jobs : {1u, 2u}) {
    CsvReadOptions options;
    options.jobs = jobs;
    EXPECT_THAT(input_error_message([&] { read_csv(header, map, options); }),
                ContainsRegex("header.csv:1: a line longer than 8 MiB"));
    EXPECT_THAT(input_error_message([&] { read_csv(row, map, options); }),
                ContainsRegex("row.csv:502: a line longer than 8 MiB.*binary file"));
    EXPECT_THAT(
        input_error_message([&] { read_csv(quote, map, options); }),
        ContainsRegex("quote.csv:502: a record longer than 8 MiB.*quote opened in this row"));
  }
}

// A scale that carries a number beyond the range of a double is an error at the cell (a fuzz
// and review finding: scale = 1e308 made the step detector blame its own options).
TEST(CsvReader, AScaleThatOverflowsIsAnErrorAtTheCell) {
  TempDir dir;
  std::string rows = "time,x\n";
  for (int i = 0; i < 300; ++i) rows += fmt::format("{},{}\n", i, i < 250 ? "0" : "2");
  const auto path = dir.write("big.csv", rows);
  ColumnMap map = map_of({{"time", "time"}, {"input", "x"}});
  map.set_scale("input", 1e308);
  for (const unsigned jobs : {1u, 2u}) {
    CsvReadOptions options;
    options.jobs = jobs;
    EXPECT_THAT(input_error_message([&] { read_csv(path, map, options); }),
                ContainsRegex("big.csv:252:2 \\(x\\): '2' times the column's scale 1e\\+308 in "
                              "SI is beyond the range of a double"));
  }
}

}  // namespace
}  // namespace dynpos::io
