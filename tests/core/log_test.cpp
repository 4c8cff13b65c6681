#include "dynpos/core/log.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace dynpos::core {
namespace {

using ::testing::HasSubstr;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// Expects `statement` to throw `Exception` whose what() contains `text`.
#define EXPECT_THROW_WITH(statement, Exception, text)          \
  EXPECT_THROW(                                                \
      {                                                        \
        try {                                                  \
          statement;                                           \
        } catch (const Exception& e) {                         \
          EXPECT_THAT(std::string(e.what()), HasSubstr(text)); \
          throw;                                               \
        }                                                      \
      },                                                       \
      Exception)

std::vector<double> range(double first, double step, std::size_t n) {
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = first + step * static_cast<double>(i);
  return out;
}

TEST(Log, ConstructionRejectsBadTimeAxis) {
  EXPECT_NO_THROW(Log(std::vector<double>{0.0, 0.5, 2.0}));
  EXPECT_THROW_WITH(Log(std::vector<double>{0.0, 1.0, 1.0}), std::invalid_argument,
                    "not strictly increasing at index 2");
  EXPECT_THROW_WITH(Log(std::vector<double>{0.0, 2.0, 1.0}), std::invalid_argument,
                    "not strictly increasing");
  EXPECT_THROW_WITH(Log(std::vector<double>{0.0, kNaN}), std::invalid_argument, "not finite");
  EXPECT_THROW(Log(std::vector<double>{-kInf, 0.0}), std::invalid_argument);
}

TEST(Log, ChannelsByName) {
  Log log(std::vector<double>{0.0, 1.0});
  log.add_channel("north", "m", {1.0, 2.0});
  log.add_channel("gear", "1", {0.0, 1.0}, Interp::kHold);
  EXPECT_TRUE(log.has("north"));
  EXPECT_FALSE(log.has("east"));
  EXPECT_EQ(log.channel_names(), (std::vector<std::string>{"north", "gear"}));
  EXPECT_EQ(log.channel("gear").interp, Interp::kHold);
  EXPECT_EQ(log.channel("north").unit, "m");
  EXPECT_EQ(log.values("north")[1], 2.0);
  log.channel("north").values[0] = 5.0;
  EXPECT_EQ(log.values("north")[0], 5.0);
  EXPECT_THROW_WITH(static_cast<void>(log.channel("east")), std::out_of_range,
                    "no channel 'east' in the log; channels are: north, gear");
}

TEST(Log, DuplicateAndMisSizedChannelsRejected) {
  Log log(std::vector<double>{0.0, 1.0, 2.0});
  log.add_channel("heading", "rad", {0.0, 0.1, 0.2});
  EXPECT_THROW_WITH(log.add_channel("heading", "deg", {1.0, 2.0, 3.0}), std::invalid_argument,
                    "channel 'heading' already exists");
  EXPECT_THROW_WITH(log.add_channel("roll", "rad", {1.0, 2.0}), std::invalid_argument,
                    "channel 'roll' has 2 values but the log has 3 time samples");
  EXPECT_THROW(log.add_channel("", "rad", {1.0, 2.0, 3.0}), std::invalid_argument);
  EXPECT_EQ(log.channels().size(), 1u);
}

TEST(Log, AppendRowBuildsTheLog) {
  Log log;
  log.declare_channel("u", "m/s");
  log.declare_channel("mode", "1", Interp::kNearest);
  log.reserve(3);
  const double row0[] = {1.0, 0.0};
  const double row1[] = {kNaN, 1.0};
  log.append_row(0.0, row0);
  log.append_row(0.1, row1);
  ASSERT_EQ(log.size(), 2u);
  EXPECT_EQ(log.time(), (std::vector<double>{0.0, 0.1}));
  EXPECT_EQ(log.values("u")[0], 1.0);
  EXPECT_TRUE(is_missing(log.values("u")[1]));  // missing stays missing, never zero
  EXPECT_EQ(log.values("mode")[1], 1.0);

  EXPECT_THROW_WITH(log.append_row(0.1, row0), std::invalid_argument, "not after the last time");
  EXPECT_THROW_WITH(log.append_row(0.05, row0), std::invalid_argument, "not after the last time");
  EXPECT_THROW(log.append_row(kNaN, row0), std::invalid_argument);
  const double short_row[] = {1.0};
  EXPECT_THROW_WITH(log.append_row(0.2, short_row), std::invalid_argument,
                    "1 values for 2 channels");
  EXPECT_EQ(log.size(), 2u);  // a rejected row leaves the log as it was
  EXPECT_EQ(log.values("mode").size(), 2u);
  EXPECT_THROW_WITH(log.declare_channel("v", "m/s"), std::invalid_argument,
                    "declared after 2 rows");
}

TEST(LogWindow, IsInclusiveAtBothEnds) {
  Log log(range(0.0, 0.5, 11));  // 0, 0.5, ..., 5
  log.add_channel("x", "m", range(10.0, 1.0, 11));
  const Log w = log.window(1.0, 2.5);
  EXPECT_EQ(w.time(), (std::vector<double>{1.0, 1.5, 2.0, 2.5}));
  EXPECT_EQ(w.values("x"), (std::vector<double>{12.0, 13.0, 14.0, 15.0}));
  EXPECT_EQ(w.channel("x").unit, "m");
  EXPECT_EQ(log.window(1.1, 1.4).size(), 0u);  // between samples
  EXPECT_EQ(log.window(2.0, 2.0).size(), 1u);  // a single instant
  EXPECT_EQ(log.window(-10.0, 100.0).size(), 11u);
  EXPECT_EQ(log.window(6.0, 7.0).size(), 0u);
  EXPECT_TRUE(log.window(6.0, 7.0).has("x"));  // channels are kept, with no samples
  EXPECT_THROW(static_cast<void>(log.window(2.0, 1.0)), std::invalid_argument);
  EXPECT_THROW(static_cast<void>(log.window(kNaN, 1.0)), std::invalid_argument);
}

TEST(LogResample, LinearIsExactOnALinearSignal) {
  // Jittered source times: the interpolation must not assume uniform sampling.
  const std::vector<double> t{0.0, 0.9, 2.1, 3.0, 3.95, 5.2};
  std::vector<double> x(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) x[i] = 3.0 - 0.5 * t[i];
  Log log(t);
  log.add_channel("x", "m", x);
  const std::vector<double> target = range(0.0, 0.25, 21);  // 0 .. 5
  const Log r = log.resample(target);
  ASSERT_EQ(r.size(), target.size());
  for (std::size_t k = 0; k < target.size(); ++k) {
    SCOPED_TRACE(target[k]);
    // A line through two points of a line is the line; a few roundings of values ≈ 3 (eps·3).
    EXPECT_NEAR(r.values("x")[k], 3.0 - 0.5 * target[k], 8e-15);
  }
}

TEST(LogResample, HoldAndNearestSemantics) {
  Log log(std::vector<double>{0.0, 1.0, 2.0, 3.0});
  log.add_channel("hold", "1", {10.0, 20.0, kNaN, 40.0}, Interp::kHold);
  log.add_channel("nearest", "1", {10.0, 20.0, kNaN, 40.0}, Interp::kNearest);
  const Log r = log.resample({0.0, 0.4, 0.5, 0.6, 1.0, 1.9, 2.4, 2.6, 3.0},
                             ResampleOptions{.max_gap_s = 5.0});
  // Hold: the last valid sample at or before t; the blank at 2 s is skipped, not held as NaN.
  EXPECT_EQ(r.values("hold"),
            (std::vector<double>{10.0, 10.0, 10.0, 10.0, 20.0, 20.0, 20.0, 20.0, 40.0}));
  // Nearest valid sample, a tie (0.5 s) to the earlier. Around the blank at 2 s the valid
  // neighbours are 1 s and 3 s, so 1.9 s takes 1 s and 2.4 s takes 3 s.
  EXPECT_EQ(r.values("nearest"),
            (std::vector<double>{10.0, 10.0, 10.0, 20.0, 20.0, 20.0, 40.0, 40.0, 40.0}));
}

TEST(LogResample, AngleTakesTheShorterArcAcrossZero) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  Log log(std::vector<double>{0.0, 1.0, 2.0});
  // [0, 2π) heading 359° → 1° → 3°; the same in [−π, π): 179° → −179° → −177°.
  log.add_channel("heading", "rad", {359.0 * kDeg, 1.0 * kDeg, 3.0 * kDeg}, Interp::kAngle);
  log.add_channel("signed", "rad", {179.0 * kDeg, -179.0 * kDeg, -177.0 * kDeg}, Interp::kAngle);
  log.add_channel("linear", "rad", {359.0 * kDeg, 1.0 * kDeg, 3.0 * kDeg});
  const Log r = log.resample({0.25, 0.5, 0.75, 1.5});
  // Across 0: 359.5°, 0°, 0.5° (not 269.5°, 180°, 90.5° as a straight line gives); a few
  // roundings of numbers ≈ 2π: 1e-14 rad.
  const std::vector<double> heading_deg{359.5, 0.0, 0.5, 2.0};
  const std::vector<double> signed_deg{179.5, -180.0, -179.5, -178.0};
  for (std::size_t k = 0; k < heading_deg.size(); ++k) {
    SCOPED_TRACE(k);
    // Compared modulo 2π: 360° may come out as 2π − ε or 0, both the same heading.
    EXPECT_NEAR(std::remainder(r.values("heading")[k] - heading_deg[k] * kDeg, kTwoPi), 0.0, 1e-14);
    EXPECT_NEAR(std::remainder(r.values("signed")[k] - signed_deg[k] * kDeg, kTwoPi), 0.0, 1e-14);
  }
  EXPECT_NEAR(r.values("linear")[1], 180.0 * kDeg, 1e-14);  // the long way, for contrast
  // Values stay in the channel's range: [0, 2π) and [−π, π).
  for (double v : r.values("heading")) EXPECT_TRUE(v >= 0.0 && v < 2.0 * std::numbers::pi);
  for (double v : r.values("signed")) EXPECT_TRUE(v >= -std::numbers::pi && v < std::numbers::pi);
}

