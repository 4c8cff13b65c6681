#include "dynpos/io/nmea_writer.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "dynpos/core/log.hpp"

namespace dynpos::io {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kEarthRadius_m = 6.371e6;  // metres per radian of latitude, near enough

// The checksum computed here, independently of the library.
std::string framed(const std::string& body) {
  unsigned sum = 0;
  for (const char c : body) sum ^= static_cast<unsigned char>(c);
  const char* hex = "0123456789ABCDEF";
  return "$" + body + "*" + hex[sum >> 4] + hex[sum & 15];
}

NmeaGga example_gga() {
  NmeaGga g;
  g.utc_s = 10 * 3600 + 0 * 60 + 1.25;
  g.lat_rad = (63 + 26.4 / 60) * kDeg;
  g.lon_rad = (10 + 21.0 / 60) * kDeg;
  g.quality = 4;
  g.satellites = 9;
  g.hdop = 0.8;
  g.altitude_m = -35.25;
  g.geoid_separation_m = 39.5;
  g.age_s = core::kMissing;
  g.station = "";
  return g;
}

TEST(NmeaWriter, GgaExactText) {
  EXPECT_EQ(format_gga("GN", example_gga()),
            framed("GNGGA,100001.250,6326.4000000,N,01021.0000000,E,4,09,0.80,-35.250,M,39.500,"
                   "M,,"));
}

TEST(NmeaWriter, MissingValuesWriteEmptyFields) {
  NmeaGga g;
  g.utc_s = 0.0;
  g.lat_rad = g.lon_rad = g.satellites = g.hdop = core::kMissing;
  g.altitude_m = g.geoid_separation_m = g.age_s = core::kMissing;
  g.quality = 0;
  EXPECT_EQ(format_gga("GP", g), framed("GPGGA,000000.000,,,,,0,,,,,,,,"));
  g.quality = -1;
  EXPECT_EQ(format_gga("GP", g), framed("GPGGA,000000.000,,,,,,,,,,,,,"));
  NmeaVtg v;
  v.cog_rad = v.cog_magnetic_rad = v.sog_mps = core::kMissing;
  EXPECT_EQ(format_vtg("GN", v), framed("GNVTG,,,,,,,,,"));
  EXPECT_EQ(format_hdt("HE", NmeaHdt{core::kMissing}), framed("HEHDT,,"));
}

TEST(NmeaWriter, RmcVtgHdtRotExactText) {
  NmeaRmc r;
  r.utc_s = 86399.9996;  // rounds to the next midnight, written modulo one day
  r.valid = true;
  r.lat_rad = -(12 + 0.5 / 60) * kDeg;
  r.lon_rad = -(179 + 59.25 / 60) * kDeg;
  r.sog_mps = 1852.0 / 3600.0;  // 1 knot
  r.cog_rad = -0.01 * kDeg;     // wraps to 359.99°
  r.date = UtcDate{2014, 8, 28};
  r.magnetic_variation_rad = -3.1 * kDeg;
  r.mode = 'D';
  EXPECT_EQ(format_rmc("GN", r),
            framed("GNRMC,000000.000,A,1200.5000000,S,17959.2500000,W,1.000,359.99,280814,3.1,W,"
                   "D"));
  NmeaVtg v;
  v.cog_rad = 359.9999 * kDeg;  // rounds to 360.00 → 0.00
  v.cog_magnetic_rad = core::kMissing;
  v.sog_mps = 2.0;
  v.mode = 'A';
  EXPECT_EQ(format_vtg("GN", v), framed("GNVTG,0.00,T,,,3.888,N,7.200,K,A"));
  EXPECT_EQ(format_hdt("HE", NmeaHdt{274.0704 * kDeg}), framed("HEHDT,274.070,T"));
  EXPECT_EQ(format_rot("TI", NmeaRot{-12.5 * kDeg / 60.0, true}), framed("TIROT,-12.50,A"));
}

TEST(NmeaWriter, MinutesRoundingNeverCarriesTo60) {
  NmeaGga g = example_gga();
  g.lat_rad = (63.0 - 1e-12) * kDeg;  // 62° 59.99999999…' rounds up to 63° 00'
  EXPECT_THAT(format_gga("GN", g), ::testing::HasSubstr(",6300.0000000,N,"));
}

TEST(NmeaWriter, PositionRoundTripsBelowATenthOfAMillimetre) {
  // 1e-7 minute of arc is 0.185 mm, so rounding leaves at most 0.093 mm; height is written to
  // 1 mm, rounding at most 0.5 mm (plus the double sum altitude + separation, ~1e-14 m).
  double worst_h_m = 0.0, worst_v_m = 0.0;
  for (int k = 0; k < 200; ++k) {
    NmeaGga g = example_gga();
    g.lat_rad = (-89.9 + 0.8987 * k) * kDeg + 1e-9 * k;
    g.lon_rad = (-179.9 + 1.7991 * k) * kDeg - 3e-9 * k;
    g.altitude_m = -50.0 + 0.7777777 * k;
    const NmeaSentence s = parse_nmea_sentence(format_gga("GN", g));
    const auto back = std::get<NmeaGga>(s.data);
    const double north_m = (back.lat_rad - g.lat_rad) * kEarthRadius_m;
    const double east_m = (back.lon_rad - g.lon_rad) * kEarthRadius_m * std::cos(g.lat_rad);
    worst_h_m = std::max({worst_h_m, std::abs(north_m), std::abs(east_m)});
    worst_v_m = std::max(worst_v_m, std::abs(back.altitude_m - g.altitude_m));
    EXPECT_NEAR(back.utc_s, g.utc_s, 5e-4);  // written to the millisecond
  }
  EXPECT_LT(worst_h_m, 0.1e-3);
  EXPECT_LE(worst_v_m, 0.5e-3 + 1e-12);
}

TEST(NmeaWriter, RejectsBadTalkerAndOutOfRangeValues) {
  EXPECT_THROW(format_hdt("H", NmeaHdt{0.0}), std::invalid_argument);
  EXPECT_THROW(format_hdt("he", NmeaHdt{0.0}), std::invalid_argument);
  NmeaGga g = example_gga();
  g.lat_rad = 90.5 * kDeg;
  EXPECT_THROW(format_gga("GN", g), std::invalid_argument);
  g = example_gga();
  g.utc_s = -1.0;
  EXPECT_THROW(format_gga("GN", g), std::invalid_argument);
  g = example_gga();
  g.quality = 10;
  EXPECT_THROW(format_gga("GN", g), std::invalid_argument);
}

TEST(NmeaWriter, FrameAppendsChecksum) {
  EXPECT_EQ(nmea_frame("GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,"),
            "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47");
}

}  // namespace
}  // namespace dynpos::io
