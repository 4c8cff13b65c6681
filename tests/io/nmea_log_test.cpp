#include "dynpos/io/nmea_log.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "../source_dir.hpp"
#include "io_test_util.hpp"

namespace dynpos::io {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using testing::input_error_message;
using testing::TempDir;

constexpr double kDeg = std::numbers::pi / 180.0;
// Decimal fields are parsed to within a few ulp.
constexpr double kExact = 1e-12;
// Log time is (t − t₀)·10⁻⁹ of integer nanoseconds: exact to the double's spacing near 100 s.
constexpr double kTime = 1e-12;

std::filesystem::path capture(std::string_view name) {
  return std::filesystem::path(DYNPOS_SOURCE_DIR) / "tests" / "data" / "nmea" / name;
}

std::string framed(const std::string& body) {
  unsigned sum = 0;
  for (const char c : body) sum ^= static_cast<unsigned char>(c);
  const char* hex = "0123456789ABCDEF";
  return "$" + body + "*" + hex[sum >> 4] + hex[sum & 15];
}

std::string lines(const std::vector<std::string>& text) {
  std::string out;
  for (const std::string& s : text) out += s + "\r\n";
  return out;
}

// The station-keeping capture (tests/data/nmea/station.nmea): 20 GNGGA fixes at 1 Hz from
// 23:59:50 on 2024-05-01 across midnight, the antenna 1 m north and 0.5 m east of 63.44° N
// 10.40° E, then as far south and west, alternately; HEHDT 91° and 89° alternately; and the
// traps of a real capture.
TEST(NmeaLog, StationCaptureCountsEveryTrap) {
  const NmeaLog read = read_nmea_log(capture("station.nmea"));
  const FileReport& r = read.report;
  EXPECT_EQ(r.format, "nmea");
  EXPECT_EQ(r.time_format, "nmea utc");
  EXPECT_EQ(r.records, 44u);                    // 20 GGA + 20 HDT + 4 ZDA
  EXPECT_EQ(r.skipped.count("truncated"), 2u);  // the first and the last line
  EXPECT_EQ(r.skipped.count("comment"), 1u);
  EXPECT_EQ(r.skipped.count("bad checksum"), 1u);
  EXPECT_EQ(r.skipped.count("other talker"), 1u);      // GPGGA after GNGGA
  EXPECT_EQ(r.skipped.count("unknown sentence"), 1u);  // GSV
  EXPECT_EQ(r.skipped.total(), 6u);
  EXPECT_EQ(r.accepted.count("no checksum"), 1u);
  EXPECT_THAT(r.notes, ::testing::Contains(HasSubstr("lat from GGA")));
  ASSERT_TRUE(read.origin);
  EXPECT_EQ(*read.origin, "2024-05-01T23:59:50.000Z");

  const core::Log& log = read.log;
  EXPECT_THAT(log.channel_names(), ElementsAre("lat", "lon", "height", "heading"));
  ASSERT_EQ(log.size(), 20u);
  // Midnight: 23:59:59 → 00:00:00 continues the time axis.
  for (std::size_t i = 0; i < log.size(); ++i) EXPECT_NEAR(log.time()[i], double(i), kTime);
  EXPECT_NEAR(log.values("height")[0], 12.345 + 39.5, kExact);
  EXPECT_NEAR(log.values("heading")[0], 91.0 * kDeg, kExact);
  EXPECT_NEAR(log.values("heading")[1], 89.0 * kDeg, kExact);
  EXPECT_NEAR(log.values("lat")[0], (63.0 + 26.4005383 / 60.0) * kDeg, kExact);
}

// The Seapath capture (tests/data/nmea/seapath_logger.nmea): logger stamps without a zone,
// INGGA with an empty geoid separation, PSXN,20/22/23, ROT and a line of binary noise.
TEST(NmeaLog, SeapathLoggerStampsAttitudeAndQualityFlags) {
  const NmeaLog read = read_nmea_log(capture("seapath_logger.nmea"));
  const FileReport& r = read.report;
  EXPECT_EQ(r.time_format, "iso8601 (logger)");
  EXPECT_EQ(r.records, 12u);
  EXPECT_EQ(r.skipped.count("binary"), 1u);
  EXPECT_EQ(r.skipped.count("comment"), 1u);
  EXPECT_EQ(r.skipped.count("unknown sentence"), 1u);  // PSXN,21
  EXPECT_EQ(r.accepted.count("empty geoid separation"), 2u);
  EXPECT_THAT(r.notes, ::testing::Contains(HasSubstr("without a zone")));
  EXPECT_THAT(r.notes, ::testing::Contains(HasSubstr("separation taken as 0")));
  ASSERT_TRUE(read.origin);
  EXPECT_EQ(*read.origin, "2024-05-01T10:00:00.000Z");

  const core::Log& log = read.log;
  EXPECT_THAT(log.channel_names(),
              ElementsAre("lat", "lon", "height", "heading", "roll", "pitch", "down", "r"));
  const std::vector<double> t = {0.0, 0.01, 0.03, 0.23, 0.43, 0.5, 1.0, 1.01};
  ASSERT_EQ(log.size(), t.size());
  for (std::size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(log.time()[i], t[i], kTime);
  EXPECT_NEAR(log.values("lat")[0], 63.44 * kDeg, kExact);
  EXPECT_NEAR(log.values("lon")[0], 10.40 * kDeg, kExact);
  EXPECT_NEAR(log.values("height")[6], 7.35, kExact);  // altitude + an empty (0) separation
  EXPECT_TRUE(std::isnan(log.values("height")[1]));    // no GGA at 0.01 s: missing, not 0
  // Heading from HDT (first in the order), not from PSXN,23.
  EXPECT_NEAR(log.values("heading")[1], 104.68 * kDeg, kExact);
  EXPECT_TRUE(std::isnan(log.values("heading")[2]));
  // Seapath signs equal ours: roll + starboard down, pitch + bow up, heave + down.
  EXPECT_NEAR(log.values("roll")[2], 1.28 * kDeg, kExact);
  EXPECT_NEAR(log.values("pitch")[3], -1.90 * kDeg, kExact);
  EXPECT_NEAR(log.values("down")[2], -0.24, kExact);
  // PSXN,20 roll/pitch quality 2 (invalid) drops roll and pitch, keeps heave.
  EXPECT_TRUE(std::isnan(log.values("roll")[4]));
  EXPECT_NEAR(log.values("down")[4], 0.10, kExact);
  // ROT −6 °/min: bow turning to port at 0.1 °/s.
  EXPECT_NEAR(log.values("r")[5], -0.1 * kDeg, kExact);
}

TEST(NmeaLog, NoUsableSentenceSaysWhatWasFound) {
  const std::string message = input_error_message([] { read_nmea_log(capture("nothing.nmea")); });
  EXPECT_THAT(message, HasSubstr("nothing.nmea: no usable NMEA sentence"));
  EXPECT_THAT(message, HasSubstr("1 bad checksum, 1 comment, 3 unknown sentence"));
}

TEST(NmeaLog, StrictNamesFileAndLineOfTheFirstSkippedLine) {
  NmeaLogOptions strict;
  strict.strict = true;
  const std::string message =
      input_error_message([&] { read_nmea_log(capture("station.nmea"), strict); });
  EXPECT_THAT(message, HasSubstr("station.nmea:1: line not usable (truncated)"));
  const std::string bad_checksum = input_error_message([&] {
    TempDir dir;
    read_nmea_log(
        dir.write("c.nmea", lines({framed("GPZDA,080000,01,05,2024,,"), "$HEHDT,2.0,T*00"})),
        strict);
  });
  EXPECT_THAT(bad_checksum, HasSubstr("c.nmea:2 (checksum): checksum mismatch"));
}

TEST(NmeaLog, EpochSecondsStampsGllThsAndPrefix) {
  TempDir dir;
  const auto file = dir.write(
      "gll.nmea", lines({"1714557600.000;" + framed("GPGLL,6326.4000,N,01024.0000,E,100000,A"),
                         "1714557600.125;" + framed("INTHS,123.4,A"),
                         "1714557600.250;" + framed("INTHS,123.6,V"),  // not valid: no sample
                         "1714557601.000;" + framed("GPGLL,6326.4000,S,01024.0000,W,100001,A")}));
  NmeaLogOptions options;
  options.prefix = "gnss2";
  const NmeaLog read = read_nmea_log(file, options);
  EXPECT_EQ(read.report.time_format, "epoch seconds (logger)");
  EXPECT_EQ(*read.origin, "2024-05-01T10:00:00.000Z");
  EXPECT_THAT(read.log.channel_names(), ElementsAre("gnss2.lat", "gnss2.lon", "gnss2.heading"));
  ASSERT_EQ(read.log.size(), 3u);
  EXPECT_NEAR(read.log.time()[1], 0.125, kTime);
  EXPECT_NEAR(read.log.values("gnss2.lat")[2], -63.44 * kDeg, kExact);
  EXPECT_NEAR(read.log.values("gnss2.heading")[1], 123.4 * kDeg, kExact);
}

// Fuzz findings: logger stamps of year 0024, of twelve epoch digits, and of 1731 beside 2024
// (their difference) overflowed the int64 nanoseconds. Stamps name 1970…2199: others are bad
// stamps, their lines skipped and counted, the others read.
TEST(NmeaLog, StampsOutsideTheNanosecondRangeAreBadStamps) {
  TempDir dir;
  const auto file =
      dir.write("old.nmea", lines({"2024-05-01 10:00:00.000 " + framed("HEHDT,10.0,T"),
                                   "0024-05-01 10:00:00.500 " + framed("HEHDT,10.5,T"),
                                   "2024-05-01 10:00:01.000 " + framed("HEHDT,11.0,T"),
                                   "999999999999.5 " + framed("HEHDT,11.5,T"),
                                   "1731-05-01 10:00:01.500 " + framed("HEHDT,11.7,T")}));
  const NmeaLog read = read_nmea_log(file);
  EXPECT_EQ(*read.origin, "2024-05-01T10:00:00.000Z");
  EXPECT_THAT(read.log.values("heading"), ElementsAre(10.0 * kDeg, 11.0 * kDeg));
  EXPECT_EQ(read.report.skipped.count("bad time stamp"), 3u);
}

// Binary data of another protocol on the same serial port: a line beyond kMaxNmeaLineBytes is
// skipped and counted; some 16 MiB without a line end is not a text capture (an error naming the
// line), so /dev/zero or a binary file costs bounded memory.
TEST(NmeaLog, OverlongLinesAreSkippedAndEndlessOnesAreAnError) {
  TempDir dir;
  const std::string binary(kMaxNmeaLineBytes + 10, '\x01');
  const auto mixed = dir.write(
      "mixed.nmea", lines({framed("GPZDA,100000,01,05,2024,,"), framed("HEHDT,10.0,T"), binary,
                           framed("GPZDA,100001,01,05,2024,,"), framed("HEHDT,11.0,T")}));
  const NmeaLog read = read_nmea_log(mixed);
  EXPECT_THAT(read.log.values("heading"), ElementsAre(10.0 * kDeg, 11.0 * kDeg));
  EXPECT_EQ(read.report.skipped.count("too long"), 1u);
  NmeaLogOptions strict;
  strict.strict = true;
  EXPECT_THAT(input_error_message([&] { read_nmea_log(mixed, strict); }),
              HasSubstr("mixed.nmea:3: line not usable (too long)"));
  const auto endless =
      dir.write("endless.nmea",
                framed("HEHDT,10.0,T") + "\n" + std::string(kMaxNmeaJunkBytes + (1 << 20), '\0'));
  EXPECT_THAT(input_error_message([&] { read_nmea_log(endless); }),
              HasSubstr("endless.nmea:2: no line end within 16 MiB: not a text capture"));
  EXPECT_FALSE(looks_like_nmea(endless));
}

TEST(NmeaLog, IsoStampsWithZoneAndWantedFilter) {
  TempDir dir;
  const auto file =
      dir.write("zone.nmea", lines({"2024-05-01T12:00:00.5+02:00 " + framed("HEHDT,10.0,T"),
                                    "2024-05-01T10:00:00.75Z " + framed("HEHDT,11.0,T"),
                                    "2024-05-01T12:00:01.5+02:00 " + framed("TIROT,60.0,A")}));
  NmeaLogOptions options;
  options.wanted = [](const std::string& channel) { return channel == "heading"; };
  const NmeaLog read = read_nmea_log(file, options);
  EXPECT_EQ(*read.origin, "2024-05-01T10:00:00.500Z");
  EXPECT_THAT(read.log.channel_names(), ElementsAre("heading"));
  ASSERT_EQ(read.log.size(), 2u);  // the ROT time is not on the axis of the wanted channels
  EXPECT_NEAR(read.log.time()[1], 0.25, kTime);
}

TEST(NmeaLog, HdgIsMagneticPlusDeviationPlusVariation) {
  TempDir dir;
  const auto file = dir.write(
      "hdg.nmea", lines({framed("GPZDA,080000,01,05,2024,,"), framed("HCHDG,100.0,1.5,E,2.0,W"),
                         framed("GPZDA,080001,01,05,2024,,"), framed("HCHDG,100.0,,,,")}));
  const NmeaLog read = read_nmea_log(file);
  EXPECT_NEAR(read.log.values("heading")[0], 99.5 * kDeg, kExact);
  EXPECT_NEAR(read.log.values("heading")[1], 100.0 * kDeg, kExact);
  EXPECT_THAT(read.report.notes, ::testing::Contains(HasSubstr("magnetic, not true")));
}

TEST(NmeaLog, UntimedRepeatsAndSentencesBeforeTheFirstTime) {
  TempDir dir;
  const auto file =
      dir.write("untimed.nmea",
                lines({framed("HEHDT,1.0,T"),             // before any UTC time
                       framed("GPGGA,,,,,,0,00,,,,,,,"),  // receiver without a fix: no time yet
                       framed("GPRMC,120000.00,A,6000.0,N,01000.0,E,0.0,0.0,010524,,,A"),
                       framed("HEHDT,2.0,T"), framed("HEHDT,3.0,T"),  // a 2nd in the epoch
                       framed("GPRMC,120001.00,V,,,,,,,010524,,,N"), framed("HEHDT,4.0,T")}));
  const NmeaLog read = read_nmea_log(file);
  EXPECT_EQ(read.report.skipped.count("no time"), 2u);
  EXPECT_EQ(read.report.skipped.count("repeat in epoch"), 1u);
  EXPECT_EQ(read.report.accepted.count("no fix"), 1u);
  EXPECT_EQ(*read.origin, "2024-05-01T12:00:00.000Z");
  EXPECT_THAT(read.log.channel_names(), ElementsAre("lat", "lon", "heading"));
  EXPECT_NEAR(read.log.values("heading")[1], 4.0 * kDeg, kExact);
  EXPECT_TRUE(std::isnan(read.log.values("lat")[1]));  // RMC status V: no position
}

// Two clocks in one capture: GGA times that step back (by 1.5 s, by 1 h) are not sorted in
// among the others. Each sentence at a time before the latest is dropped and counted as "time
// back", with the untimed sentences of its epoch; strict reading stops at the first one. A
// step back of more than 12 h stays a midnight rollover.
TEST(NmeaLog, AClockSteppingBackIsDroppedAndCountedNotSorted) {
  TempDir dir;
  const auto gga = [](const std::string& hhmmss_ss, const std::string& lat_min) {
    return framed("GPGGA," + hhmmss_ss + ",6000." + lat_min +
                  ",N,01000.000,E,4,12,0.7,1.0,M,"
                  "39.5,M,,");
  };
  const auto file =
      dir.write("two_clocks.nmea",
                lines({framed("GPZDA,100000.00,01,05,2024,,"), gga("100000.00", "000"),
                       framed("HEHDT,10.0,T"), gga("100001.00", "001"), framed("HEHDT,11.0,T"),
                       gga("095959.50", "900"), framed("HEHDT,200.0,T"),  // back by 1.5 s
                       gga("100002.00", "002"), framed("HEHDT,12.0,T"), gga("090002.50", "800"),
                       framed("HEHDT,300.0,T"),  // back by 1 h
                       gga("100003.00", "003"), framed("HEHDT,13.0,T")}));
  const NmeaLog read = read_nmea_log(file);
  EXPECT_EQ(read.report.skipped.count("time back"), 4u);  // two GGA and their HDT
  ASSERT_EQ(read.log.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(read.log.time()[i], double(i), kTime);
    EXPECT_NEAR(read.log.values("heading")[i], (10.0 + double(i)) * kDeg, kExact);
    EXPECT_NEAR(read.log.values("lat")[i], (60.0 + 0.001 * double(i) / 60.0) * kDeg, kExact);
  }
  NmeaLogOptions strict;
  strict.strict = true;
  EXPECT_THAT(input_error_message([&] { read_nmea_log(file, strict); }),
              HasSubstr("two_clocks.nmea:6: line not usable (time back): GGA at 09:59:59.500 "
                        "after 10:00:01.000"));
}

// A UTF-8 byte order mark before the first sentence (an editor's save) is not part of it: the
// capture is detected as NMEA and its first line read, also strictly.
TEST(NmeaLog, AByteOrderMarkIsNotPartOfTheFirstLine) {
  TempDir dir;
  const std::string text = lines({framed("GPZDA,100000,01,05,2024,,"), framed("HEHDT,10.0,T"),
                                  framed("GPZDA,100001,01,05,2024,,"), framed("HEHDT,11.0,T")});
  const auto file = dir.write("bom.nmea", "\xEF\xBB\xBF" + text);
  EXPECT_TRUE(looks_like_nmea(file));
  NmeaLogOptions strict;
  strict.strict = true;
  const NmeaLog read = read_nmea_log(file, strict);
  EXPECT_EQ(read.report.records, 4u);
  EXPECT_EQ(read.report.skipped.total(), 0u);
  EXPECT_THAT(read.log.values("heading"), ElementsAre(10.0 * kDeg, 11.0 * kDeg));
  // Elsewhere than at the start of the file the same bytes are binary data.
  const auto inside = dir.write("inside.nmea", text + "\xEF\xBB\xBF" + text);
  EXPECT_EQ(read_nmea_log(inside).report.skipped.count("binary"), 1u);
}

// Line ends: LF, CR LF, or a lone CR (as some loggers and old terminals write them) read alike,
// line numbers too.
TEST(NmeaLog, ALoneCarriageReturnEndsALine) {
  TempDir dir;
  const std::vector<std::string> sentences = {
      framed("GPZDA,100000,01,05,2024,,"), framed("HEHDT,10.0,T"),
      framed("GPZDA,100001,01,05,2024,,"), "$HEHDT,2.0,T*00", framed("HEHDT,11.0,T")};
  std::string cr, lf, crlf;
  for (const std::string& s : sentences) {
    cr += s + "\r";
    lf += s + "\n";
    crlf += s + "\r\n";
  }
  NmeaLogOptions strict;
  strict.strict = true;
  for (const auto& [name, text] :
       {std::pair{"cr.nmea", cr}, std::pair{"lf.nmea", lf}, std::pair{"crlf.nmea", crlf}}) {
    const auto file = dir.write(name, text);
    EXPECT_TRUE(looks_like_nmea(file)) << name;
    const NmeaLog read = read_nmea_log(file);
    EXPECT_EQ(read.report.records, 4u) << name;
    EXPECT_EQ(read.report.skipped.count("bad checksum"), 1u) << name;
    EXPECT_THAT(read.log.values("heading"), ElementsAre(10.0 * kDeg, 11.0 * kDeg)) << name;
    EXPECT_THAT(input_error_message([&] { read_nmea_log(file, strict); }),
                HasSubstr(std::string(name) + ":4 (checksum)"));
  }
}

// A file that holds no NMEA sentence at all (random bytes, /dev/urandom, a CSV log given as
// NMEA) is refused after a stated amount, not read to its end, which may never come.
TEST(NmeaLog, NoValidSentenceInTheFirstLinesIsNotACapture) {
  const std::string urandom = input_error_message([] { read_nmea_log("/dev/urandom"); });
  EXPECT_THAT(urandom, HasSubstr("/dev/urandom:"));
  EXPECT_THAT(urandom, HasSubstr("not an NMEA capture: no valid NMEA sentence in the first"));
  TempDir dir;
  std::string csv = "time,heading\n";
  for (int i = 0; i < 150000; ++i) csv += std::to_string(i) + ",1.5\n";
  EXPECT_THAT(input_error_message([&] { read_nmea_log(dir.write("log.csv", csv)); }),
              HasSubstr("log.csv:100000: not an NMEA capture: no valid NMEA sentence in the "
                        "first 100000 lines"));
  // A sentence of an unknown type without a checksum is no sign of a capture: random bytes
  // make one ("$P,…" is proprietary) about once in 2·10⁷ lines, and /dev/urandom was then read
  // until killed.
  EXPECT_THAT(input_error_message(
                  [&] { read_nmea_log(dir.write("junk.nmea", "$P,1\n$QWERT,1,2\n" + csv)); }),
              HasSubstr("junk.nmea:100000: not an NMEA capture"));
  // One valid sentence early enough, even of a type not read, and the rest is read.
  const auto late = dir.write(
      "late.nmea", framed("GPGSV,3,1,11,03,03,111,00,04,15,270,00") + "\n" + csv +
                       lines({framed("GPZDA,100000,01,05,2024,,"), framed("HEHDT,10.0,T")}));
  EXPECT_EQ(read_nmea_log(late).report.skipped.count("comment"), 150001u);
}

TEST(NmeaLog, SniffsCapturesNotCsv) {
  TempDir dir;
  EXPECT_TRUE(looks_like_nmea(capture("station.nmea")));
  EXPECT_TRUE(looks_like_nmea(capture("seapath_logger.nmea")));
  EXPECT_FALSE(looks_like_nmea(dir.write("log.csv", "time,north\n0,1\n1,2\n")));
}

}  // namespace
}  // namespace dynpos::io