TEST(LogResample, AngleWithoutAJumpEqualsLinearBitForBit) {
  // An unwrapped heading (beyond 2π) and one that never crosses a wrap: exactly kLinear.
  const std::vector<double> t{0.0, 0.9, 2.1, 3.0};
  Log log(t);
  const std::vector<double> unwrapped{6.0, 6.5, 7.2, 7.9};
  const std::vector<double> inside{0.1, 0.4, 1.3, 3.0};
  log.add_channel("unwrapped", "rad", unwrapped, Interp::kAngle);
  log.add_channel("unwrapped_lin", "rad", unwrapped);
  log.add_channel("inside", "rad", inside, Interp::kAngle);
  log.add_channel("inside_lin", "rad", inside);
  const Log r = log.resample(range(0.0, 0.1, 31));
  EXPECT_EQ(r.values("unwrapped"), r.values("unwrapped_lin"));
  EXPECT_EQ(r.values("inside"), r.values("inside_lin"));
}

TEST(LogResample, NoExtrapolationOutsideTheValidRange) {
  Log log(std::vector<double>{0.0, 1.0, 2.0, 3.0, 4.0});
  for (Interp mode : {Interp::kLinear, Interp::kNearest, Interp::kHold, Interp::kAngle}) {
    const std::string name = std::string("c") + std::to_string(static_cast<int>(mode));
    log.add_channel(name, "m", {kNaN, 1.0, 2.0, 3.0, kNaN}, mode);
  }
  const Log r = log.resample({-1.0, 0.5, 0.999, 1.0, 3.0, 3.001, 4.0, 9.0});
  for (const Channel& c : r.channels()) {
    SCOPED_TRACE(c.name);
    EXPECT_TRUE(std::isnan(c.values[0]));  // before the log
    EXPECT_TRUE(std::isnan(c.values[1]));  // in the log, before the channel's first valid
    EXPECT_TRUE(std::isnan(c.values[2]));
    EXPECT_EQ(c.values[3], 1.0);           // exactly on the first valid sample
    EXPECT_EQ(c.values[4], 3.0);           // exactly on the last valid sample
    EXPECT_TRUE(std::isnan(c.values[5]));  // just after it: hold does not hold past the end
    EXPECT_TRUE(std::isnan(c.values[6]));
    EXPECT_TRUE(std::isnan(c.values[7]));
  }
}

