#include "dynpos/io/nmea_epoch_assembler.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io_test_util.hpp"

namespace dynpos::io {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using testing::input_error_message;

// Decoded sentences built directly, so these tests do not depend on the sentence parser.
NmeaSentence gga(double utc_s, int quality = 4, const std::string& talker = "GN") {
  NmeaGga g;
  g.utc_s = utc_s;
  g.lat_rad = 1.1;
  g.lon_rad = 0.18;
  g.quality = quality;
  g.satellites = 12;
  g.hdop = 0.7;
  g.altitude_m = 1.0;
  g.geoid_separation_m = 39.5;
  return {talker, "GGA", {"t"}, false, g};
}

NmeaSentence rmc(double utc_s, std::optional<UtcDate> date, double sog_mps = 0.5) {
  NmeaRmc r;
  r.utc_s = utc_s;
  r.valid = true;
  r.sog_mps = sog_mps;
  r.cog_rad = 1.5;
  r.date = date;
  return {"GN", "RMC", {"t"}, false, r};
}

NmeaSentence vtg(double sog_mps, char mode = 'D') {
  NmeaVtg v;
  v.sog_mps = sog_mps;
  v.cog_rad = 0.75;
  v.mode = mode;
  return {"GN", "VTG", {}, false, v};
}

NmeaSentence hdt(double heading_rad) { return {"HE", "HDT", {}, false, NmeaHdt{heading_rad}}; }

TEST(NmeaEpochAssembler, TimedSentencesOpenEpochsAndUntimedOnesJoinTheLast) {
  NmeaEpochAssembler a("f.nmea");
  EXPECT_FALSE(a.add(hdt(0.1), 1));  // before the first epoch
  EXPECT_TRUE(a.add(gga(36000.0), 2));
  EXPECT_TRUE(a.add(rmc(36000.0, UtcDate{2014, 8, 27}), 3));  // same time: same epoch
  EXPECT_TRUE(a.add(hdt(0.2), 4));
  EXPECT_FALSE(a.add(hdt(0.3), 5));               // a second HDT in the epoch
  EXPECT_FALSE(a.add(gga(36000.0), 6));           // a second GGA at the same time
  EXPECT_FALSE(a.add(gga(36001.0, 4, "GP"), 7));  // another talker of GGA
  EXPECT_FALSE(a.add({"GP", "GSV", {}, false, NmeaOther{}}, 8));
  EXPECT_TRUE(a.add(gga(36001.0), 9));
  ASSERT_EQ(a.epochs().size(), 2u);
  EXPECT_EQ(a.epochs()[0].t_s, 36000.0);
  EXPECT_EQ(a.epochs()[0].heading, 0.2);
  EXPECT_DOUBLE_EQ(a.epochs()[0].height, 40.5);
  EXPECT_TRUE(std::isnan(a.epochs()[1].heading));
  EXPECT_EQ(a.gga_seen(), 4u);
  EXPECT_EQ(a.gga_used(), 2u);
  ASSERT_TRUE(a.date());
  EXPECT_EQ(*a.date(), (UtcDate{2014, 8, 27}));
}

TEST(NmeaEpochAssembler, NoFixLeavesThePositionMissing) {
  NmeaEpochAssembler a("f.nmea");
  EXPECT_TRUE(a.add(gga(10.0, 0), 1));
  EXPECT_FALSE(a.add(gga(std::nan(""), 4), 2));  // no time: skipped, but seen
  EXPECT_TRUE(std::isnan(a.epochs()[0].lat));
  EXPECT_EQ(a.epochs()[0].quality, 0.0);
  EXPECT_EQ(a.gga_seen(), 2u);
  EXPECT_EQ(a.gga_used(), 1u);
}

TEST(NmeaEpochAssembler, MidnightRolloverContinuesTimeAndDatesTheFirstDay) {
  NmeaEpochAssembler a("f.nmea");
  EXPECT_TRUE(a.add(gga(86399.0), 1));
  EXPECT_TRUE(a.add(gga(0.5), 2));
  EXPECT_TRUE(a.add(rmc(0.5, UtcDate{2014, 8, 28}), 3));  // the date after midnight
  ASSERT_EQ(a.epochs().size(), 2u);
  EXPECT_EQ(a.epochs()[1].t_s, 86400.5);
  EXPECT_EQ(*a.date(), (UtcDate{2014, 8, 27}));
}

TEST(NmeaEpochAssembler, TimeBackwardsAndContradictingDatesAreErrors) {
  NmeaEpochAssembler a("f.nmea");
  a.add(gga(100.0), 4);
  EXPECT_THAT(
      input_error_message([&] { a.add(gga(90.0), 7); }),
      HasSubstr("f.nmea:7:1 (GGA.time): fix time t is 10.000 s before the epoch of line 4"));
  NmeaEpochAssembler b("g.nmea");
  b.add(rmc(100.0, UtcDate{2014, 8, 27}), 1);
  EXPECT_THAT(input_error_message([&] {
                b.add(rmc(101.0, UtcDate{2014, 8, 29}), 2);
              }),
              HasSubstr("g.nmea:2:9 (RMC.date): date 2014-08-29 does not follow from the date "
                        "of line 1 and the 0 midnight rollover(s) between"));
}

TEST(NmeaEpochsToLog, SpeedFromVtgElseRmcAndOptionalChannels) {
  NmeaEpochAssembler a("f.nmea");
  a.add(gga(1.0), 1);
  a.add(rmc(1.0, std::nullopt, 0.5), 2);
  a.add(vtg(2.0), 3);
  a.add(gga(2.0), 4);
  a.add(rmc(2.0, std::nullopt, 0.5), 5);
  a.add(gga(3.0), 6);
  a.add(vtg(9.0, 'N'), 7);  // mode N: not valid, so missing
  const core::Log log = nmea_epochs_to_log(a.epochs(), "gnss1");
  EXPECT_THAT(log.time(), ElementsAre(1.0, 2.0, 3.0));
  const auto& sog = log.values("gnss1.sog");
  EXPECT_EQ(sog[0], 2.0);
  EXPECT_EQ(sog[1], 0.5);
  EXPECT_TRUE(std::isnan(sog[2]));
  EXPECT_TRUE(log.has("gnss1.lat") && log.has("gnss1.hdop"));
  EXPECT_FALSE(log.has("heading"));
  EXPECT_FALSE(log.has("rate_of_turn"));
  EXPECT_FALSE(nmea_epochs_to_log({NmeaEpoch{}}, "gnss1").has("gnss1.sog"));
}

}  // namespace
}  // namespace dynpos::io
