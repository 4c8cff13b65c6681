// read_csv_log() on one small fixture per time-stamp form (tests/data/io/time_*.csv).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <fmt/format.h>

#include "dynpos/io/csv_reader.hpp"
#include "io_test_util.hpp"

namespace dynpos::io {
namespace {

using ::testing::ContainsRegex;
using testing::fixture;
using ::testing::HasSubstr;
using testing::input_error_message;
using testing::TempDir;

ColumnMap map_of(std::initializer_list<std::pair<const char*, const char*>> columns) {
  ColumnMap map;
  for (const auto& [role, column] : columns) map.set_column(role, column);
  return map;
}

// Times that are k·dt apart in the file: (k·dt_ns)/1e9 is one correctly rounded division.
std::vector<double> steps_of(std::int64_t dt_ns, int n) {
  std::vector<double> t;
  for (int k = 0; k < n; ++k) t.push_back(static_cast<double>(k * dt_ns) / 1e9);
  return t;
}

TEST(CsvTimeStamps, IsoWithZone) {
  const CsvLog r = read_csv_log(fixture("time_iso_zone.csv"),
                                map_of({{"time", "Time (UTC+2)"}, {"heading", "Heading"}}));
  EXPECT_EQ(r.log.time(), steps_of(100'000'000, 4));
  EXPECT_EQ(r.time.format, "iso8601");
  EXPECT_EQ(r.time.origin, "2024-05-01T12:00:00+02:00");
  EXPECT_EQ(r.time.origin_zone, "+02:00");
  EXPECT_EQ(r.log.channel_names(), std::vector<std::string>{"heading"});
}

// Stamps 2^63 ns or more apart (1677 and 2262) overflowed their integer difference; they are
// read (in doubles), and the second is then simply far after the first.
TEST(CsvTimeStamps, StampsCenturiesApartDoNotOverflow) {
  TempDir dir;
  const auto path =
      dir.write("centuries.csv", "time,heading\n1678-01-01T00:00:00Z,1\n2262-01-01T00:00:00Z,2\n");
  const CsvLog r = read_csv_log(path, map_of({{"time", "time"}, {"heading", "heading"}}));
  ASSERT_EQ(r.log.size(), 2u);
  EXPECT_NEAR(r.log.time()[1], 584.0 * 365.2425 * 86400.0, 1e6);
}

TEST(CsvTimeStamps, IsoLocalWithSlashesAcrossALeapDay) {
  const CsvLog r = read_csv_log(fixture("time_iso_local.csv"),
                                map_of({{"time", "timestamp"}, {"heading", "heading"}}));
  EXPECT_EQ(r.log.time(), steps_of(250'000'000, 4));
  EXPECT_EQ(r.time.origin, "2024-02-29T23:59:59.500");
  EXPECT_EQ(r.time.origin_zone, "local (no zone in the file)");
}

TEST(CsvTimeStamps, EpochMillisecondsAndNanoseconds) {
  const CsvLog ms = read_csv_log(fixture("time_epoch_ms.csv"),
                                 map_of({{"time", "unix_ms"}, {"heading", "heading"}}));
  EXPECT_EQ(ms.time.format, "epoch-ms");
  EXPECT_EQ(ms.log.time(), steps_of(250'000'000, 4));
  EXPECT_EQ(ms.time.origin, "2024-05-01T10:00:00Z");
  EXPECT_EQ(ms.time.origin_zone, "UTC");

  const CsvLog ns = read_csv_log(fixture("time_epoch_ns.csv"),
                                 map_of({{"time", "t_ns"}, {"heading", "heading"}}));
  EXPECT_EQ(ns.time.format, "epoch-ns");
  // The last stamp is 1 ns later than the 0.1 s grid: kept, not rounded away.
  EXPECT_EQ(ns.log.time(), (std::vector<double>{0.0, 0.1, 0.2, 300'000'001 / 1e9}));
  EXPECT_EQ(ns.time.origin, "2024-05-01T10:00:00.123456789Z");
}

TEST(CsvTimeStamps, TimeOfDayWithADateColumnOverNewYear) {
  const CsvLog r =
      read_csv_log(fixture("time_of_day.csv"),
                   map_of({{"time", "Time"}, {"date", "Date"}, {"heading", "Heading"}}));
  EXPECT_EQ(r.time.format, "time-of-day");
  EXPECT_EQ(r.log.time(), steps_of(250'000'000, 4));
  EXPECT_EQ(r.time.origin, "2024-12-31T23:59:59.500");
  EXPECT_EQ(r.log.channel_names(), std::vector<std::string>{"heading"});  // date is no channel
}

TEST(CsvTimeStamps, TimeOfDayWithDateOptionRollsOverMidnight) {
  ColumnMap map = map_of({{"time", "Time"}, {"heading", "Heading"}});
  map.time().date = "2024-12-31";
  const CsvLog r = read_csv_log(fixture("time_of_day_nodate.csv"), map);
  EXPECT_EQ(r.log.time(), steps_of(250'000'000, 4));
  EXPECT_EQ(r.time.origin, "2024-12-31T23:59:59.500");
  EXPECT_TRUE(r.time.notes.empty());

  map.time().date.clear();
  const CsvLog undated = read_csv_log(fixture("time_of_day_nodate.csv"), map);
  EXPECT_EQ(undated.log.time(), steps_of(250'000'000, 4));
  EXPECT_EQ(undated.time.origin, "23:59:59.500");
  EXPECT_EQ(undated.time.notes.size(), 1u);
}

TEST(CsvTimeStamps, SecondsAndNanosecondsColumns) {
  const CsvLog r =
      read_csv_log(fixture("time_sec_nsec.csv"),
                   map_of({{"time.sec", "sec"}, {"time.nsec", "nsec"}, {"heading", "heading"}}));
  EXPECT_EQ(r.time.format, "sec-nsec");
  EXPECT_EQ(r.log.time(), steps_of(100'000'000, 4));
  EXPECT_EQ(r.time.origin, "2024-05-01T10:00:00.079441101Z");
  EXPECT_EQ(r.log.channel_names(), std::vector<std::string>{"heading"});
}

// A 1 Hz logger's date-time stamps with the bug (tests/data/io/time_unpadded_iso_1hz.csv):
// the decimal reading never goes back but jumps 0.11 s where the fraction gets its 9th digit.
TEST(CsvTimeStamps, UnpaddedNanosecondsOfASlowDateTimeLogger) {
  const CsvLog r = read_csv_log(fixture("time_unpadded_iso_1hz.csv"),
                                map_of({{"time", "time"}, {"heading", "heading"}}));
  EXPECT_EQ(r.time.format, "iso8601 (unpadded nanoseconds)");
  ASSERT_EQ(r.time.notes.size(), 1u);
  EXPECT_THAT(r.time.notes[0], HasSubstr("'2025/04/28 11:39:17.78903511' is 11:39:17.078903511"));
  EXPECT_EQ(r.time.origin, "2025-04-28T11:39:17.090");
  ASSERT_EQ(r.log.size(), 20u);
  for (std::size_t k = 0; k < r.log.size(); ++k) {
    EXPECT_NEAR(r.log.time()[k], 1.001 * static_cast<double>(k), 1e-9) << k;
  }
}

TEST(CsvTimeStamps, UnpaddedNanosecondsAreReadAsTheExporterMeantThem) {
  const CsvLog r = read_csv_log(fixture("time_unpadded_ns.csv"),
                                map_of({{"time", "time"}, {"heading", "heading"}}));
  EXPECT_EQ(r.time.format, "seconds (unpadded nanoseconds)");
  ASSERT_EQ(r.time.notes.size(), 1u);
  ASSERT_EQ(r.log.size(), 12u);
  for (std::size_t k = 0; k < r.log.size(); ++k) {
    // 16.079441101 s + k·0.1 s, as logged (relative: no origin).
    EXPECT_EQ(r.log.time()[k], static_cast<double>(16'079'441'101 + k * 100'000'000) / 1e9) << k;
  }
  EXPECT_FALSE(r.time.origin);
}

TEST(CsvTimeStamps, PlainSecondsUnchanged) {
  const CsvLog r = read_csv_log(fixture("merged_100hz_1hz.csv"),
                                map_of({{"time", "Time [s]"}, {"heading", "Heading (deg)"}}));
  EXPECT_EQ(r.time.format, "seconds");
  EXPECT_FALSE(r.time.origin);
  EXPECT_EQ(r.log.time()[37], 0.37);
}

TEST(CsvTimeStamps, DuplicatePolicy) {
  ColumnMap map = map_of({{"time", "time"}, {"heading", "heading"}});
  EXPECT_THAT(input_error_message([&] { read_csv_log(fixture("time_duplicate.csv"), map); }),
              ContainsRegex("time_duplicate\\.csv:4:1 \\(time\\): time 0\\.1 s repeats the "
                            "previous row's 0\\.1 s \\(line 3\\)"));
  map.time().order = TimeOrder::kDropDuplicates;
  const CsvLog r = read_csv_log(fixture("time_duplicate.csv"), map);
  EXPECT_EQ(r.log.time(), (std::vector<double>{0.0, 0.1, 0.2}));
  EXPECT_EQ(r.log.values("heading").size(), 3u);
  EXPECT_EQ(r.time.skipped.count("duplicate time"), 1u);
}

TEST(CsvTimeStamps, IsoErrorsNameLineAndColumn) {
  TempDir dir;
  const auto path = dir.write("bad.csv",
                              "a,Time\n"
                              "1,2024-05-01T10:00:00Z\n"
                              "2,2024-05-01T10:00:01Z\n"
                              "3,2024-05-01T10:00:01Z\n");
  EXPECT_THAT(input_error_message([&] {
                read_csv_log(path, map_of({{"time", "Time"}}));
              }),
              ContainsRegex("bad\\.csv:4:2 \\(Time\\): time '2024-05-01T10:00:01Z' \\(1 s\\) "
                            "repeats the previous row's 1 s \\(line 3, time stamps read as "
                            "iso8601\\)"));
  const auto text = dir.write("text.csv", "Time,a\n2024-05-01T10:00:00Z,1\nnoon,2\n");
  EXPECT_THAT(input_error_message([&] {
                read_csv_log(text, map_of({{"time", "Time"}}));
              }),
              ContainsRegex("text\\.csv:3:1 \\(Time\\): 'noon' is not an ISO 8601 date-time"));
  // "Time (UTC)" is no unit; that matters only when the stamps are plain seconds.
  const auto utc = dir.write("utc.csv", "Time (UTC),a\n0.5,1\n");
  EXPECT_THAT(input_error_message([&] {
                read_csv_log(utc, map_of({{"time", "Time"}}));
              }),
              ContainsRegex("utc\\.csv:1:1 \\(Time \\(UTC\\)\\): unknown unit 'UTC'"));
}

TEST(CsvTimeStamps, DetectionLooksPastTheFirstRowsHeldBack) {
  // More rows than are held for detection, a window, and the plain-seconds fast path.
  TempDir dir;
  std::string text = "t,x\n";
  for (int k = 0; k < 1000; ++k) text += std::to_string(k) + "," + std::to_string(2 * k) + "\n";
  const auto path = dir.write("long.csv", text);
  CsvReadOptions window;
  window.t_from_s = 300.0;
  window.t_to_s = 700.0;
  const CsvLog r = read_csv_log(path, map_of({{"time", "t"}, {"output", "x"}}), window);
  ASSERT_EQ(r.log.size(), 401u);
  EXPECT_EQ(r.log.time().front(), 300.0);
  EXPECT_EQ(r.log.values("output").back(), 1400.0);
  const CsvLog all = read_csv_log(path, map_of({{"time", "t"}, {"output", "x"}}));
  ASSERT_EQ(all.log.size(), 1000u);
  EXPECT_EQ(all.log.values("output")[255], 510.0);
  EXPECT_EQ(all.log.values("output")[256], 512.0);
}

// A time column whose header or map declares a unit is read in that unit whatever its size:
// an uptime counter in ms past 10⁹ (11.6 days) is no epoch second.
TEST(CsvTimeStamps, ADeclaredUnitIsNotOverriddenByTheEpochMagnitudes) {
  TempDir dir;
  struct Case {
    const char* unit;
    std::int64_t first;  // first count, in the unit
    std::int64_t step;   // 0.1 s in the unit
  };
  for (const Case c : {Case{"ms", 1'000'000'000, 100}, Case{"us", 1'000'000'000'000, 100'000},
                       Case{"ns", 1'000'000'000'000'000, 100'000'000}}) {
    std::string text = fmt::format("time [{}],heading\n", c.unit);
    for (int k = 0; k < 5; ++k) text += fmt::format("{},{}\n", c.first + k * c.step, k);
    const auto path = dir.write(fmt::format("uptime_{}.csv", c.unit), text);
    const CsvLog r = read_csv_log(
        path, map_of({{"time", fmt::format("time [{}]", c.unit).c_str()}, {"heading", "heading"}}));
    EXPECT_EQ(r.time.format, "seconds") << c.unit;
    ASSERT_EQ(r.log.size(), 5u);
    EXPECT_NEAR(r.log.time()[4] - r.log.time()[0], 0.4, 1e-9) << c.unit;
    ASSERT_EQ(r.time.notes.size(), 1u) << c.unit;
    EXPECT_THAT(r.time.notes[0], ContainsRegex("declares its unit"));

    // The same unit declared by --unit (the map) instead of the header.
    const auto bare =
        dir.write(fmt::format("bare_{}.csv", c.unit), "time" + text.substr(text.find(',')));
    ColumnMap map = map_of({{"time", "time"}, {"heading", "heading"}});
    map.set_unit({.role = "time", .unit = c.unit});
    EXPECT_EQ(read_csv_log(bare, map).time.format, "seconds") << c.unit;
    // Undeclared, the size still says epoch time.
    EXPECT_NE(read_csv_log(bare, map_of({{"time", "time"}, {"heading", "heading"}})).time.format,
              "seconds")
        << c.unit;
  }
  // A declared unit that is the epoch form's own unit keeps the epoch reading.
  const auto epoch_ms = dir.write("epoch_ms.csv", "t [ms],h\n1714557600000,1\n1714557600100,2\n");
  const CsvLog e = read_csv_log(epoch_ms, map_of({{"time", "t [ms]"}, {"heading", "h"}}));
  EXPECT_EQ(e.time.format, "epoch-ms");
  EXPECT_EQ(e.time.origin, "2024-05-01T10:00:00Z");
}

// One row 50 ms back among decimals of varying length ("12.85" after "12.9") is a row out of
// order, not the unpadded-nanosecond exporter bug: an error by default, dropped on request.
TEST(CsvTimeStamps, OneRowBackIsNotTheUnpaddedNanosecondBug) {
  TempDir dir;
  std::string text = "time,heading\n";
  for (int k = 0; k < 300; ++k) {
    text += fmt::format("{:.1f},{}\n", 0.1 * k, k);
    if (k == 129) text += "12.85,-1\n";  // after 12.9, at line 132
  }
  const auto path = dir.write("one_back.csv", text);
  ColumnMap map = map_of({{"time", "time"}, {"heading", "heading"}});
  EXPECT_THAT(input_error_message([&] { read_csv_log(path, map); }),
              ContainsRegex("one_back\\.csv:132:1 \\(time\\): time 12\\.85 s goes back"));
  map.time().order = TimeOrder::kDropNonIncreasing;
  const CsvLog r = read_csv_log(path, map);
  EXPECT_EQ(r.time.format, "seconds");
  EXPECT_TRUE(r.time.notes.empty());
  ASSERT_EQ(r.log.size(), 300u);
  EXPECT_EQ(r.time.skipped.count("time going back"), 1u);
  EXPECT_DOUBLE_EQ(r.log.time()[299], 29.9);
}

// Lines that end with CR alone would make the whole file one header line.
TEST(CsvTimeStamps, CarriageReturnOnlyLineEndsAreRefused) {
  TempDir dir;
  const auto path = dir.write("mac.csv", "time,heading\r0,1\r0.1,2\r");
  EXPECT_THAT(input_error_message([&] {
                read_csv_log(path, map_of({{"time", "time"}, {"heading", "heading"}}));
              }),
              ContainsRegex("mac\\.csv:1:13.*carriage return.*end with CR alone"));
}

// A leap second in ISO stamps: read, and counted in the time axis (t runs on by 1 s).
TEST(CsvTimeStamps, LeapSecondInIsoStamps) {
  TempDir dir;
  const auto path = dir.write("leap.csv",
                              "time,heading\n"
                              "2016-12-31T23:59:59.5Z,1\n"
                              "2016-12-31T23:59:60.0Z,2\n"
                              "2016-12-31T23:59:60.5Z,3\n"
                              "2017-01-01T00:00:00.0Z,4\n"
                              "2017-01-01T00:00:00.5Z,5\n");
  const CsvLog r = read_csv_log(path, map_of({{"time", "time"}, {"heading", "heading"}}));
  EXPECT_EQ(r.log.time(), (std::vector<double>{0.0, 0.5, 1.0, 1.5, 2.0}));
  ASSERT_EQ(r.time.notes.size(), 1u);
  EXPECT_THAT(r.time.notes[0], ContainsRegex("leap second.*line 3"));
}

// sec-nsec seconds whose nanoseconds leave 64 bits (after 2262) are an error, not a wrap.
TEST(CsvTimeStamps, SecNsecBeyond2262IsAnError) {
  TempDir dir;
  const auto path = dir.write("far.csv", "sec,nsec,h\n9300000000,0,1\n9300000001,0,2\n");
  EXPECT_THAT(
      input_error_message([&] {
        read_csv_log(path, map_of({{"time.sec", "sec"}, {"time.nsec", "nsec"}, {"heading", "h"}}));
      }),
      ContainsRegex("far\\.csv:2:1 \\(sec\\): '9300000000' is not a second within 64-bit"));
}

}  // namespace
}  // namespace dynpos::io