TEST(LogResample, WideGapsStayGaps) {
  // 1 Hz samples with a 10 s dropout between t = 4 and t = 14.
  std::vector<double> t = range(0.0, 1.0, 5);
  for (double ti : range(14.0, 1.0, 5)) t.push_back(ti);
  std::vector<double> x(t.size(), 1.0);
  Log log(t);
  log.add_channel("lin", "m", x);
  log.add_channel("hold", "m", x, Interp::kHold);
  const std::vector<double> target{3.5, 4.0, 4.5, 9.0, 13.9, 14.0, 15.5};
  for (const ResampleOptions& options : {ResampleOptions{}, ResampleOptions{.max_gap_s = 5.0}}) {
    SCOPED_TRACE(options.max_gap_s);
    const Log r = log.resample(target, options);
    for (const char* name : {"lin", "hold"}) {
      SCOPED_TRACE(name);
      const std::vector<double>& v = r.values(name);
      EXPECT_EQ(v[0], 1.0);
      EXPECT_EQ(v[1], 1.0);  // the sample at the edge of the gap is still valid
      EXPECT_TRUE(std::isnan(v[2]));
      EXPECT_TRUE(std::isnan(v[3]));
      EXPECT_TRUE(std::isnan(v[4]));
      EXPECT_EQ(v[5], 1.0);
      EXPECT_EQ(v[6], 1.0);
    }
  }
  // Infinity bridges every gap.
  const Log bridged = log.resample(target, ResampleOptions{.max_gap_s = kInf});
  EXPECT_EQ(bridged.values("lin")[3], 1.0);
  EXPECT_THROW(static_cast<void>(log.resample(target, ResampleOptions{.max_gap_s = -1.0})),
               std::invalid_argument);
}

