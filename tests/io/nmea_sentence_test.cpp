#include "dynpos/io/nmea_sentence.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <ostream>
#include <string>

#include "io_test_util.hpp"

namespace dynpos::io {
namespace {

using ::testing::HasSubstr;
using testing::input_error_message;

constexpr double kDeg = std::numbers::pi / 180.0;

// The checksum computed here, independently of the library: XOR of the bytes between '$' and
// '*', as two upper-case hex digits.
std::string framed(const std::string& body) {
  unsigned sum = 0;
  for (const char c : body) sum ^= static_cast<unsigned char>(c);
  const char* hex = "0123456789ABCDEF";
  return "$" + body + "*" + hex[sum >> 4] + hex[sum & 15];
}

// The record of one sentence, by value.
template <class T>
T parsed(const std::string& line) {
  return std::get<T>(parse_nmea_sentence(line).data);
}

// Exact to the last digit: the parser's arithmetic on a few decimal digits is exact to well
// below 1e-12 of the value.
constexpr double kExact = 1e-12;

TEST(NmeaChecksum, MatchesPublishedExamples) {
  // Sentences quoted with their checksums in receiver manuals.
  EXPECT_EQ(nmea_checksum("GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,"), 0x47);
  EXPECT_EQ(nmea_checksum("GPRMC,123519,A,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W"),
            0x6A);
  EXPECT_EQ(nmea_checksum(""), 0);
}

TEST(NmeaSentence, GgaDecodedInSi) {
  const NmeaSentence s =
      parse_nmea_sentence("$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47\r\n");
  EXPECT_EQ(s.talker, "GP");
  EXPECT_EQ(s.type, "GGA");
  EXPECT_TRUE(s.has_checksum);
  ASSERT_EQ(s.fields.size(), 14u);
  const auto g = std::get<NmeaGga>(s.data);
  EXPECT_NEAR(g.utc_s, 12 * 3600 + 35 * 60 + 19, kExact);
  EXPECT_NEAR(g.lat_rad, (48 + 7.038 / 60) * kDeg, kExact);
  EXPECT_NEAR(g.lon_rad, (11 + 31.0 / 60) * kDeg, kExact);
  EXPECT_EQ(g.quality, 1);
  EXPECT_EQ(g.satellites, 8);
  EXPECT_NEAR(g.hdop, 0.9, kExact);
  EXPECT_NEAR(g.altitude_m, 545.4, kExact);
  EXPECT_NEAR(g.geoid_separation_m, 46.9, kExact);
  EXPECT_TRUE(std::isnan(g.age_s));
  EXPECT_EQ(g.station, "");
}

TEST(NmeaSentence, SouthWestAndFractionalSecondsAndRtk) {
  const NmeaSentence s = parse_nmea_sentence(
      framed("GNGGA,235959.75,6326.4000000,S,01021.0000000,W,4,21,0.55,1.234,M,39.500,M,1.0,0042"));
  const auto g = std::get<NmeaGga>(s.data);
  EXPECT_NEAR(g.utc_s, 86399.75, kExact);
  EXPECT_NEAR(g.lat_rad, -(63 + 26.4 / 60) * kDeg, kExact);
  EXPECT_NEAR(g.lon_rad, -(10 + 21.0 / 60) * kDeg, kExact);
  EXPECT_EQ(g.quality, 4);
  EXPECT_NEAR(g.age_s, 1.0, kExact);
  EXPECT_EQ(g.station, "0042");
}

TEST(NmeaSentence, EmptyFieldsAreMissingNotZero) {
  const NmeaSentence s = parse_nmea_sentence(framed("GPGGA,,,,,,0,,,,,,,,"));
  const auto g = std::get<NmeaGga>(s.data);
  EXPECT_TRUE(std::isnan(g.utc_s));
  EXPECT_TRUE(std::isnan(g.lat_rad));
  EXPECT_TRUE(std::isnan(g.lon_rad));
  EXPECT_EQ(g.quality, 0);
  EXPECT_TRUE(std::isnan(g.satellites));
  EXPECT_TRUE(std::isnan(g.altitude_m));
  EXPECT_TRUE(std::isnan(g.geoid_separation_m));
  const auto q = parsed<NmeaGga>(framed("GPGGA,,,,,,,,,,,,,,"));
  EXPECT_EQ(q.quality, -1);
}

TEST(NmeaSentence, RmcWithDateSpeedCourseVariation) {
  const NmeaSentence s =
      parse_nmea_sentence("$GPRMC,123519,A,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W*6A");
  const auto r = std::get<NmeaRmc>(s.data);
  EXPECT_TRUE(r.valid);
  EXPECT_NEAR(r.sog_mps, 22.4 * 1852.0 / 3600.0, kExact);
  EXPECT_NEAR(r.cog_rad, 84.4 * kDeg, kExact);
  ASSERT_TRUE(r.date.has_value());
  EXPECT_EQ(*r.date, (UtcDate{1994, 3, 23}));
  EXPECT_NEAR(r.magnetic_variation_rad, -3.1 * kDeg, kExact);
  EXPECT_EQ(r.mode, '\0');
  // NMEA 2.3 (mode) and 4.1 (mode, navigational status) forms; year < 80 is 20yy.
  const auto r23 = parsed<NmeaRmc>(framed("GNRMC,100000.00,V,,,,,,,270814,,,N"));
  EXPECT_FALSE(r23.valid);
  EXPECT_EQ(r23.mode, 'N');
  EXPECT_EQ(*r23.date, (UtcDate{2014, 8, 27}));
  EXPECT_TRUE(std::isnan(r23.sog_mps));
  const auto r41 =
      parsed<NmeaRmc>(framed("GNRMC,100000.00,A,6326.4,N,01021.0,E,0.1,,270814,,,D,V"));
  EXPECT_EQ(r41.mode, 'D');
  EXPECT_TRUE(std::isnan(r41.cog_rad));
}

TEST(NmeaSentence, VtgPrefersKmhAndReadsMode) {
  const auto v = parsed<NmeaVtg>("$GPVTG,054.7,T,034.4,M,005.5,N,010.2,K*48");
  EXPECT_NEAR(v.cog_rad, 54.7 * kDeg, kExact);
  EXPECT_NEAR(v.cog_magnetic_rad, 34.4 * kDeg, kExact);
  EXPECT_NEAR(v.sog_mps, 10.2 / 3.6, kExact);
  const auto knots_only = parsed<NmeaVtg>(framed("GNVTG,,T,,M,2.000,N,,K,A"));
  EXPECT_NEAR(knots_only.sog_mps, 2.0 * 1852.0 / 3600.0, kExact);
  EXPECT_TRUE(std::isnan(knots_only.cog_rad));
  EXPECT_EQ(knots_only.mode, 'A');
}

TEST(NmeaSentence, HeadingAndRateOfTurnWithoutTime) {
  const auto h = parsed<NmeaHdt>(framed("HEHDT,274.07,T"));
  EXPECT_NEAR(h.heading_rad, 274.07 * kDeg, kExact);
  const auto r = parsed<NmeaRot>(framed("HEROT,-12.5,A"));
  EXPECT_NEAR(r.rate_rad_s, -12.5 * kDeg / 60.0, kExact);  // deg/min → rad/s
  EXPECT_TRUE(r.valid);
  EXPECT_FALSE(parsed<NmeaRot>(framed("TIROT,3.0,V")).valid);
}

TEST(NmeaSentence, AnyTalkerProprietaryAndUnknownTypes) {
  for (const char* talker : {"GP", "GN", "GL", "GA", "GB", "IN", "HE", "II"}) {
    const NmeaSentence s = parse_nmea_sentence(framed(std::string(talker) + "HDT,1.0,T"));
    EXPECT_EQ(s.talker, talker);
    EXPECT_TRUE(std::holds_alternative<NmeaHdt>(s.data));
  }
  const NmeaSentence gsv = parse_nmea_sentence(framed("GPGSV,3,1,11,03,03,111,00,04,15,270,00"));
  EXPECT_EQ(gsv.type, "GSV");
  EXPECT_TRUE(std::holds_alternative<NmeaOther>(gsv.data));
  EXPECT_EQ(gsv.fields.size(), 11u);
  const NmeaSentence p = parse_nmea_sentence(framed("PGRME,15.0,M,45.0,M,25.0,M"));
  EXPECT_EQ(p.talker, "P");
  EXPECT_EQ(p.type, "GRME");
  EXPECT_TRUE(std::holds_alternative<NmeaOther>(p.data));
}

TEST(NmeaSentence, ChecksumIsOptionalAndCaseInsensitive) {
  const NmeaSentence s = parse_nmea_sentence("$HEHDT,10.0,T");
  EXPECT_FALSE(s.has_checksum);
  EXPECT_NEAR(std::get<NmeaHdt>(s.data).heading_rad, 10.0 * kDeg, kExact);
  EXPECT_TRUE(parse_nmea_sentence("$GPRMC,123519,A,4807.038,N,01131.000,E,022.4,084.4,230394,"
                                  "003.1,W*6a")
                  .has_checksum);
}

// Every rejected input names the file, line, field number and field, and gives a hint.
struct BadCase {
  std::string line;
  std::string where;    // expected "file:line[:column] (name)"
  std::string problem;  // expected part of the problem text
};

// Printed by GoogleTest when a case fails.
void PrintTo(const BadCase& c, std::ostream* os) { *os << c.line; }

class NmeaSentenceErrors : public ::testing::TestWithParam<BadCase> {};

TEST_P(NmeaSentenceErrors, NameFileLineFieldAndHint) {
  const BadCase& c = GetParam();
  const std::string message = input_error_message([&] {
    parse_nmea_sentence(c.line, core::InputLocation{"gps.nmea", 7, {}, {}});
  });
  EXPECT_THAT(message, HasSubstr(c.where)) << message;
  EXPECT_THAT(message, HasSubstr(c.problem)) << message;
  EXPECT_THAT(message, HasSubstr("; ")) << "no hint: " << message;
}

const std::string kGga = "GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,";

INSTANTIATE_TEST_SUITE_P(
    AllCases, NmeaSentenceErrors,
    ::testing::Values(
        BadCase{"$" + kGga + "*48", "gps.nmea:7 (checksum)", "says 48, its text gives 47"},
        BadCase{"$" + kGga + "*4", "gps.nmea:7 (checksum)", "not two hex digits"},
        BadCase{"$" + kGga + "*G7", "gps.nmea:7 (checksum)", "not two hex digits"},
        BadCase{"12:00:01 $" + kGga, "gps.nmea:7:1 (start)", "does not start with '$'"},
        BadCase{"", "gps.nmea:7:1 (start)", "does not start with '$'"},
        BadCase{framed("GPGG,1"), "gps.nmea:7:1 (address)", "'GPGG' is not an NMEA address"},
        BadCase{framed("gpgga,1"), "gps.nmea:7:1 (address)", "not an NMEA address"},
        BadCase{framed("GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,"),
                "gps.nmea:7:13 (GGA.field_count)", "GGA has 13 fields"},
        BadCase{framed(kGga + ",extra"), "gps.nmea:7:15 (GGA.field_count)", "GGA has 15"},
        BadCase{framed("GPGGA,123519,4807.038,N,01131.000,E,1,O8,0.9,545.4,M,46.9,M,,"),
                "gps.nmea:7:7 (GGA.satellites)", "'O8' is not a number"},
        BadCase{framed("GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,5 45.4,M,46.9,M,,"),
                "gps.nmea:7:9 (GGA.altitude)", "not a number"},
        BadCase{framed("GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,F,46.9,M,,"),
                "gps.nmea:7:10 (GGA.altitude_unit)", "'F' is not one of the letters M"},
        BadCase{framed("GPGGA,123519,4807.038,X,01131.000,E,1,08,0.9,545.4,M,46.9,M,,"),
                "gps.nmea:7:3 (GGA.latitude_hemisphere)", "not one of the letters NS"},
        BadCase{framed("GPGGA,123519,4807.038,,01131.000,E,1,08,0.9,545.4,M,46.9,M,,"),
                "gps.nmea:7:3 (GGA.latitude_hemisphere)", "hemisphere letter is missing"},
        BadCase{framed("GPGGA,123519,4860.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,"),
                "gps.nmea:7:2 (GGA.latitude)", "minutes"},
        BadCase{framed("GPGGA,123519,9107.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,"),
                "gps.nmea:7:2 (GGA.latitude)", "beyond 90 degrees"},
        BadCase{framed("GPGGA,123519,48.07038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,"),
                "gps.nmea:7:2 (GGA.latitude)", "is not ddmm.mmmm"},
        BadCase{framed("GPGGA,126019,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,"),
                "gps.nmea:7:1 (GGA.time)", "not a UTC time"},
        BadCase{framed("GPGGA,1235,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,"),
                "gps.nmea:7:1 (GGA.time)", "not a UTC time"},
        BadCase{framed("GPGGA,123519,4807.038,N,01131.000,E,A,08,0.9,545.4,M,46.9,M,,"),
                "gps.nmea:7:6 (GGA.quality)", "not a number"},
        BadCase{framed("GPGGA,123519,4807.038,N,01131.000,E,12,08,0.9,545.4,M,46.9,M,,"),
                "gps.nmea:7:6 (GGA.quality)", "not a digit 0-9"},
        BadCase{framed("GPRMC,123519,A,4807.038,N,01131.000,E,022.4,084.4,310294,003.1,W"),
                "gps.nmea:7:9 (RMC.date)", "'310294' is not a date"},
        BadCase{framed("GPRMC,123519,X,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W"),
                "gps.nmea:7:2 (RMC.status)", "not one of the letters AV"},
        BadCase{framed("GPRMC,123519,A,4807.038,N,01131.000,E,022.4,084.4,230394"),
                "gps.nmea:7:9 (RMC.field_count)", "RMC has 9 fields"},
        BadCase{framed("GPVTG,054.7,T,034.4,M,005.5,N,010.2,X"), "gps.nmea:7:8 (VTG.sog_kmh_unit)",
                "not one of the letters K"},
        BadCase{framed("HEHDT,27x.1,T"), "gps.nmea:7:1 (HDT.heading)", "'27x.1' is not a number"},
        BadCase{framed("HEHDT,274.1"), "gps.nmea:7:1 (HDT.field_count)", "HDT has 1 fields"},
        BadCase{framed("HEHDT,274.1,M"), "gps.nmea:7:2 (HDT.heading_reference)", "letters T"},
        // A heading is in [0, 360) degrees.
        BadCase{framed("HEHDT,400.0,T"), "gps.nmea:7:1 (HDT.heading)",
                "'400.0' is not in [0, 360)"},
        BadCase{framed("HEHDT,360.0,T"), "gps.nmea:7:1 (HDT.heading)", "not in [0, 360)"},
        BadCase{framed("HEHDT,-0.5,T"), "gps.nmea:7:1 (HDT.heading)", "not in [0, 360)"},
        BadCase{framed("INTHS,512.3,A"), "gps.nmea:7:1 (THS.heading)", "not in [0, 360)"},
        BadCase{framed("HCHDG,361.0,,,,"), "gps.nmea:7:1 (HDG.heading)", "not in [0, 360)"},
        BadCase{framed("PSXN,23,0.1,0.2,370.0,0.3"), "(PSXN,23.heading)", "not in [0, 360)"},
        BadCase{framed("HEROT,1.-5,A"), "gps.nmea:7:1 (ROT.rate)", "not a number"},
        BadCase{framed("HEROT,1.5,Q"), "gps.nmea:7:2 (ROT.status)", "letters AV"}),
    [](const ::testing::TestParamInfo<BadCase>& info) {
      return "case" + std::to_string(info.index);
    });

TEST(NmeaSentence, GllPositionTimeAndStatus) {
  const auto g = parsed<NmeaGll>(framed("GPGLL,4916.45,N,12311.12,W,225444.50,A,A"));
  EXPECT_NEAR(g.lat_rad, (49.0 + 16.45 / 60.0) * kDeg, kExact);
  EXPECT_NEAR(g.lon_rad, -(123.0 + 11.12 / 60.0) * kDeg, kExact);
  EXPECT_NEAR(g.utc_s, 22 * 3600.0 + 54 * 60.0 + 44.5, kExact);
  EXPECT_TRUE(g.valid);
  EXPECT_FALSE(parsed<NmeaGll>(framed("GPGLL,4916.45,N,12311.12,W,225444,V")).valid);
}

TEST(NmeaSentence, ZdaTimeAndFourDigitDate) {
  const auto z = parsed<NmeaZda>(framed("GPZDA,235959.50,31,12,2023,00,00"));
  EXPECT_NEAR(z.utc_s, 86399.5, kExact);
  ASSERT_TRUE(z.date);
  EXPECT_EQ(*z.date, (UtcDate{2023, 12, 31}));
  EXPECT_FALSE(parsed<NmeaZda>(framed("GPZDA,120000,,,,,")).date);  // no date yet: absent
  const std::string message = input_error_message([] {
    parse_nmea_sentence(framed("GPZDA,120000,30,02,2024,,"), {"z.nmea", 4, {}, {}});
  });
  EXPECT_THAT(message, HasSubstr("z.nmea:4:2 (ZDA.date): '30,02,2024' is not a date"));
  // Years outside 1970-2199, whose instants may be 2^63 ns or more apart, and a year beyond int
  // (fuzz findings: the cast, the origin's nanoseconds and a difference overflowed), are not
  // dates.
  for (const char* year : {"1969", "2200", "739336282847", "99999999999999999999"}) {
    const std::string sentence = framed(std::string("GPZDA,120000,01,05,") + year + ",,");
    EXPECT_THAT(input_error_message([&] {
                  parse_nmea_sentence(sentence, {"z.nmea", 1, {}, {}});
                }),
                HasSubstr("a four-digit year 1970-2199"))
        << year;
  }
}

TEST(NmeaSentence, ThsAndHdgHeadings) {
  const auto t = parsed<NmeaThs>(framed("INTHS,123.45,A"));
  EXPECT_NEAR(t.heading_rad, 123.45 * kDeg, kExact);
  EXPECT_EQ(t.mode, 'A');
  EXPECT_EQ(parsed<NmeaThs>(framed("INTHS,,V")).mode, 'V');
  // Deviation east +, variation west −.
  const auto h = parsed<NmeaHdg>(framed("HCHDG,98.3,1.5,E,2.0,W"));
  EXPECT_NEAR(h.sensor_heading_rad, 98.3 * kDeg, kExact);
  EXPECT_NEAR(h.deviation_rad, 1.5 * kDeg, kExact);
  EXPECT_NEAR(h.variation_rad, -2.0 * kDeg, kExact);
  EXPECT_TRUE(std::isnan(parsed<NmeaHdg>(framed("HCHDG,98.3,,,,")).variation_rad));
}

TEST(NmeaSentence, SeapathProprietaryAttitudeQualityGyro) {
  const auto a = parsed<NmeaPsxnAttitude>(framed("PSXN,23,1.28,-1.93,104.68,-0.24"));
  EXPECT_NEAR(a.roll_rad, 1.28 * kDeg, kExact);
  EXPECT_NEAR(a.pitch_rad, -1.93 * kDeg, kExact);
  EXPECT_NEAR(a.heading_rad, 104.68 * kDeg, kExact);
  EXPECT_NEAR(a.heave_m, -0.24, kExact);
  const auto q = parsed<NmeaPsxnQuality>(framed("PSXN,20,0,1,2,"));
  EXPECT_EQ(q.horizontal, 0);
  EXPECT_EQ(q.height, 1);
  EXPECT_EQ(q.heading, 2);
  EXPECT_EQ(q.roll_pitch, -1);
  const auto g = parsed<NmeaPsxnGyro>(framed("PSXN,22,0.12,-0.01"));
  EXPECT_NEAR(g.offset_rad, -0.01 * kDeg, kExact);
  EXPECT_TRUE(std::holds_alternative<NmeaOther>(parse_nmea_sentence(framed("PSXN,21,1")).data));
  EXPECT_TRUE(std::holds_alternative<NmeaOther>(parse_nmea_sentence(framed("PSXX,23,1")).data));
  const std::string message =
      input_error_message([] { parse_nmea_sentence(framed("PSXN,20,0,0,3,0")); });
  EXPECT_THAT(message, HasSubstr("(PSXN,20.heading): quality '3' is not 0, 1 or 2"));
}

TEST(NmeaSentence, LenientFieldCountPadsAndCuts) {
  const NmeaParseOptions lenient{.lenient_field_count = true};
  // Without the trailing age and station fields (12 instead of 14), and with an extra field.
  const std::string short_gga = framed("GPGGA,120000,6000.0,N,01000.0,E,1,08,0.9,10.0,M,40.0,M");
  EXPECT_THROW(parse_nmea_sentence(short_gga), core::InputError);
  const auto g = std::get<NmeaGga>(parse_nmea_sentence(short_gga, {}, lenient).data);
  EXPECT_NEAR(g.altitude_m + g.geoid_separation_m, 50.0, kExact);
  EXPECT_TRUE(std::isnan(g.age_s));
  const std::string long_hdt = framed("HEHDT,12.5,T,extra");
  EXPECT_NEAR(std::get<NmeaHdt>(parse_nmea_sentence(long_hdt, {}, lenient).data).heading_rad,
              12.5 * kDeg, kExact);
  // Fewer than the fields the record needs: still an error.
  EXPECT_THROW(parse_nmea_sentence(framed("GPGGA,120000,6000.0,N"), {}, lenient), core::InputError);
}

TEST(UtcDate, CalendarArithmetic) {
  EXPECT_EQ(days_since_epoch({1970, 1, 1}), 0);
  EXPECT_EQ(days_since_epoch({2000, 3, 1}), 11017);  // 30 years incl. 7 leap days + Jan, Feb
  EXPECT_EQ(add_days({2014, 8, 27}, 1), (UtcDate{2014, 8, 28}));
  EXPECT_EQ(add_days({2014, 12, 31}, 1), (UtcDate{2015, 1, 1}));
  EXPECT_EQ(add_days({2016, 2, 28}, 1), (UtcDate{2016, 2, 29}));
  EXPECT_EQ(add_days({2100, 2, 28}, 1), (UtcDate{2100, 3, 1}));
  EXPECT_EQ(add_days({2000, 3, 1}, -1), (UtcDate{2000, 2, 29}));
  for (long d = -800; d <= 800; d += 37) {
    EXPECT_EQ(days_since_epoch(add_days({2014, 8, 27}, d)) - days_since_epoch({2014, 8, 27}), d);
  }
  EXPECT_TRUE(is_valid({2000, 2, 29}));
  EXPECT_FALSE(is_valid({1900, 2, 29}));
  EXPECT_FALSE(is_valid({2014, 4, 31}));
  EXPECT_FALSE(is_valid({2014, 13, 1}));
  EXPECT_EQ(to_iso({2014, 8, 7}), "2014-08-07");
}

}  // namespace
}  // namespace dynpos::io
