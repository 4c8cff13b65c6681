// The stream time read from the lines: CSV time columns, NMEA sentence UTC, logger stamps.

#include "dynpos/live/stream_clock.hpp"

#include <gtest/gtest.h>

namespace dynpos::live {
namespace {

TEST(StreamClock, ACsvTimeColumnWithAUnit) {
  StreamClock clock("time");
  EXPECT_FALSE(clock.read("# a comment\n"));
  EXPECT_FALSE(clock.read("cmd [1],time [s],y\n"));
  EXPECT_EQ(clock.read("1,12.5,3\n"), 12.5);
  EXPECT_FALSE(clock.read("1,,3\n"));
}

TEST(StreamClock, SemicolonsAndIsoStamps) {
  StreamClock clock("t");
  EXPECT_FALSE(clock.read("t;x\n"));
  EXPECT_DOUBLE_EQ(*clock.read("1970-01-01T00:01:40.5Z;1\n"), 100.5);
}

TEST(StreamClock, NmeaSentenceUtcAcrossMidnight) {
  StreamClock clock("time");
  EXPECT_DOUBLE_EQ(*clock.read("$GPGGA,235959.50,6325.0,N,01023.0,E,1,8,1.0,0,M,0,M,,*00\r\n"),
                   86399.5);
  EXPECT_FALSE(clock.read("$HEHDT,12.0,T*00\r\n"));  // untimed
  EXPECT_DOUBLE_EQ(*clock.read("$GPRMC,000000.50,A,6325.0,N,01023.0,E,0,0,010524,,*00\r\n"),
                   86400.5);
  EXPECT_DOUBLE_EQ(*clock.read("$GPGLL,6325.0,N,01023.0,E,000001.00,A*00\r\n"), 86401.0);
}

TEST(StreamClock, ALoggerStampBeforeTheSentence) {
  StreamClock clock("time");
  EXPECT_DOUBLE_EQ(*clock.read("1714557600.25 $HEHDT,12.0,T*00\r\n"), 1714557600.25);
  EXPECT_DOUBLE_EQ(*clock.read("2024-05-01 10:00:00.5 $HEHDT,12.0,T*00\r\n"), 1714557600.5);
}

TEST(StreamClock, TimesOfDay) {
  EXPECT_EQ(nmea_time_of_day("123456"), 12 * 3600 + 34 * 60 + 56);
  EXPECT_EQ(nmea_time_of_day("000000.25"), 0.25);
  EXPECT_FALSE(nmea_time_of_day("12345"));
  EXPECT_FALSE(nmea_time_of_day("12a456"));
  EXPECT_FALSE(nmea_time_of_day("123456x5"));
}

}  // namespace
}  // namespace dynpos::live