TEST(LogResample, SlowChannelInterpolatesAcrossItsOwnBlankRows) {
  // A 100 Hz log over 10 s, with a 1 Hz channel present only on whole seconds.
  const std::size_t n = 1001;
  std::vector<double> t(n);
  for (std::size_t i = 0; i < n; ++i) t[i] = static_cast<double>(i) / 100.0;
  std::vector<double> fast(n);
  std::vector<double> slow(n, kMissing);
  for (std::size_t i = 0; i < n; ++i) {
    fast[i] = std::sin(t[i]);
    if (i % 100 == 0) slow[i] = 2.0 * t[i];
  }
  // A dropout of the fast channel between 5 s and 5.5 s is a real gap (50 × its spacing).
  for (std::size_t i = 501; i < 550; ++i) fast[i] = kMissing;
  Log log(t);
  log.add_channel("fast", "rad", fast);
  log.add_channel("slow", "m", slow);

  const std::vector<double> target{0.0, 0.255, 2.5, 5.25, 9.995};
  const Log r = log.resample(target);
  // The slow channel's valid spacing is 1 s, so its 99 blank rows are bridged; 2t is linear.
  // One rounding in t[i] = i/100 and in the interpolation, values ≤ 20: 1e-14.
  EXPECT_NEAR(r.values("slow")[1], 0.51, 1e-14);
  EXPECT_NEAR(r.values("slow")[2], 5.0, 1e-14);    // as above
  EXPECT_NEAR(r.values("slow")[3], 10.5, 1e-14);   // as above
  EXPECT_NEAR(r.values("slow")[4], 19.99, 1e-14);  // as above
  // The fast channel's auto gap is 2.5 × 0.01 s: its dropout stays missing.
  // Chord error of linear interpolation: h²/8·max|sin''| = (0.01)²/8·sin(0.26) ≈ 3.2e-6.
  EXPECT_NEAR(r.values("fast")[1], std::sin(0.255), 4e-6);
  EXPECT_TRUE(std::isnan(r.values("fast")[3]));
}

TEST(LogResample, KeepsUnitsModesAndAcceptsAnyTargetSpacing) {
  Log log(std::vector<double>{0.0, 1.0});
  log.add_channel("n", "rps", {0.0, 1.0}, Interp::kNearest);
  const Log r = log.resample({0.2, 0.3, 0.9});
  EXPECT_EQ(r.channel("n").unit, "rps");
  EXPECT_EQ(r.channel("n").interp, Interp::kNearest);
  EXPECT_EQ(r.values("n"), (std::vector<double>{0.0, 0.0, 1.0}));
  EXPECT_THROW(static_cast<void>(log.resample({0.2, 0.2})), std::invalid_argument);
  EXPECT_THROW(static_cast<void>(log.resample({0.3, 0.2})), std::invalid_argument);
  EXPECT_THROW(static_cast<void>(log.resample({0.3, kNaN})), std::invalid_argument);
  // A channel with no valid sample is all missing.
  log.add_channel("empty", "m", {kNaN, kNaN});
  const Log r2 = log.resample({0.0, 0.5, 1.0});
  for (double v : r2.values("empty")) EXPECT_TRUE(std::isnan(v));
}

}  // namespace
}  // namespace dynpos::core
