// The onset of a unit's fall (src/ident/fall_onset.hpp) on shaft speeds sampled as a trial
// logger sees them: the Gunnerus' tunnel at 1 Hz, its speed control a first-order lag of 1 s
// behind an acceleration limit of 1.4 rps/s, tripped at every phase between two samples.

#include "fall_onset.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace dynpos::ident::detail {
namespace {

// The shaft speed [rps] of a unit at `level` (plus `slope` per s) tripped at t_f: the rate
// limit r until r·T, then first order with T.
double shaft(double t, double level, double t_f, double tau = 1.0, double r = 1.4,
             double slope = 0.0) {
  if (t <= t_f) return level + slope * (t - t_f);
  const double dt = t - t_f, t_lin = std::max(0.0, (level - r * tau) / r);
  if (dt <= t_lin) return level - r * dt;
  return std::min(level, r * tau) * std::exp(-(dt - t_lin) / tau);
}

struct Sampled {
  std::vector<double> t, s;
};

// Samples every `dt` from 590 s to 615 s; NaN rows between them as a 10 Hz log has.
Sampled sample(double dt, double level, double t_f, double slope = 0.0) {
  Sampled x;
  for (int k = 0; k <= 250; ++k) {
    const double t = 590.0 + 0.1 * k;
    x.t.push_back(t);
    const bool at_sample = std::abs(std::remainder(t - 590.0, dt)) < 1e-6;
    x.s.push_back(at_sample ? shaft(t, level, t_f, 1.0, 1.4, slope)
                            : std::numeric_limits<double>::quiet_NaN());
  }
  return x;
}

// The search as the failure test sets it: from 2 s before the last sample at 0.6 of the level
// to the next sample.
FallSearch search(const Sampled& x, double level, double dt) {
  double t_hi = x.t.front();
  for (std::size_t i = 0; i < x.t.size(); ++i) {
    if (!std::isnan(x.s[i]) && x.s[i] >= 0.6 * level && x.t[i] < 605.0) t_hi = x.t[i];
  }
  FallSearch q;
  q.from_s = t_hi - 2.0;
  q.to_s = t_hi + dt;
  q.noise_sigma = 1e-3;
  return q;
}

TEST(FallOnset, TimedBetweenOneHertzSamplesAtEveryPhaseAndLevel) {
  // From 0.5 rps (first order only) to the tunnel's full 5.42 rps (rate-limited for 2.9 s).
  for (const double level : {0.5, 1.4, 2.65, 4.0, 5.42}) {
    for (int k = 0; k < 10; ++k) {
      const double t_f = 600.0 + 0.1 * k;
      SCOPED_TRACE(testing::Message() << "level " << level << " rps, onset " << t_f << " s");
      const Sampled x = sample(1.0, level, t_f);
      const auto o = fit_fall_onset(x.t, x.s, search(x, level, 1.0));
      ASSERT_TRUE(o);
      EXPECT_NEAR(o->t_s, t_f, 0.3);
      EXPECT_LE(o->earliest_s, o->latest_s);
      EXPECT_NEAR(o->level, level, 0.02 * level);
    }
  }
}

// A fall slower than the search was set for (r = 0.5 rps/s: 4.3 s from the level to 0.6 of it,
// the search reaching 2 s back) began before the search: not timed, rather than 3.6 s late (a
// line through its first falling samples taken for a swing).
TEST(FallOnset, AFallThatBeganBeforeTheSearchIsNotTimed) {
  Sampled x;
  for (int k = 0; k <= 250; ++k) {
    const double t = 590.0 + 0.1 * k;
    x.t.push_back(t);
    x.s.push_back(k % 10 == 0 ? shaft(t, 5.42, 600.0, 1.0, 0.5)
                              : std::numeric_limits<double>::quiet_NaN());
  }
  EXPECT_FALSE(fit_fall_onset(x.t, x.s, search(x, 5.42, 1.0)));
  // The same fall, searched from far enough back, is timed.
  FallSearch wide = search(x, 5.42, 1.0);
  wide.from_s -= 4.0;
  const auto o = fit_fall_onset(x.t, x.s, wide);
  ASSERT_TRUE(o);
  EXPECT_NEAR(o->t_s, 600.0, 0.3);
}

TEST(FallOnset, ADriftingLevelIsTheLineBeforeTheFall) {
  // The DP system swings the unit at 0.1 rps/s up or down until the trip.
  for (const double slope : {-0.1, 0.1}) {
    const Sampled x = sample(1.0, 2.65, 600.4, slope);
    const auto o = fit_fall_onset(x.t, x.s, search(x, 2.65, 1.0));
    ASSERT_TRUE(o);
    EXPECT_NEAR(o->t_s, 600.4, 0.3) << "slope " << slope;
  }
}

// The DP loop ramps the unit's order down from 2.5 to 1.5 rps over 595–599 s, before the unit
// trips at 600.4 s (then asks 1.83 rps for the load the unit no longer takes); the shaft follows
// the order after the Gunnerus' command dead time of 1.3 s with T = 1 s until the trip. Order at
// 10 Hz, feedback at 1 Hz.
TEST(FallOnset, AnOrderedRampBeforeTheTripIsFollowedNotTakenForTheFall) {
  constexpr double kTrip = 600.4, kTau = 1.0, kRate = 1.4;
  const auto ordered = [](double t) {
    if (t >= kTrip + 0.5) return 1.83;
    return 2.5 - 1.0 * std::clamp((t - 595.0) / 4.0, 0.0, 1.0);
  };
  constexpr double kDead = 1.3;
  Sampled x;
  std::vector<double> order;
  double y = 2.5;  // the shaft following the order, integrated at 1 ms
  double at_trip = 0.0;
  for (int k = 0; k <= 250; ++k) {
    const double t = 590.0 + 0.1 * k;
    for (int m = 0; m < 100 && t > 590.0; ++m) {
      const double tm = t - 0.1 + 0.001 * m;
      if (tm < kTrip) y += 0.001 * (ordered(tm - kDead) - y) / kTau;
    }
    if (t <= kTrip) at_trip = y;
    x.t.push_back(t);
    order.push_back(ordered(t));
    const double s = t <= kTrip ? y : shaft(t, at_trip, kTrip, kTau, kRate);
    x.s.push_back(k % 10 == 0 ? s : std::numeric_limits<double>::quiet_NaN());
  }
  const FallSearch q = search(x, 2.5, 1.0);
  const auto with_order = fit_fall_onset(x.t, x.s, q, order);
  ASSERT_TRUE(with_order);
  EXPECT_NEAR(with_order->t_s, kTrip, 0.3);
  // Without the order, the level line takes the ramp for the start of the decay: the fixture
  // shows the weakness it guards against.
  const auto without = fit_fall_onset(x.t, x.s, q);
  EXPECT_TRUE(!without || std::abs(without->t_s - kTrip) > 0.3)
      << "onset without the order " << without->t_s;
}

TEST(FallOnset, AtTenHertzTheOnsetAndTimeConstantAreClose) {
  const Sampled x = sample(0.1, 1.0, 600.35);  // below r·T: first order from the onset
  const auto o = fit_fall_onset(x.t, x.s, search(x, 1.0, 0.1));
  ASSERT_TRUE(o);
  EXPECT_NEAR(o->t_s, 600.35, 0.05);
  EXPECT_NEAR(o->time_constant_s, 1.0, 0.1);
}

TEST(FallOnset, NothingWithoutALevelBeforeOrAFallAfter) {
  const Sampled x = sample(1.0, 2.65, 600.0);
  FallSearch q = search(x, 2.65, 1.0);
  q.from_s = 589.0;  // no sample in the 2 s before it
  q.to_s = 589.5;
  EXPECT_FALSE(fit_fall_onset(x.t, x.s, q));
  q.from_s = 612.0;  // one sample left after the latest onset
  q.to_s = 614.0;
  q.fall_s = 0.5;
  EXPECT_FALSE(fit_fall_onset(x.t, x.s, q));
}

}  // namespace
}  // namespace dynpos::ident::detail
