#include "dynpos/io/nmea.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "dynpos/io/nmea_writer.hpp"
#include "io_test_util.hpp"

namespace dynpos::io {
namespace {

using ::testing::HasSubstr;
using testing::input_error_message;
using testing::TempDir;

constexpr double kDeg = std::numbers::pi / 180.0;
// Decimal fields are parsed to within a few ulp.
constexpr double kExact = 1e-12;

// The checksum computed here, independently of the library.
std::string framed(const std::string& body) {
  unsigned sum = 0;
  for (const char c : body) sum ^= static_cast<unsigned char>(c);
  const char* hex = "0123456789ABCDEF";
  return "$" + body + "*" + hex[sum >> 4] + hex[sum & 15];
}

// Sentences as one file, CR LF after each.
std::string lines(const std::vector<std::string>& sentences) {
  std::string out;
  for (const std::string& s : sentences) out += s + "\r\n";
  return out;
}

std::string gga(const std::string& talker, const std::string& time, const std::string& lat_min,
                int quality = 4, const std::string& separation = "39.500") {
  return framed(talker + "GGA," + time + ",6326." + lat_min + ",N,01021.0000000,E," +
                std::to_string(quality) + ",12,0.7,1.000,M," + separation + ",M,,");
}

TEST(ReadNmeaGnss, EpochsJoinTimedAndUntimedSentences) {
  TempDir dir;
  const auto file = dir.write(
      "trial.nmea",
      lines({framed("HEHDT,10.0,T"),  // before the first epoch: skipped
             gga("GN", "100000.00", "0000000"),
             framed("GNRMC,100000.00,A,6326.0000000,N,"
                    "01021.0000000,E,1.000,90.00,270814,,,D"),
             framed("GNVTG,45.00,T,,,2.000,N,3.704,K,D"), framed("HEHDT,12.5,T"),
             framed("HEHDT,13.0,T"),  // a second heading in the same epoch: skipped
             framed("HEROT,-30.0,A"), framed("GPGSV,1,1,01,03,03,111,00"),  // other type
             gga("GN", "100001.00", "1000000"),
             framed("GNRMC,100001.00,A,6326.1000000,N,01021.0000000,E,1.000,90.00,270814,,,D"),
             framed("HEHDT,14.0,T")}));
  const NmeaGnssLog r = read_nmea_gnss(file, "gnss1");
  EXPECT_EQ(r.date, "2014-08-27");
  EXPECT_EQ(r.sentences, 11u);
  EXPECT_EQ(r.skipped, 3u);
  const core::Log& log = r.log;
  ASSERT_EQ(log.size(), 2u);
  EXPECT_EQ(log.time()[0], 36000.0);
  EXPECT_EQ(log.time()[1], 36001.0);
  EXPECT_NEAR(log.values("gnss1.lat")[0], (63 + 26.0 / 60) * kDeg, kExact);
  EXPECT_NEAR(log.values("gnss1.lat")[1], (63 + 26.1 / 60) * kDeg, kExact);
  EXPECT_NEAR(log.values("gnss1.lon")[1], 10.35 * kDeg, kExact);
  EXPECT_NEAR(log.values("gnss1.height")[0], 40.5, kExact);  // 1.000 + 39.500
  EXPECT_EQ(log.values("gnss1.quality")[0], 4.0);
  EXPECT_EQ(log.values("gnss1.satellites")[0], 12.0);
  EXPECT_NEAR(log.values("gnss1.hdop")[0], 0.7, kExact);
  EXPECT_EQ(log.channel("gnss1.lat").unit, "rad");
  // Epoch 1: VTG wins over RMC; epoch 2 has RMC only.
  EXPECT_NEAR(log.values("gnss1.sog")[0], 3.704 / 3.6, kExact);
  EXPECT_NEAR(log.values("gnss1.cog")[0], 45.0 * kDeg, kExact);
  EXPECT_NEAR(log.values("gnss1.sog")[1], 1852.0 / 3600.0, kExact);
  EXPECT_NEAR(log.values("gnss1.cog")[1], 90.0 * kDeg, kExact);
  EXPECT_NEAR(log.values("heading")[0], 12.5 * kDeg, kExact);
  EXPECT_NEAR(log.values("heading")[1], 14.0 * kDeg, kExact);
  EXPECT_NEAR(log.values("rate_of_turn")[0], -0.5 * kDeg, kExact);  // −30°/min
  EXPECT_TRUE(std::isnan(log.values("rate_of_turn")[1]));
  EXPECT_EQ(log.channel("rate_of_turn").unit, "rad/s");
}

TEST(ReadNmeaGnss, OptionalChannelsOnlyWhenTheirSentencesArePresent) {
  TempDir dir;
  const auto file =
      dir.write("gga.nmea", gga("GP", "000001", "0000000") + "\n" + gga("GP", "000002", "0"));
  const NmeaGnssLog r = read_nmea_gnss(file, "ant");
  EXPECT_EQ(r.date, "");
  EXPECT_EQ(r.log.channel_names(),
            (std::vector<std::string>{"ant.lat", "ant.lon", "ant.height", "ant.quality",
                                      "ant.satellites", "ant.hdop"}));
  EXPECT_EQ(r.log.time(), (std::vector<double>{1.0, 2.0}));
}

TEST(ReadNmeaGnss, MalformedSentencesOfUnusedTypesAreSkipped) {
  TempDir dir;
  // A ZDA with an impossible date and a Seapath PSXN,20 with quality 7: not used, so skipped;
  // a bad checksum is still an error whatever the type.
  const auto file = dir.write(
      "unused.nmea", lines({gga("GP", "120000", "0000000"), framed("GPZDA,120000,30,02,2024,,"),
                            framed("PSXN,20,0,0,7,0")}));
  const NmeaGnssLog r = read_nmea_gnss(file, "g");
  EXPECT_EQ(r.skipped, 2u);
  EXPECT_EQ(r.log.size(), 1u);
  const auto bad = dir.write("bad.nmea", lines({gga("GP", "120000", "0000000"), "$GPGSV,1*00"}));
  EXPECT_THAT(input_error_message([&] { read_nmea_gnss(bad, "g"); }),
              HasSubstr("bad.nmea:2 (checksum)"));
}

TEST(ReadNmeaGnss, NoFixAndUnknownSeparationAreMissingNotErrors) {
  TempDir dir;
  const auto file = dir.write(
      "nofix.nmea", lines({framed("GPGGA,,,,,,0,00,99.99,,,,,,"),  // no time: skipped
                           gga("GP", "120000", "0000000", 0), gga("GP", "120001", "0000000", 1, ""),
                           framed("GPVTG,,,,,,,,,N")}));
  const NmeaGnssLog r = read_nmea_gnss(file, "g");
  EXPECT_EQ(r.skipped, 1u);
  ASSERT_EQ(r.log.size(), 2u);
  EXPECT_TRUE(std::isnan(r.log.values("g.lat")[0]));  // quality 0: no fix
  EXPECT_TRUE(std::isnan(r.log.values("g.height")[0]));
  EXPECT_EQ(r.log.values("g.quality")[0], 0.0);
  EXPECT_FALSE(std::isnan(r.log.values("g.lat")[1]));
  EXPECT_TRUE(std::isnan(r.log.values("g.height")[1]));  // no geoid separation given
  EXPECT_TRUE(std::isnan(r.log.values("g.sog")[1]));     // VTG mode N: not valid
}

TEST(ReadNmeaGnss, OneTalkerPerSentenceType) {
  TempDir dir;
  const auto file = dir.write("talkers.nmea",
                              lines({gga("GN", "120000", "0000000"), gga("GP", "120000", "5000000"),
                                     gga("GL", "120001", "5000000"), gga("GN", "120001", "1000000"),
                                     framed("INHDT,1.0,T"), framed("HEHDT,2.0,T")}));
  const NmeaGnssLog r = read_nmea_gnss(file, "g");
  EXPECT_EQ(r.skipped, 3u);  // GPGGA, GLGGA, HEHDT
  ASSERT_EQ(r.log.size(), 2u);
  EXPECT_NEAR(r.log.values("g.lat")[0], (63 + 26.0 / 60) * kDeg, kExact);
  EXPECT_NEAR(r.log.values("g.lat")[1], (63 + 26.1 / 60) * kDeg, kExact);
  EXPECT_NEAR(r.log.values("heading")[1], 1.0 * kDeg, kExact);
}

TEST(ReadNmeaGnss, MidnightRolloverContinuesTimeAndKeepsTheFirstDate) {
  TempDir dir;
  const std::string rmc_tail = ",A,6326.0,N,01021.0,E,0.0,0.0,";
  const auto file = dir.write(
      "midnight.nmea",
      lines({gga("GN", "235959.50", "0000000"), framed("GNRMC,235959.50" + rmc_tail + "311214,,"),
             gga("GN", "000000.50", "0000000"), framed("GNRMC,000000.50" + rmc_tail + "010115,,"),
             gga("GN", "000001.50", "0000000")}));
  const NmeaGnssLog r = read_nmea_gnss(file, "g");
  EXPECT_EQ(r.date, "2014-12-31");
  EXPECT_EQ(r.log.time(), (std::vector<double>{86399.5, 86400.5, 86401.5}));

  // The first RMC after midnight still dates time 0 to the day before.
  const auto late = dir.write("late_rmc.nmea",
                              lines({gga("GN", "235959", "0000000"), gga("GN", "000000", "0000000"),
                                     framed("GNRMC,000000" + rmc_tail + "010316,,")}));
  const NmeaGnssLog l = read_nmea_gnss(late, "g");
  EXPECT_EQ(l.date, "2016-02-29");
  EXPECT_EQ(l.log.time(), (std::vector<double>{86399.0, 86400.0}));
}

TEST(ReadNmeaGnss, RoundTripThroughTheWriter) {
  // Positions written by nmea_writer and read back: 1e-7 minute rounding is at most 0.093 mm of
  // latitude (1e-9 rad ≈ 6.4 mm, so 2e-11 rad bounds it); height written to 1 mm: ≤ 0.5 mm.
  TempDir dir;
  std::string text;
  std::vector<double> lat, lon, height, times;
  for (int k = 0; k < 50; ++k) {
    NmeaGga g;
    g.utc_s = 43200.0 + 0.2 * k;
    g.lat_rad = (63.44 + 1e-6 * k * k) * kDeg;
    g.lon_rad = (10.35 - 3e-6 * k) * kDeg;
    g.quality = 4;
    g.satellites = core::kMissing;
    g.hdop = core::kMissing;
    g.altitude_m = 1.0 + 0.0123456 * k;
    g.geoid_separation_m = 39.5;
    g.age_s = core::kMissing;
    text += format_gga("GN", g) + "\r\n";
    text += format_hdt("HE", NmeaHdt{(350.0 + 0.5 * k) * kDeg}) + "\r\n";
    lat.push_back(g.lat_rad);
    lon.push_back(g.lon_rad);
    height.push_back(g.altitude_m + g.geoid_separation_m);
    times.push_back(g.utc_s);
  }
  const NmeaGnssLog r = read_nmea_gnss(dir.write("rt.nmea", text), "gnss2");
  ASSERT_EQ(r.log.size(), 50u);
  for (std::size_t k = 0; k < 50; ++k) {
    EXPECT_NEAR(r.log.time()[k], times[k], 5e-4);
    EXPECT_NEAR(r.log.values("gnss2.lat")[k], lat[k], 2e-11);
    EXPECT_NEAR(r.log.values("gnss2.lon")[k], lon[k], 2e-11);
    EXPECT_NEAR(r.log.values("gnss2.height")[k], height[k], 0.5e-3 + 1e-9);
    // Heading written to 0.001° and wrapped to [0°, 360°).
    const double h_deg = std::fmod(350.0 + 0.5 * static_cast<double>(k), 360.0);
    EXPECT_NEAR(r.log.values("heading")[k] / kDeg, h_deg, 0.0005 + 1e-9);
  }
}

// Line ends as the capture reader takes them: a lone CR ends a line, and a UTF-8 byte order
// mark at the start is not part of the first sentence.
TEST(ReadNmeaGnss, LoneCarriageReturnsAndAByteOrderMark) {
  TempDir dir;
  const std::vector<std::string> sentences = {gga("GN", "100000", "0000000"),
                                              gga("GN", "100001", "0000000"), "$GNGGA,1*00"};
  std::string cr = "\xEF\xBB\xBF";
  for (const std::string& s : sentences) cr += s + "\r";
  const auto file = dir.write("cr.nmea", cr.substr(0, cr.rfind('$')));
  const NmeaGnssLog read = read_nmea_gnss(file, "g");
  EXPECT_EQ(read.sentences, 2u);
  ASSERT_EQ(read.log.size(), 2u);
  EXPECT_EQ(read.log.time()[1] - read.log.time()[0], 1.0);
  EXPECT_THAT(input_error_message([&] { read_nmea_gnss(dir.write("bad.nmea", cr), "g"); }),
              HasSubstr("bad.nmea:3 (checksum)"));
}

// Every rejected file names the file, the line and the field, with a hint.
TEST(ReadNmeaGnss, Errors) {
  TempDir dir;
  const auto message = [&](const std::string& name, const std::string& text) {
    const auto file = dir.write(name, text);
    return input_error_message([&] { read_nmea_gnss(file, "g"); });
  };
  EXPECT_THAT(message("empty.nmea", ""), HasSubstr("empty.nmea: the file holds no NMEA sentences"));
  EXPECT_THAT(message("blank.nmea", "\r\n \r\n"), HasSubstr("no NMEA sentences"));
  EXPECT_THAT(message("no_gga.nmea", lines({framed("GNRMC,100000,A,6326.0,N,01021.0,E,0.0,0.0,"
                                                   "270814,,"),
                                            framed("HEHDT,1.0,T")})),
              HasSubstr("no_gga.nmea (GGA): no GGA sentence among the 2 sentences; "));
  EXPECT_THAT(message("untimed.nmea", lines({framed("GPGGA,,,,,,0,,,,,,,,")})),
              HasSubstr("none of the 1 GGA sentences has a UTC time"));
  const std::string good = gga("GN", "100000", "0000000");
  EXPECT_THAT(message("checksum.nmea", lines({good, good.substr(0, good.size() - 2) + "00"})),
              HasSubstr("checksum.nmea:2 (checksum): checksum mismatch"));
  EXPECT_THAT(message("count.nmea", lines({good, framed("GNGGA,100001,6326.0,N")})),
              HasSubstr("count.nmea:2:3 (GGA.field_count)"));
  EXPECT_THAT(message("text.nmea",
                      lines({good, framed("GNGGA,100001,6326.0,N,01021.0,E,4,twelve,0.7,1.0,M,39."
                                          "5,M,,")})),
              HasSubstr("text.nmea:2:7 (GGA.satellites): 'twelve' is not a number; "));
  EXPECT_THAT(message("garbage.nmea", lines({good, "hello"})),
              HasSubstr("garbage.nmea:2:1 (start)"));
  const std::string back = message(
      "back.nmea", lines({good, gga("GN", "100001", "0000000"), gga("GN", "095959", "0000000")}));
  EXPECT_THAT(back, HasSubstr("back.nmea:3:1 (GGA.time): fix time 095959 is 2.000 s before the "
                              "epoch of line 2; "));
  EXPECT_THAT(message("date.nmea",
                      lines({good, framed("GNRMC,100000,A,6326.0,N,01021.0,E,0.0,0.0,270814,,"),
                             gga("GN", "100001", "0"),
                             framed("GNRMC,100001,A,6326.0,N,01021.0,E,0.0,0.0,280814,,")})),
              HasSubstr("date.nmea:4:9 (RMC.date): date 2014-08-28 does not follow"));
  EXPECT_THAT(input_error_message([&] { read_nmea_gnss(dir / "missing.nmea", "g"); }),
              HasSubstr("missing.nmea: cannot open"));
}

TEST(ParseUtcTime, BothFormsAndErrors) {
  EXPECT_EQ(parse_utc_time_of_day("10:00:00"), 36000.0);
  EXPECT_NEAR(parse_utc_time_of_day("23:59:59.125"), 86399.125, kExact);
  EXPECT_EQ(parse_utc_time_of_day("2014-08-27T10:00:00Z"), 36000.0);
  const UtcTimestamp t = parse_utc_timestamp("2016-02-29T00:00:01.5Z");
  ASSERT_TRUE(t.date.has_value());
  EXPECT_EQ(*t.date, (UtcDate{2016, 2, 29}));
  EXPECT_EQ(t.time_of_day_s, 1.5);
  EXPECT_FALSE(parse_utc_timestamp("00:00:00").date.has_value());
  for (const char* bad : {"", "10:00", "24:00:00", "10:60:00", "10:00:00.", "10:00:00Z",
                          "2014-08-27T10:00:00", "2014-08-27 10:00:00Z", "2015-02-29T10:00:00Z",
                          "2014-8-27T10:00:00Z", "10:00:00+01", "x0:00:00"}) {
    EXPECT_THAT(input_error_message([&] { parse_utc_time_of_day(bad); }),
                HasSubstr("(time): '" + std::string(bad) + "' is not a UTC time; write"))
        << bad;
  }
}

}  // namespace
}  // namespace dynpos::io
