#include "dynpos/ident/failure_test.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "dynpos/core/error.hpp"
#include "synthetic.hpp"

namespace dynpos::ident {
namespace {

using testing::Normal;

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

// A unit that trips at t_trip: its thrust [N] holds `level` (with a slow DP swing of 3 kN),
// then after a dead time of 0.2 s decays to 0 with a first-order time constant of 1 s.
std::function<double(double)> tripping(double level, double t_trip) {
  return [=](double t) {
    const double before = level + 3e3 * std::sin(2.0 * kPi * t / 40.0);
    const double t0 = t_trip + 0.2;
    if (t < t0) return before;
    const double at_t0 = level + 3e3 * std::sin(2.0 * kPi * t0 / 40.0);
    return at_t0 * std::exp(-(t - t0) / 1.0);
  };
}

// A unit taking over: `from` until t_start, then a 2 s ramp to `to` [N].
std::function<double(double)> taking_over(double from, double to, double t_start) {
  return [=](double t) {
    const double s = std::clamp((t - t_start) / 2.0, 0.0, 1.0);
    return from + (to - from) * s;
  };
}

// The horizontal excursion after a failure at t_fail: a half sine of amplitude `peak_m` and
// duration `duration_s` (peak at half of it), 30° from north.
struct Bump {
  double t_fail = 300.0;
  double peak_m = 3.0;
  double duration_s = 30.0;
  double operator()(double t) const {
    const double s = t - t_fail;
    return (s <= 0.0 || s >= duration_s) ? 0.0 : peak_m * std::sin(kPi * s / duration_s);
  }
  // The first time after the peak at which the bump is down to `radius` [m].
  double back_within(double radius) const {
    return t_fail + duration_s - duration_s / kPi * std::asin(radius / peak_m);
  }
};

struct Series {
  std::vector<double> t;
  FailureTestInput in;
};

// 600 s at 10 Hz: position noise 2 cm around a bump, heading 90° ± 0.05° plus 2° per 3 m of
// the bump, thrust noise 0.2 kN on every unit.
Series series(const Bump& bump,
              const std::vector<std::pair<std::string, std::function<double(double)>>>& units,
              double duration_s = 600.0, std::uint64_t seed = 7) {
  Series s;
  s.t = testing::time_axis(0.0, 0.1, static_cast<std::size_t>(duration_s / 0.1) + 1);
  FailureTestInput& in = s.in;
  in.t_s = s.t;
  Normal rng(seed);
  for (const double t : s.t) {
    const double b = bump(t);
    in.north_m.push_back(7e6 + b * std::cos(30.0 * kDeg) + 0.02 * rng());
    in.east_m.push_back(5e5 + b * std::sin(30.0 * kDeg) + 0.02 * rng());
    in.heading_rad.push_back((90.0 + 2.0 * b / 3.0 + 0.05 * rng()) * kDeg);
  }
  for (const auto& [name, f] : units) {
    in.units.push_back({name, testing::sample(s.t, f, 200.0, ++seed)});
  }
  return s;
}

auto constant(double v) {
  return [v](double) { return v; };
}

// Four units; port trips at 300 s, the others take over 0.5 s later.
Series one_trip(const Bump& bump = {}) {
  return series(bump, {{"port", tripping(40e3, 300.0)},
                       {"stb", taking_over(30e3, 55e3, 300.5)},
                       {"tunnel", taking_over(10e3, 20e3, 300.5)},
                       {"azimuth", taking_over(20e3, 30e3, 300.5)}});
}

// A bump of the noise's own size: the median peak lies at the footprint (the largest of a
// minute's 2 cm noise), so whether the vessel left it is a toss of the noise. The recovery is
// flagged; the same bump at 0.3 m is not.
TEST(FailureTest, ARecoveryAtTheFootprintsEdgeIsFlagged) {
  for (const double peak_m : {0.3, 0.06}) {
    Bump bump;
    bump.peak_m = peak_m;
    const FailureTestResult r = analyse_failure_test(one_trip(bump).in);
    ASSERT_EQ(r.events.size(), 1u) << peak_m;
    const FailureEvent& e = r.events.front();
    ASSERT_TRUE(e.median_peak_m && e.footprint_m) << peak_m;
    const double share = std::abs(*e.median_peak_m / *e.footprint_m - 1.0);
    std::printf("bump %.2f m: median peak %.3f m, footprint %.3f m (%.0f %% apart)\n", peak_m,
                *e.median_peak_m, *e.footprint_m, 100.0 * share);
    EXPECT_EQ(e.recovery_at_footprint_edge, share <= 0.1) << peak_m;
    EXPECT_EQ(e.recovery_at_footprint_edge, peak_m < 0.1) << peak_m;
  }
  FailureTestOptions o;
  o.footprint_edge_share = -0.1;
  EXPECT_THROW(o.validate(), core::InputError);
}

TEST(FailureTest, FindsATripAndItsExcursion) {
  const Bump bump;
  const FailureTestResult r = analyse_failure_test(one_trip(bump).in);
  ASSERT_EQ(r.events.size(), 1u);
  const FailureEvent& e = r.events.front();
  EXPECT_EQ(e.unit, "port");
  EXPECT_EQ(e.units, std::vector<std::string>{"port"});
  // The fit finds the start of the fall, 0.2 s (the dead time) after the trip.
  EXPECT_EQ(e.onset, OnsetMethod::kFallFit);
  EXPECT_NEAR(e.time_s, 300.0, 0.5);
  EXPECT_NEAR(e.time_s, 300.2, 0.1);
  ASSERT_TRUE(e.fall_time_constant_s);
  EXPECT_NEAR(*e.fall_time_constant_s, 1.0, 0.1);
  // Peak 3 m 15 s after the trip, within max(5 %, 0.1 m) and 2 s (the half sine's top is
  // flat: 2 cm of noise move the largest distance by up to 1 s).
  ASSERT_TRUE(e.peak_excursion_m && e.time_to_peak_s && e.footprint_m && e.recovery_s);
  EXPECT_NEAR(*e.peak_excursion_m, 3.0, std::max(0.05 * 3.0, 0.1));
  EXPECT_NEAR(e.time_s + *e.time_to_peak_s, bump.t_fail + 0.5 * bump.duration_s, 2.0);
  // The footprint is the noise's largest distance: 600 samples of 2 cm per axis.
  EXPECT_GT(*e.footprint_m, 0.03);
  EXPECT_LT(*e.footprint_m, 0.12);
  EXPECT_NEAR(e.time_s + *e.recovery_s, bump.back_within(*e.footprint_m), 2.0);
  // The 3 s median of the distance peaks with the bump, far from the footprint's edge.
  ASSERT_TRUE(e.median_peak_m);
  EXPECT_NEAR(*e.median_peak_m, 3.0, 0.05);
  EXPECT_FALSE(e.recovery_at_footprint_edge);
  ASSERT_TRUE(e.peak_heading_rad);
  EXPECT_NEAR(*e.peak_heading_rad / kDeg, 2.0, 0.2);
  EXPECT_NEAR(e.pre_from_s, e.time_s - 60.0, 1e-9);
  EXPECT_NEAR(*e.pre_heading_rad / kDeg, 90.0, 0.05);
  // The others: 30 s means before and after; the ramps take 2.3 s of the 30 s after.
  ASSERT_EQ(e.redistribution.size(), 3u);
  const UnitRedistribution& stb = e.redistribution[0];
  EXPECT_EQ(stb.unit, "stb");
  EXPECT_NEAR(*stb.mean_before, 30e3, 0.2e3);
  EXPECT_NEAR(*stb.mean_after, 55e3 - 25e3 * 1.3 / 30.0, 0.3e3);
  EXPECT_TRUE(stb.took_over);
  EXPECT_NEAR(*e.redistribution[1].change, 10e3 * (1.0 - 1.3 / 30.0), 0.3e3);
  EXPECT_NEAR(e.level_before, 40e3, 3e3);
}

TEST(FailureTest, AnInstantDropIsTimedAtTheDrop) {
  Series s = one_trip();
  std::vector<double>& port = s.in.units[0].values;
  for (std::size_t i = 0; i < s.t.size(); ++i) port[i] = s.t[i] < 300.05 ? 40e3 : 0.0;
  const FailureTestResult r = analyse_failure_test(s.in);
  ASSERT_EQ(r.events.size(), 1u);
  EXPECT_NEAR(r.events[0].time_s, 300.0, 0.1 + 1e-9);
}

TEST(FailureTest, ACommandedRampToZeroIsNotATrip) {
  // Port ramps from 40 kN to 0 over 60 s; the others ramp up as slowly.
  auto ramp = [](double from, double to) {
    return [=](double t) { return from + (to - from) * std::clamp((t - 300.0) / 60.0, 0.0, 1.0); };
  };
  const Series s = series(
      Bump{}, {{"port", ramp(40e3, 0.0)}, {"stb", ramp(30e3, 55e3)}, {"tunnel", ramp(10e3, 20e3)}});
  EXPECT_TRUE(analyse_failure_test(s.in).events.empty());
}

TEST(FailureTest, NoEventOnAUnitAtZeroOrANoisySmallLevel) {
  const Series s = series(
      Bump{},
      {{"port", constant(40e3)}, {"stb", taking_over(30e3, 55e3, 300.0)}, {"idle", constant(0.0)}});
  EXPECT_TRUE(analyse_failure_test(s.in).events.empty());
  // 1 kN with a noise of 0.5 kN dips to zero again and again, and never for long.
  Series noisy =
      series(Bump{}, {{"small", constant(1e3)}, {"stb", taking_over(30e3, 55e3, 300.0)}});
  Normal rng(3);
  for (double& v : noisy.in.units[0].values) v = 1e3 + 0.5e3 * rng();
  EXPECT_TRUE(analyse_failure_test(noisy.in).events.empty());
}

TEST(FailureTest, TwoTripsGiveTwoEvents) {
  // Port trips at 150 s and is back at 250 s (a 3 s ramp); stb trips at 400 s.
  auto port = [f = tripping(40e3, 150.0)](double t) {
    return t < 250.0 ? f(t) : 40e3 * std::min(1.0, (t - 250.0) / 3.0);
  };
  // Stb covers port's outage and trips itself at 400 s; the tunnel answers both.
  auto stb = [](double t) {
    if (t >= 400.2) return 30e3 * std::exp(-(t - 400.2));
    return (t < 150.5 || t >= 250.0) ? 30e3 : 50e3;
  };
  auto tunnel = [](double t) { return t < 150.5 ? 10e3 : t < 400.5 ? 15e3 : 25e3; };
  const Series s =
      series(Bump{400.0, 2.0, 40.0}, {{"port", port}, {"stb", stb}, {"tunnel", tunnel}});
  const FailureTestResult r = analyse_failure_test(s.in);
  ASSERT_EQ(r.events.size(), 2u);
  EXPECT_EQ(r.events[0].unit, "port");
  EXPECT_NEAR(r.events[0].time_s, 150.0, 0.5);
  EXPECT_EQ(r.events[1].unit, "stb");
  EXPECT_NEAR(r.events[1].time_s, 400.0, 0.5);
  // The second event's pre-failure window stops at the first event at the earliest; the
  // first's response span ends at the second.
  EXPECT_LE(r.events[0].response_to_s, r.events[1].time_s);
  EXPECT_NEAR(*r.events[1].peak_excursion_m, 2.0, 0.1);
  // No bump after the first trip: the noise alone.
  EXPECT_LT(*r.events[0].peak_excursion_m, 0.15);
}

TEST(FailureTest, UnitsTrippingTogetherAreOneEvent) {
  const Series s = series(Bump{}, {{"port", tripping(40e3, 300.0)},
                                   {"stb", tripping(35e3, 300.8)},
                                   {"tunnel", taking_over(10e3, 25e3, 301.0)}});
  const FailureTestResult r = analyse_failure_test(s.in);
  ASSERT_EQ(r.events.size(), 1u);
  EXPECT_EQ(r.events[0].unit, "port");
  EXPECT_EQ(r.events[0].units, (std::vector<std::string>{"port", "stb"}));
  ASSERT_EQ(r.events[0].redistribution.size(), 1u);
  EXPECT_EQ(r.events[0].redistribution[0].unit, "tunnel");
}

TEST(FailureTest, ATripNoOtherUnitAnswersIsNotReported) {
  const Series s = series(Bump{}, {{"port", tripping(40e3, 300.0)}, {"stb", constant(30e3)}});
  EXPECT_TRUE(analyse_failure_test(s.in).events.empty());
  // With the tripped unit alone in the log there is no one to answer: reported.
  const Series alone = series(Bump{}, {{"port", tripping(40e3, 300.0)}});
  EXPECT_EQ(analyse_failure_test(alone.in).events.size(), 1u);
}

TEST(FailureTest, NoRecoveryBeforeTheLogEnds) {
  // The bump lasts 200 s and the log ends 100 s after the failure.
  const Series s =
      series(Bump{300.0, 3.0, 200.0},
             {{"port", tripping(40e3, 300.0)}, {"stb", taking_over(30e3, 55e3, 300.5)}}, 400.0);
  const FailureTestResult r = analyse_failure_test(s.in);
  ASSERT_EQ(r.events.size(), 1u);
  EXPECT_FALSE(r.events[0].recovery_s);
  EXPECT_NEAR(*r.events[0].peak_excursion_m, 3.0 * std::sin(kPi * 100.0 / 200.0), 0.15);
  EXPECT_NEAR(r.events[0].response_to_s, 400.0, 1e-9);
}

// Two fixes in the pre-failure minute are no footprint, however many rows joining them fills.
TEST(FailureTest, TwoFixesBeforeTheFailureAreNoFootprint) {
  Series s = one_trip();
  for (std::size_t i = 0; i < s.t.size(); ++i) {
    const bool kept =
        s.t[i] > 301.0 || std::abs(s.t[i] - 250.0) < 0.05 || std::abs(s.t[i] - 251.0) < 0.05;
    if (!kept) s.in.north_m[i] = s.in.east_m[i] = std::numeric_limits<double>::quiet_NaN();
  }
  const FailureTestResult r = analyse_failure_test(s.in);
  ASSERT_EQ(r.events.size(), 1u);
  EXPECT_FALSE(r.events[0].footprint_m);
  EXPECT_FALSE(r.events[0].recovery_s);
}

// A single wild fix 10 s after the vessel is back (the bump ends at 330 s) does not hold the
// recovery back to it: the return is sought from the median distance's peak, not the raw one.
TEST(FailureTest, AWildFixAfterTheReturnMovesNoRecovery) {
  const Bump bump;
  Series s = one_trip(bump);
  const std::size_t i = static_cast<std::size_t>(std::lround(340.0 / 0.1));
  s.in.north_m[i] += 20.0;
  const FailureTestResult r = analyse_failure_test(s.in);
  ASSERT_EQ(r.events.size(), 1u);
  const FailureEvent& e = r.events.front();
  ASSERT_TRUE(e.recovery_s && e.footprint_m);
  EXPECT_NEAR(e.time_s + *e.recovery_s, bump.back_within(*e.footprint_m), 2.0);
}

TEST(FailureTest, WithoutPositionOnlyThePositionFiguresAreMissing) {
  Series s = one_trip();
  s.in.north_m.clear();
  s.in.east_m.clear();
  const FailureTestResult r = analyse_failure_test(s.in);
  ASSERT_EQ(r.events.size(), 1u);
  EXPECT_FALSE(r.events[0].peak_excursion_m);
  EXPECT_FALSE(r.events[0].recovery_s);
  EXPECT_TRUE(r.events[0].peak_heading_rad);
}

// An order chattering at 10 Hz between two allocations (0.2 and 13.9 kN, as the Gunnerus'
// tunnel's in the agility trial) until `t_stop` [s], 0 after; NaN-free.
std::vector<double> chattering_order(const std::vector<double>& t, double t_stop) {
  std::vector<double> order(t.size());
  Normal rng(11);
  for (std::size_t i = 0; i < t.size(); ++i)
    order[i] = t[i] >= t_stop ? 0.0 : rng() > 0.0 ? 13.9e3 : 0.2e3;
  return order;
}

TEST(FailureTest, AChatteringOrderTheFeedbackFollowsIsNoTrip) {
  // The unit follows the order's mean (7 kN) and, 1 s after the order drops to 0 at 400 s,
  // decays to 0 with T = 1 s: a stop. The other unit does not answer.
  auto follows = [](double t) { return t < 401.0 ? 7e3 : 7e3 * std::exp(-(t - 401.0)); };
  Series s = series(Bump{}, {{"tunnel", follows}, {"stb", constant(30e3)}});
  s.in.units[0].order = chattering_order(s.t, 400.0);
  EXPECT_TRUE(analyse_failure_test(s.in).events.empty());
  // The same order chattering on while the feedback falls at 400 s: a trip, at its instant.
  auto trips = [](double t) { return t < 400.0 ? 7e3 : 7e3 * std::exp(-(t - 400.0)); };
  Series tripped = series(Bump{}, {{"tunnel", trips}, {"stb", constant(30e3)}});
  tripped.in.units[0].order = chattering_order(tripped.t, 1e9);
  const FailureTestResult r = analyse_failure_test(tripped.in);
  ASSERT_EQ(r.events.size(), 1u);
  EXPECT_NEAR(r.events[0].time_s, 400.0, 0.2);
}

// 300 s at 10 Hz of wave motion alone: 0.5 m north at an 8 s period, a failure at 150 s.
FailureTestInput waves() {
  FailureTestInput in;
  in.t_s = testing::time_axis(0.0, 0.1, 3001);
  for (const double t : in.t_s) {
    in.north_m.push_back(0.5 * std::sin(2.0 * kPi * t / 8.0));
    in.east_m.push_back(0.0);
  }
  return in;
}

TEST(FailureTest, ASingleWaveCrestAboveTheFootprintIsNoDeparture) {
  // The crest at 202 s, 2 cm higher than the rest for 0.3 s: the peak, above the footprint,
  // but the distance through its 3 s median never leaves it.
  FailureTestInput in = waves();
  for (std::size_t i = 0; i < in.t_s.size(); ++i) {
    in.north_m[i] += 0.02 * std::exp(-std::pow((in.t_s[i] - 202.0) / 0.15, 2));
  }
  const FailureEvent e = failure_excursion(in, 150.0);
  ASSERT_TRUE(e.footprint_m && e.peak_excursion_m && e.recovery_s);
  EXPECT_GT(*e.peak_excursion_m, *e.footprint_m + 0.01);
  EXPECT_EQ(*e.recovery_s, 0.0);
}

TEST(FailureTest, FixesAtOneHertzGiveTheFootprintAndPeakOfEveryRow) {
  // The same motion with a fix every 10th row, 0.3 s off the crests: joined by the spline, the
  // footprint and peak are those of the 10 Hz motion within 0.5 %; the fixes alone reach
  // cos(2π·0.3/8) = 0.97 of them.
  const FailureTestInput every_row = waves();
  FailureTestInput fixes = every_row;
  for (std::size_t i = 0; i < fixes.t_s.size(); ++i) {
    if (i % 10 != 3) fixes.north_m[i] = fixes.east_m[i] = std::nan("");
  }
  const FailureEvent a = failure_excursion(every_row, 150.0), b = failure_excursion(fixes, 150.0);
  ASSERT_TRUE(a.footprint_m && b.footprint_m && a.peak_excursion_m && b.peak_excursion_m);
  EXPECT_NEAR(*b.footprint_m, *a.footprint_m, 0.005 * *a.footprint_m);
  EXPECT_NEAR(*b.peak_excursion_m, *a.peak_excursion_m, 0.005 * *a.peak_excursion_m);
  FailureTestOptions no_fill;
  no_fill.fix_gap_s = 0.0;
  EXPECT_LT(*failure_excursion(fixes, 150.0, no_fill).footprint_m, 0.99 * *a.footprint_m);
}

TEST(FailureTest, BadInputAndOptions) {
  FailureTestInput in = one_trip().in;
  FailureTestOptions o;
  o.pre_window_s = 0.0;
  EXPECT_THROW_MATCHING(analyse_failure_test(in, o), core::InputError, "pre_window");
  o = {};
  o.zero_fraction = 1.5;
  EXPECT_THROW_MATCHING(analyse_failure_test(in, o), core::InputError, "zero_fraction");
  in.units[1].values.pop_back();
  EXPECT_THROW_MATCHING(analyse_failure_test(in), core::InputError, "stb");
  in.units.clear();
  EXPECT_THROW_MATCHING(analyse_failure_test(in), core::InputError, "no unit feedback");
}

}  // namespace
}  // namespace dynpos::ident
