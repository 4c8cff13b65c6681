#include "dynpos/io/time_stamp.hpp"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io_test_util.hpp"

namespace dynpos::io {
namespace {

using ::testing::ContainsRegex;
using testing::input_error_message;

constexpr std::int64_t kS = 1'000'000'000;  // ns per s
// 2024-05-01T10:00:00Z: 19844 days (1714521600 s) after 1970-01-01, plus 10 h.
constexpr std::int64_t kMay1At10Z = 1'714'557'600 * kS;

TEST(TimeStamp, DaysFromCivilMatchesKnownDates) {
  EXPECT_EQ(days_from_civil(1970, 1, 1), 0);
  EXPECT_EQ(days_from_civil(1969, 12, 31), -1);
  EXPECT_EQ(days_from_civil(2000, 3, 1), 11017);  // 951868800 s
  EXPECT_EQ(days_from_civil(2024, 5, 1), 19844);  // 1714521600 s
  // Leap years: 2000 and 2024 have 29 February, 1900 and 2023 do not.
  EXPECT_EQ(days_from_civil(2000, 3, 1) - days_from_civil(2000, 2, 28), 2);
  EXPECT_EQ(days_from_civil(2024, 3, 1) - days_from_civil(2024, 2, 28), 2);
  EXPECT_EQ(days_from_civil(1900, 3, 1) - days_from_civil(1900, 2, 28), 1);
  EXPECT_EQ(days_from_civil(2023, 3, 1) - days_from_civil(2023, 2, 28), 1);
  EXPECT_TRUE(is_valid_date({2000, 2, 29}));
  EXPECT_TRUE(is_valid_date({2024, 2, 29}));
  EXPECT_FALSE(is_valid_date({1900, 2, 29}));
  EXPECT_FALSE(is_valid_date({2023, 2, 29}));
  EXPECT_FALSE(is_valid_date({2024, 4, 31}));
  EXPECT_FALSE(is_valid_date({2024, 13, 1}));
  EXPECT_FALSE(is_valid_date({2024, 0, 1}));
}

TEST(TimeStamp, FormatAndParseRoundTripOverCenturies) {
  // Every 37 days and 1 ns over the int64 ns range (1678-2261; leap and century years
  // included), at three offsets: parse(format(ns)) is the identity.
  for (std::int64_t day = days_from_civil(1678, 1, 1); day < days_from_civil(2262, 1, 1);
       day += 37) {
    const std::int64_t ns = day * 86'400 * kS + (day % 86'400) * kS + 1;
    for (const int offset : {0, 120, -270}) {
      const std::string text = format_iso8601(ns, offset);
      const auto back = parse_iso8601(text);
      ASSERT_TRUE(back) << text;
      EXPECT_EQ(back->ns, ns) << text;
      EXPECT_EQ(back->utc_offset_min, offset) << text;
    }
  }
}

TEST(TimeStamp, Iso8601SeparatorsAndZones) {
  struct Case {
    const char* text;
    std::int64_t ns;
    std::optional<int> offset_min;
  };
  const std::vector<Case> cases = {
      {"2024-05-01T10:00:00Z", kMay1At10Z, 0},
      {"2024-05-01 10:00:00Z", kMay1At10Z, 0},
      {"2024/05/01T10:00:00z", kMay1At10Z, 0},
      {"2024-05-01T10:00Z", kMay1At10Z, 0},
      {"2024-05-01T12:00:00+02:00", kMay1At10Z, 120},
      {"2024-05-01T12:00:00+0200", kMay1At10Z, 120},
      {"2024-05-01T12:00:00+02", kMay1At10Z, 120},
      {"2024-05-01 12:00:00 +02:00", kMay1At10Z, 120},
      {"2024-05-01T05:30:00-04:30", kMay1At10Z, -270},
      {"2024-05-01T10:00:00", kMay1At10Z, std::nullopt},  // local wall clock
      {" 2024-05-01T10:00:00 ", kMay1At10Z, std::nullopt},
      {"2024-05-01T00:30:00+01:00", kMay1At10Z - 10 * 3600 * kS - 30 * 60 * kS, 60},
  };
  for (const Case& c : cases) {
    const auto stamp = parse_iso8601(c.text);
    ASSERT_TRUE(stamp) << c.text;
    EXPECT_EQ(stamp->ns, c.ns) << c.text;
    EXPECT_EQ(stamp->utc_offset_min, c.offset_min) << c.text;
  }
}

TEST(TimeStamp, Iso8601FractionDigitsZeroToNineAndBeyond) {
  const std::string digits = "123456789";
  EXPECT_EQ(parse_iso8601("2024-05-01T10:00:00Z")->ns, kMay1At10Z);
  std::int64_t scale = kS;
  for (std::size_t k = 1; k <= 9; ++k) {
    scale /= 10;
    const std::string text = "2024-05-01T10:00:00." + digits.substr(0, k) + "Z";
    const auto stamp = parse_iso8601(text);
    ASSERT_TRUE(stamp) << text;
    EXPECT_EQ(stamp->ns - kMay1At10Z, std::stoll(digits.substr(0, k)) * scale) << text;
  }
  // Digits below 1 ns are truncated, not rounded.
  EXPECT_EQ(parse_iso8601("2024-05-01T10:00:00.123456789999Z")->ns, kMay1At10Z + 123456789);
}

TEST(TimeStamp, Iso8601RejectsImpossibleDatesAndTimes) {
  for (const char* text :
       {"2024-13-01T00:00:00Z", "2023-02-29T00:00:00Z", "1900-02-29T00:00:00Z",
        "2024-04-31T00:00:00Z", "2024-05-01T24:00:00Z", "2024-05-01T10:60:00Z",
        "2024-05-01T10:00:60Z", "2024-05-01", "2024-05-01T10:00:00+25:00",
        "2024-05-01T10:00:00+02:", "2024-05-01T10:00:00.Z", "2024-05-01X10:00:00",
        "2024-05-01T10:00:00ZZ", "2024-05/01T10:00:00", "24-05-01T10:00:00", "", "12.5"}) {
    EXPECT_FALSE(parse_iso8601(text)) << text;
  }
  EXPECT_FALSE(parse_iso8601("2300-01-01T00:00:00Z"));  // beyond int64 ns (2262)
  EXPECT_FALSE(parse_iso8601("1600-01-01T00:00:00Z"));
  EXPECT_TRUE(parse_iso8601("2024-02-29T00:00:00Z"));
  EXPECT_TRUE(parse_iso8601("2000-02-29T00:00:00Z"));
}

TEST(TimeStamp, TimeOfDayAndDate) {
  EXPECT_EQ(parse_time_of_day_ns("00:00:00"), 0);
  EXPECT_EQ(parse_time_of_day_ns("23:59:59.999999999"), 86'400 * kS - 1);
  EXPECT_EQ(parse_time_of_day_ns("9:05:00"), (9 * 3600 + 5 * 60) * kS);
  EXPECT_EQ(parse_time_of_day_ns("12:30"), (12 * 3600 + 30 * 60) * kS);
  EXPECT_EQ(parse_time_of_day_ns("12:00:00.5"), (12 * 3600) * kS + kS / 2);
  for (const char* text : {"24:00:00", "12:5:00", "12:00:00.", "12", "12:00:00Z", "1.5"}) {
    EXPECT_FALSE(parse_time_of_day_ns(text)) << text;
  }
  EXPECT_EQ(parse_date_days("2024-05-01"), 19844);
  EXPECT_EQ(parse_date_days("2024/05/01"), 19844);
  EXPECT_FALSE(parse_date_days("2024-02-30"));
  EXPECT_FALSE(parse_date_days("2024-05-01T00:00"));
  EXPECT_FALSE(parse_date_days("01.05.2024"));
}

TEST(TimeStamp, DecimalEpochIsExactInEveryUnit) {
  const std::int64_t expected = kMay1At10Z + 250'000'000;
  EXPECT_EQ(parse_decimal_ns("1714557600.25", 0), expected);
  EXPECT_EQ(parse_decimal_ns("1714557600250", 3), expected);
  EXPECT_EQ(parse_decimal_ns("1714557600250000", 6), expected);
  EXPECT_EQ(parse_decimal_ns("1714557600250000000", 9), expected);
  EXPECT_EQ(parse_decimal_ns("1714557600250.5", 3), expected + 500'000);
  // A fuzz finding: whole nanoseconds just below the int64 limit plus a fraction overflowed.
  EXPECT_EQ(parse_decimal_ns("9223372036854775.807", 6), INT64_MAX);
  EXPECT_EQ(parse_decimal_ns("-9223372036854775.84", 6), std::nullopt);
  EXPECT_EQ(parse_decimal_ns("9223372036.854775808", 0), std::nullopt);
  EXPECT_EQ(parse_decimal_ns("+1714557600.25", 0), expected);
  // A double near 1.7e18 has a spacing of 256 ns: the integer path keeps every digit.
  EXPECT_EQ(parse_decimal_ns("1714557600123456789", 9), kMay1At10Z + 123'456'789);
  EXPECT_EQ(parse_decimal_ns("1714557600.123456789", 0), kMay1At10Z + 123'456'789);
  EXPECT_EQ(parse_decimal_ns("0.1234567899", 0), 123'456'789);  // truncated below 1 ns
  EXPECT_EQ(parse_decimal_ns("-1.5", 0), -1'500'000'000);
  EXPECT_EQ(parse_decimal_ns(".5", 0), 500'000'000);
  // An exponent goes through a double: exact for these few digits.
  EXPECT_EQ(parse_decimal_ns("1.7145576e9", 0), kMay1At10Z);
  for (const char* text : {"", ".", "abc", "1.2.3", "1,5", "99999999999", "1e30", "12a"}) {
    EXPECT_FALSE(parse_decimal_ns(text, 0)) << text;
  }
}

TEST(TimeStamp, UnpaddedNanoseconds) {
  EXPECT_EQ(parse_unpadded_ns("16.79441101"), 16'079'441'101);
  EXPECT_EQ(parse_unpadded_ns("16.5"), 16 * kS + 5);
  EXPECT_EQ(parse_unpadded_ns("16.999999999"), 17 * kS - 1);
  EXPECT_FALSE(parse_unpadded_ns("16.1000000000"));  // 10 digits: not nanoseconds
  EXPECT_FALSE(parse_unpadded_ns("16"));
  EXPECT_FALSE(parse_unpadded_ns("-16.5"));
}

TEST(TimeStamp, LeapSecondsOnlyAtTheEndOfAUtcDayOrAnHourWithoutZone) {
  const auto utc = parse_iso8601("2016-12-31T23:59:60.25Z");
  ASSERT_TRUE(utc);
  EXPECT_TRUE(utc->leap_second);
  EXPECT_EQ(utc->ns, (days_from_civil(2017, 1, 1) * 86400) * kS + kS / 4);
  const auto zoned = parse_iso8601("2017-01-01T00:59:60+01:00");
  ASSERT_TRUE(zoned);
  EXPECT_TRUE(zoned->leap_second);
  EXPECT_TRUE(parse_iso8601("2016-12-31 23:59:60")->leap_second);  // local: any hh:59:60
  EXPECT_FALSE(parse_iso8601("2016-12-31T12:59:60Z"));             // not the end of a UTC day
  EXPECT_FALSE(parse_iso8601("2016-12-31T23:58:60Z"));
  EXPECT_FALSE(parse_iso8601("2016-12-31T23:59:61Z"));
  EXPECT_FALSE(parse_iso8601("2016-12-31T23:59:59Z")->leap_second);
  EXPECT_FALSE(parse_time_of_day_ns("23:59:60"));  // times of day: no leap seconds
}

TEST(TimeStamp, FormatIso8601ShowsOffsetAndShortestFraction) {
  const std::int64_t ns = kMay1At10Z + 250'000'000;
  EXPECT_EQ(format_iso8601(ns, 0), "2024-05-01T10:00:00.250Z");
  EXPECT_EQ(format_iso8601(ns, 120), "2024-05-01T12:00:00.250+02:00");
  EXPECT_EQ(format_iso8601(ns, -270), "2024-05-01T05:30:00.250-04:30");
  EXPECT_EQ(format_iso8601(ns, std::nullopt), "2024-05-01T10:00:00.250");
  EXPECT_EQ(format_iso8601(kMay1At10Z, 0), "2024-05-01T10:00:00Z");
  EXPECT_EQ(format_iso8601(kMay1At10Z + 1, 0), "2024-05-01T10:00:00.000000001Z");
  EXPECT_EQ(format_iso8601(kMay1At10Z + 1000, 0), "2024-05-01T10:00:00.000001Z");
  EXPECT_EQ(format_iso8601(-kS / 2, 0), "1969-12-31T23:59:59.500Z");
}

std::optional<TimeStampFormat> detect(std::vector<std::string_view> cells) {
  return detect_time_format(cells);
}

TEST(TimeStamp, DetectsEveryFormAndEpochMagnitude) {
  struct Case {
    std::vector<std::string_view> cells;
    TimeFormat format;
  };
  const std::vector<Case> cases = {
      {{"0", "0.1"}, TimeFormat::kSeconds},
      {{"999999999.5"}, TimeFormat::kSeconds},  // just below 1e9: 31.7 years of seconds
      {{"1714557600"}, TimeFormat::kEpochSeconds},
      {{"1714557600.25"}, TimeFormat::kEpochSeconds},
      {{"10000000000"}, TimeFormat::kSeconds},  // 1e10: neither s (year 2286+) nor ms
      {{"1714557600250"}, TimeFormat::kEpochMillis},
      {{"1714557600250.5"}, TimeFormat::kEpochMillis},
      {{"1714557600250000"}, TimeFormat::kEpochMicros},
      {{"1714557600250000000"}, TimeFormat::kEpochNanos},
      {{"", "2024-05-01T10:00:00Z"}, TimeFormat::kIso8601},
      {{"2024/05/01 10:00:00"}, TimeFormat::kIso8601},
      {{"10:00:00.25"}, TimeFormat::kTimeOfDay},
  };
  for (const Case& c : cases) {
    const auto detected = detect(c.cells);
    ASSERT_TRUE(detected) << c.cells.back();
    EXPECT_EQ(detected->format, c.format) << c.cells.back();
    EXPECT_FALSE(detected->unpadded_ns) << c.cells.back();
  }
  EXPECT_FALSE(detect({"abc"}));
  EXPECT_FALSE(detect({"", " "}));
  EXPECT_FALSE(detect({"01.05.2024 10:00"}));
}

// Cells "S.N" of a 10 Hz logger whose exporter drops the leading zeros of N [ns].
std::vector<std::string> unpadded_cells(std::int64_t first_ns, int rows) {
  std::vector<std::string> out;
  for (int k = 0; k < rows; ++k) {
    const std::int64_t ns = first_ns + k * (kS / 10);
    out.push_back(fmt::format("{}.{}", ns / kS, ns % kS));
  }
  return out;
}

TEST(TimeStamp, DetectsUnpaddedNanosecondsOnlyWhenDecimalsGoBack) {
  const std::vector<std::string> relative = unpadded_cells(16'079'441'101, 30);
  EXPECT_EQ(relative[0], "16.79441101");
  EXPECT_EQ(relative[1], "16.179441101");
  const std::vector<std::string_view> views(relative.begin(), relative.end());
  const auto detected = detect_time_format(views);
  ASSERT_TRUE(detected);
  EXPECT_EQ(detected->format, TimeFormat::kSeconds);
  EXPECT_TRUE(detected->unpadded_ns);

  const std::vector<std::string> epoch = unpadded_cells(kMay1At10Z + 79'441'101, 30);
  const std::vector<std::string_view> epoch_views(epoch.begin(), epoch.end());
  EXPECT_EQ(detect_time_format(epoch_views)->format, TimeFormat::kEpochSeconds);
  EXPECT_TRUE(detect_time_format(epoch_views)->unpadded_ns);

  // Negative cases: true decimals with trailing zeros dropped (lengths vary, never back); fixed
  // lengths going back (a real disorder); both readings going back; one row per second.
  for (const std::vector<std::string_view>& cells : std::vector<std::vector<std::string_view>>{
           {"16.5", "16.55", "16.6", "16.75"},
           {"16.500", "16.400", "16.600"},
           {"16.9", "16.10", "16.05"},
           {"16.79441101", "17.79441101", "18.7944110"},
           {"16.79441101", "abc", "16.179441101"},
           // one row back at 10 Hz, decimals
           {"12.7", "12.8", "12.9", "12.85", "13.0", "13.1", "13.2", "13.3"}}) {
    EXPECT_FALSE(looks_like_unpadded_ns(cells)) << cells.front() << ", " << cells[1];
  }
}

TEST(TimeStamp, FormatAndOrderNames) {
  for (const TimeFormat f :
       {TimeFormat::kAuto, TimeFormat::kSeconds, TimeFormat::kEpochSeconds,
        TimeFormat::kEpochMillis, TimeFormat::kEpochMicros, TimeFormat::kEpochNanos,
        TimeFormat::kIso8601, TimeFormat::kTimeOfDay, TimeFormat::kSecNsec}) {
    EXPECT_EQ(find_time_format(time_format_name(f)), f);
  }
  EXPECT_FALSE(find_time_format("iso"));
  for (const TimeOrder o :
       {TimeOrder::kError, TimeOrder::kDropDuplicates, TimeOrder::kDropNonIncreasing}) {
    EXPECT_EQ(find_time_order(time_order_name(o)), o);
  }
  EXPECT_FALSE(find_time_order("sort"));
}

// Reads `time` (and optional nsec/date) cells as rows 2, 3, … of "f.csv", time in column 2.
TimeColumn read(const std::vector<std::string_view>& time, TimeStampOptions options = {},
                const std::vector<std::string_view>& nsec = {},
                const std::vector<std::string_view>& date = {}) {
  std::vector<TimeCells> cells;
  std::vector<std::size_t> lines;
  for (std::size_t i = 0; i < time.size(); ++i) {
    cells.push_back({time[i], nsec.empty() ? "" : nsec[i], date.empty() ? "" : date[i]});
    lines.push_back(i + 2);
  }
  return read_time_column(cells, lines, options,
                          {"f.csv", "Time", 1, !nsec.empty(), !date.empty(), {}, 0.0});
}

TEST(TimeStampReader, IsoWithZoneBecomesSecondsSinceTheFirstRow) {
  const TimeColumn c = read({"2024-05-01T12:00:00+02:00", "2024-05-01T12:00:00.1+02:00",
                             "2024-05-01T10:00:01.000000001Z"});
  EXPECT_EQ(c.t_s, (std::vector<double>{0.0, 0.1, 1.000000001}));
  EXPECT_EQ(c.info.format, "iso8601");
  EXPECT_EQ(c.info.origin, "2024-05-01T12:00:00+02:00");
  EXPECT_EQ(c.info.origin_zone, "+02:00");
  EXPECT_EQ(c.info.origin_ns, kMay1At10Z);
}

TEST(TimeStampReader, IsoWithoutZoneIsLocalAndSaysSo) {
  const TimeColumn c = read({"2024-05-01 10:00:00", "2024-05-01 10:00:00.5"});
  EXPECT_EQ(c.t_s, (std::vector<double>{0.0, 0.5}));
  EXPECT_EQ(c.info.origin, "2024-05-01T10:00:00");
  EXPECT_EQ(c.info.origin_zone, "local (no zone in the file)");
  EXPECT_THAT(input_error_message([] {
                read({"2024-05-01 10:00:00", "2024-05-01 10:00:01Z"});
              }),
              ContainsRegex("f\\.csv:3:2 \\(Time\\).*mixes time stamps with and without"));
}

TEST(TimeStampReader, EpochNanosecondsKeepEveryNanosecond) {
  const TimeColumn c = read({"1714557600123456789", "1714557600123456790", "1714557601123456789"});
  EXPECT_EQ(c.info.format, "epoch-ns");
  EXPECT_EQ(c.t_s, (std::vector<double>{0.0, 1e-9, 1.0}));
  EXPECT_EQ(c.info.origin, "2024-05-01T10:00:00.123456789Z");
  EXPECT_EQ(c.info.origin_zone, "UTC");
}

TEST(TimeStampReader, TimeOfDayRollsOverMidnightIntoALeapDay) {
  TimeStampOptions options;
  options.date = "2024-02-28";
  const TimeColumn c = read({"23:59:59.5", "00:00:00.5", "11:00:00.5"}, options);
  EXPECT_EQ(c.t_s, (std::vector<double>{0.0, 1.0, 39601.0}));
  EXPECT_EQ(c.info.format, "time-of-day");
  EXPECT_EQ(c.info.origin, "2024-02-28T23:59:59.500");
  EXPECT_EQ(c.info.origin_zone, "local (no zone in the file)");
  // Back by less than 12 h is not a new day but time going back.
  EXPECT_THAT(input_error_message([&] {
                read({"12:00:00", "00:30:00"}, options);
              }),
              ContainsRegex("f\\.csv:3:2 \\(Time\\): time '00:30:00' \\(-41400 s\\) goes back"));
}

TEST(TimeStampReader, TimeOfDayTakesTheDateColumn) {
  const TimeColumn c = read({"23:59:59", "00:00:01"}, {}, {}, {"2024-12-31", "2025/01/01"});
  EXPECT_EQ(c.t_s, (std::vector<double>{0.0, 2.0}));
  EXPECT_EQ(c.info.origin, "2024-12-31T23:59:59");
  EXPECT_THAT(input_error_message([] { read({"23:59:59"}, {}, {}, {"31.12.2024"}); }),
              ContainsRegex("f\\.csv:2:2.*'31\\.12\\.2024' in the date column is not a date"));
}

TEST(TimeStampReader, TimeOfDayWithoutDateNotesIt) {
  const TimeColumn c = read({"10:00:00", "10:00:00.5"});
  EXPECT_EQ(c.t_s, (std::vector<double>{0.0, 0.5}));
  EXPECT_EQ(c.info.origin, "10:00:00");
  ASSERT_EQ(c.info.notes.size(), 1u);
  EXPECT_THAT(c.info.notes[0], ContainsRegex("without a date.*--date"));
}

TEST(TimeStampReader, SecNsecRelativeStaysAsLoggedEpochGetsAnOrigin) {
  const TimeColumn relative = read({"16", "16"}, {}, {"79441101", "179441101"});
  EXPECT_EQ(relative.info.format, "sec-nsec");
  // 16079441101 and 16179441101 are exact doubles; /1e9 is one correctly rounded division.
  EXPECT_EQ(relative.t_s, (std::vector<double>{16079441101 / 1e9, 16179441101 / 1e9}));
  EXPECT_FALSE(relative.info.origin);

  const TimeColumn epoch = read({"1714557600", "1714557600"}, {}, {"5", "7"});
  EXPECT_EQ(epoch.t_s, (std::vector<double>{0.0, 2e-9}));
  EXPECT_EQ(epoch.info.origin, "2024-05-01T10:00:00.000000005Z");
  EXPECT_THAT(input_error_message([] { read({"16"}, {}, {"1000000000"}); }),
              ContainsRegex("f\\.csv:2:2.*'1000000000' is not nanoseconds"));
}

TEST(TimeStampReader, UnpaddedNanosecondsAreReadAndNoted) {
  const std::vector<std::string> text = unpadded_cells(16'079'441'101, 12);
  const std::vector<std::string_view> cells(text.begin(), text.end());
  const TimeColumn c = read(cells);
  EXPECT_EQ(c.info.format, "seconds (unpadded nanoseconds)");
  ASSERT_EQ(c.info.notes.size(), 1u);
  EXPECT_THAT(c.info.notes[0], ContainsRegex("without leading zeros"));
  ASSERT_EQ(c.t_s.size(), 12u);
  EXPECT_EQ(c.t_s[0], 16079441101 / 1e9);
  EXPECT_EQ(c.t_s[11], 17179441101 / 1e9);
}

// The same exporter bug in date-time stamps: "2025/04/28 11:39:17.78903511" is 17.078903511 s.
TEST(TimeStampReader, UnpaddedNanosecondsInDateTimeStamps) {
  std::vector<std::string> text;
  for (int k = 0; k < 25; ++k) {
    const std::int64_t ns = 17'078'903'511 + k * (kS / 10);
    text.push_back(fmt::format("2025/04/28 11:39:{:02}.{}", ns / kS, ns % kS));
  }
  EXPECT_EQ(text[0], "2025/04/28 11:39:17.78903511");
  const std::vector<std::string_view> cells(text.begin(), text.end());
  const TimeColumn c = read(cells);
  EXPECT_EQ(c.info.format, "iso8601 (unpadded nanoseconds)");
  EXPECT_EQ(c.info.origin, "2025-04-28T11:39:17.078903511");
  ASSERT_EQ(c.t_s.size(), 25u);
  for (std::size_t k = 0; k < c.t_s.size(); ++k) {
    EXPECT_EQ(c.t_s[k], static_cast<double>(k * (kS / 10)) / 1e9) << k;
  }
  TimeStampOptions forced;
  forced.format = TimeFormat::kIso8601;
  EXPECT_EQ(read(cells, forced).info.format, "iso8601 (unpadded nanoseconds)");

  // Decimals of varying length, one row back: a row out of order, not the bug.
  const std::vector<std::string_view> one_back = {"2025/04/28 11:39:17.7", "2025/04/28 11:39:17.8",
                                                  "2025/04/28 11:39:17.9", "2025/04/28 11:39:17.85",
                                                  "2025/04/28 11:39:18.0", "2025/04/28 11:39:18.1"};
  EXPECT_FALSE(looks_like_unpadded_iso8601(one_back));
  EXPECT_THAT(
      input_error_message([&] { read(one_back); }),
      ContainsRegex("f\\.csv:5:2 \\(Time\\): time '2025/04/28 11:39:17\\.85' .* goes back"));
}

// A 1 Hz logger with the bug never goes back read as decimals; where its fraction drifts across
// 0.1 s (8 digits, then 9) the decimal reading steps 0.11 s instead of 1.001 s while the
// nanosecond reading keeps its pace: read as nanoseconds. A 1 Hz logger of true decimals
// printed to 9 digits without trailing zeros keeps its pace as decimals: decimals.
TEST(TimeStampReader, UnpaddedNanosecondsOfASlowLogger) {
  std::vector<std::string> iso, seconds;
  for (int k = 0; k < 30; ++k) {
    const std::int64_t ns = 17 * kS + 90'000'000 + k * (kS + 1'000'000);  // gains 1 ms/s
    iso.push_back(fmt::format("2025/04/28 11:39:{:02}.{}", ns / kS, ns % kS));
    seconds.push_back(fmt::format("{}.{}", ns / kS, ns % kS));
  }
  EXPECT_EQ(iso[9], "2025/04/28 11:39:26.99000000");
  EXPECT_EQ(iso[10], "2025/04/28 11:39:27.100000000");
  const std::vector<std::string_view> iso_cells(iso.begin(), iso.end());
  const TimeColumn c = read(iso_cells);
  EXPECT_EQ(c.info.format, "iso8601 (unpadded nanoseconds)");
  EXPECT_EQ(c.info.origin, "2025-04-28T11:39:17.090");
  ASSERT_EQ(c.t_s.size(), 30u);
  for (std::size_t k = 0; k < c.t_s.size(); ++k) {
    EXPECT_NEAR(c.t_s[k], 1.001 * static_cast<double>(k), 1e-9) << k;
  }
  const std::vector<std::string_view> second_cells(seconds.begin(), seconds.end());
  EXPECT_TRUE(detect_time_format(second_cells)->unpadded_ns);

  // The same drift that never reaches 9 digits: the readings differ by a constant only.
  EXPECT_FALSE(looks_like_unpadded_iso8601(std::span(iso_cells).first(10)));
  // True decimals at 1 Hz, 9 digits where needed: as nanoseconds their steps would be 1.5 s
  // and 0.5 s.
  const std::vector<std::string_view> decimals = {"17.5", "18.500000001", "19.5", "20.499999999",
                                                  "21.5", "22.500000002", "23.5"};
  EXPECT_FALSE(looks_like_unpadded_ns(decimals));
  // A fraction with a leading zero is no unpadded integer.
  EXPECT_FALSE(looks_like_unpadded_ns(std::vector<std::string_view>{
      "17.90000000", "18.91000000", "19.92000000", "20.093000000", "21.104000000"}));
}

TEST(TimeStampReader, OrderPolicies) {
  const std::vector<std::string_view> cells = {"0", "0.1", "0.1", "0.05", "0.2"};
  EXPECT_THAT(
      input_error_message([&] { read(cells); }),
      ContainsRegex("f\\.csv:4:2 \\(Time\\): time 0\\.1 s repeats the previous row's 0\\.1 s "
                    "\\(line 3\\); time must be strictly increasing.*--time-order"));
  TimeStampOptions options;
  options.order = TimeOrder::kDropDuplicates;
  EXPECT_THAT(input_error_message([&] { read(cells, options); }),
              ContainsRegex("f\\.csv:5:2 \\(Time\\): time 0\\.05 s goes back"));
  options.order = TimeOrder::kDropNonIncreasing;
  const TimeColumn c = read(cells, options);
  EXPECT_EQ(c.t_s, (std::vector<double>{0.0, 0.1, 0.2}));
  EXPECT_EQ(c.kept, (std::vector<bool>{true, true, false, false, true}));
  EXPECT_EQ(c.info.skipped.count("duplicate time"), 1u);
  EXPECT_EQ(c.info.skipped.count("time going back"), 1u);
}

TEST(TimeStampReader, ErrorsNameLineColumnAndForm) {
  EXPECT_THAT(input_error_message([] {
                read({"2024-05-01T10:00:00Z", "2024-05-32T10:00:00Z"});
              }),
              ContainsRegex("f\\.csv:3:2 \\(Time\\): '2024-05-32T10:00:00Z' is not an ISO 8601"));
  EXPECT_THAT(input_error_message([] { read({"abc"}); }),
              ContainsRegex("f\\.csv:2:2 \\(Time\\): 'abc' is not a time stamp.*--time-format"));
  EXPECT_THAT(input_error_message([] {
                read({"1", ""});
              }),
              ContainsRegex("f\\.csv:3:2 \\(Time\\): the time cell is blank"));
  TimeStampOptions options;
  options.format = TimeFormat::kEpochMillis;
  EXPECT_THAT(input_error_message([&] { read({"2024-05-01T10:00:00Z"}, options); }),
              ContainsRegex("f\\.csv:2:2.*is not a number \\(epoch-ms\\)"));
  options.format = TimeFormat::kSecNsec;
  EXPECT_THAT(input_error_message([&] { read({"16"}, options); }),
              ContainsRegex("time-format.*sec-nsec.*--col time\\.nsec=COLUMN"));
  options = {};
  options.date = "2024-02-30";
  EXPECT_THAT(input_error_message([&] { read({"10:00:00"}, options); }),
              ContainsRegex("date.*'2024-02-30' is not a date"));
}

TEST(TimeStampReader, ForcedFormatOverridesDetection) {
  TimeStampOptions options;
  options.format = TimeFormat::kEpochMillis;
  // 1e11 ms (1973) is below the detection range; forced, it is epoch milliseconds.
  const TimeColumn c = read({"100000000000", "100000000250"}, options);
  EXPECT_EQ(c.info.format, "epoch-ms");
  EXPECT_EQ(c.t_s, (std::vector<double>{0.0, 0.25}));
  EXPECT_EQ(c.info.origin, "1973-03-03T09:46:40Z");
}

}  // namespace
}  // namespace dynpos::io
