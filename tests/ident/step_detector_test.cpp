#include "dynpos/ident/step_detector.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "dynpos/core/error.hpp"
#include "dynpos/core/log.hpp"
#include "synthetic.hpp"

namespace dynpos::ident {
namespace {

using core::InputError;
using testing::make_gap;
using testing::sample;
using testing::time_axis;

// A command that ramps from `from` to `to` over `ramp` seconds starting at `at` (ramp = 0: an
// ideal step, the new value from `at` on).
struct Move {
  double at;
  double from;
  double to;
  double ramp;
};

double command(const std::vector<Move>& moves, double t) {
  double u = moves.front().from;
  for (const Move& m : moves) {
    if (t < m.at) break;
    u = m.ramp > 0.0 ? m.from + (m.to - m.from) * std::min((t - m.at) / m.ramp, 1.0) : m.to;
  }
  return u;
}

// The surge programme in miniature: small and large steps up and down, from several
// baselines, ideal and rate-limited, positive and negative.
const std::vector<Move> kProgramme{
    {50.0, 0.0, 0.05, 0.0},  {150.0, 0.05, 0.10, 0.0}, {250.0, 0.10, 0.40, 3.0},
    {400.0, 0.40, 0.0, 4.0}, {500.0, 0.0, -0.30, 0.0}, {600.0, -0.30, -0.10, 2.0},
};

// A window [from, to] with its step time, and how far the log reaches when t holds only the
// window's rows.
StepWindow window(double from, double to, std::optional<double> t_step = {},
                  std::optional<double> log_start_s = {}, std::optional<double> log_end_s = {}) {
  return {from, to, t_step, log_start_s, log_end_s};
}

TEST(StepDetector, FindsEveryStepOfAMultiStepLog) {
  // 100 Hz with ±30 % jitter, input noise σ = 0.002, a 2 s logging gap inside a plateau.
  const std::vector<double> t = time_axis(0.0, 0.01, 70001, 0.3, 3);
  std::vector<double> u = sample(
      t, [](double x) { return command(kProgramme, x); }, 0.002, 4);
  make_gap(t, u, 320.0, 322.0);
  const StepDetection found = detect_steps(t, u);
  ASSERT_EQ(found.steps.size(), kProgramme.size());
  // The difference-based noise estimate of σ = 0.002: within 10 % for 70 000 samples.
  EXPECT_NEAR(found.noise_sigma, 0.002, 0.0002);
  for (std::size_t k = 0; k < kProgramme.size(); ++k) {
    const Move& m = kProgramme[k];
    const Step& s = found.steps[k];
    SCOPED_TRACE(k);
    // Ideal steps: the first sample at the new level, at most one period (+30 % jitter)
    // after the true time. Ramps: the line through the 10–90 % samples (σ/rate ≤ 0.02 s per
    // sample, averaged over ≥ 160 samples) meets the levels within 0.02 s.
    if (m.ramp == 0.0) {
      EXPECT_GE(s.t_step, m.at);
      EXPECT_LE(s.t_step, m.at + 0.013);
      EXPECT_EQ(s.t_ramp_end, s.t_step);
    } else {
      EXPECT_NEAR(s.t_step, m.at, 0.02);
      EXPECT_NEAR(s.t_ramp_end, m.at + m.ramp, 0.02);
    }
    // Levels are medians of ≥ 9 000 samples: standard error 1.25σ/√n < 3e-5; 2e-4 is 7 of them.
    EXPECT_NEAR(*s.u_before, m.from, 2e-4);
    EXPECT_NEAR(*s.u_after, m.to, 2e-4);
    EXPECT_NEAR(*s.delta_u(), m.to - m.from, 4e-4);
    // Windows: from the previous ramp's end to the sample before the next step.
    const double prev_end = k == 0 ? 0.0 : kProgramme[k - 1].at + kProgramme[k - 1].ramp;
    EXPECT_NEAR(s.t_begin, prev_end, 0.05);
    if (k + 1 < kProgramme.size()) {
      EXPECT_LT(s.t_end, found.steps[k + 1].t_step);
      EXPECT_GT(s.t_end, found.steps[k + 1].t_step - 0.014);
    } else {
      EXPECT_EQ(s.t_end, t.back());
    }
  }
}

TEST(StepDetector, IgnoresSpikesAndNoiseBelowTheThreshold) {
  const std::vector<double> t = time_axis(0.0, 0.1, 3001);
  std::vector<double> u = sample(
      t, [](double x) { return x < 150.0 ? 1.0 : 2.0; }, 0.01, 9);
  u[500] += 0.5;  // one-sample spikes: not plateaus, so not steps
  u[2000] -= 0.8;
  const StepDetection found = detect_steps(t, u);
  ASSERT_EQ(found.steps.size(), 1u);
  EXPECT_NEAR(found.steps.front().t_step, 150.0, 0.1);
  // A min_step larger than the step leaves nothing: an empty list and the reason.
  StepDetectorOptions coarse;
  coarse.min_step = 1.05;  // above the step, below the range with spikes (1.07)
  const StepDetection none = detect_steps(t, u, coarse);
  EXPECT_TRUE(none.steps.empty());
  EXPECT_THAT(none.message, ::testing::HasSubstr("no step found"));
}

TEST(StepDetector, MinStepOverridesTheNoiseOfADitheredOrder) {
  // An rpm order dithered by ±2 rpm (uniform, every 0.5 s sample: σ = 1.15 rpm), programme
  // 0 → 9 → 18 → 150 rpm. The adapted threshold, 10 σ̂ = 11.5 rpm, keeps the dither out and
  // with it the two 9 rpm steps; --min-step 6 finds all three and no dither; --min-step 10
  // only the large one (nothing below it is reported).
  const std::vector<double> t = time_axis(0.0, 0.5, 1601);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> dither(-2.0, 2.0);
  std::vector<double> u(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double level = t[i] < 200.0 ? 0.0 : t[i] < 400.0 ? 9.0 : t[i] < 600.0 ? 18.0 : 150.0;
    u[i] = level + dither(rng);
  }
  EXPECT_EQ(detect_steps(t, u).steps.size(), 1u);
  StepDetectorOptions fine;
  fine.min_step = 6.0;
  const StepDetection found = detect_steps(t, u, fine);
  EXPECT_EQ(found.threshold, 6.0);
  ASSERT_EQ(found.steps.size(), 3u);
  const double at[] = {200.0, 400.0, 600.0};
  for (std::size_t k = 0; k < 3; ++k) {
    // The first sample past the band: the step time within one 0.5 s sample.
    EXPECT_NEAR(found.steps[k].t_step, at[k], 0.5) << k;
  }
  // Levels are medians of ≥ 100 samples of the dither: within 0.5 rpm.
  EXPECT_NEAR(*found.steps[0].delta_u(), 9.0, 0.5);
  EXPECT_NEAR(*found.steps[1].delta_u(), 9.0, 0.5);
  StepDetectorOptions coarse;
  coarse.min_step = 10.0;
  const StepDetection large = detect_steps(t, u, coarse);
  ASSERT_EQ(large.steps.size(), 1u);
  EXPECT_NEAR(large.steps[0].t_step, 600.0, 0.5);
}

// The input's noise by selection on copies of its differences (what step_threshold gives
// from their counts when they take few values): max(1.4826·MAD/√2, trimmed RMS/√2).
double selected_noise_sigma(const std::vector<double>& u) {
  std::vector<double> d;
  for (std::size_t i = 1; i < u.size(); ++i) d.push_back(u[i] - u[i - 1]);
  const auto median = [](std::vector<double> v) {
    const std::size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid), v.end());
    if (v.size() % 2 == 1) return v[mid];
    return 0.5 *
           (*std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid)) + v[mid]);
  };
  const double m = median(d);
  std::vector<double> dev, d2;
  for (const double x : d) {
    dev.push_back(std::abs(x - m));
    d2.push_back(x * x);
  }
  const double mad_sigma = 1.4826 * median(dev) / std::sqrt(2.0);
  const std::size_t keep = d2.size() - d2.size() / 50;
  std::sort(d2.begin(), d2.end());
  double sum = 0.0;
  for (std::size_t i = 0; i < keep; ++i) sum += d2[i];
  return std::max(mad_sigma, std::sqrt(sum / static_cast<double>(keep) / 2.0));
}

TEST(StepDetector, ThresholdOfAQuantizedOrderFromCountsAndOnEveryCore) {
  // An rpm order logged in whole rpm with a ±2 rpm dither: its differences take 9 values, so
  // the noise is counted, not selected from copies; the same σ̂ either way, and the same
  // threshold on one thread or two.
  const std::vector<double> t = time_axis(0.0, 0.5, 4001);
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> dither(-2, 2);
  std::vector<double> u(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) u[i] = (t[i] < 1000.0 ? 20.0 : 80.0) + dither(rng);
  StepDetectorOptions one, two;
  two.jobs = 2;
  const StepThreshold a = step_threshold(t, u, one);
  const StepThreshold b = step_threshold(t, u, two);
  EXPECT_NEAR(a.noise_sigma, selected_noise_sigma(u), 1e-12 * a.noise_sigma);
  EXPECT_EQ(a.noise_sigma, b.noise_sigma);
  EXPECT_EQ(a.largest_change, b.largest_change);
  EXPECT_EQ(a.threshold, b.threshold);
  EXPECT_EQ(a.band, b.band);
  EXPECT_NEAR(a.largest_change, 60.0, 4.0 + 1e-9);  // 20 → 80 rpm, each level ±2 rpm
}

TEST(StepDetector, ExactOnANoiseFreeCommand) {
  // A clean command (σ̂ = 0): the band shrinks to round-off, and a step of 1e-3 is found.
  const std::vector<double> t = time_axis(0.0, 1.0, 101);
  const std::vector<double> u = sample(t, [](double x) { return x < 40.0 ? 0.2 : 0.201; });
  const StepDetection found = detect_steps(t, u);
  ASSERT_EQ(found.steps.size(), 1u);
  EXPECT_EQ(found.steps.front().t_step, 40.0);
  EXPECT_EQ(found.noise_sigma, 0.0);
}

TEST(StepDetector, WindowsContainTheirStepOnADriftingCommand) {
  // A noise-free command that creeps after its step (an allocation re-solving as the vessel
  // gathers way): the creep (0.77 in 62 s) is a drift, not more steps. The window must begin
  // at or before the step and end after it, or the fit rejects the step with "step time not
  // inside the window".
  const std::vector<double> t = time_axis(0.0, 0.1, 1001);
  const std::vector<double> u = sample(t, [](double x) {
    if (x < 20.0) return 0.0;
    return x < 38.0 ? 40.0 : 40.0 + 2e-4 * (x - 38.0) * (x - 38.0);
  });
  const StepDetection found = detect_steps(t, u);
  ASSERT_EQ(found.steps.size(), 1u);
  EXPECT_NEAR(found.steps.front().t_step, 20.0, 0.1);
  for (const Step& s : found.steps) {
    EXPECT_LE(s.t_begin, s.t_step);
    EXPECT_LT(s.t_step, s.t_end);
  }
}

TEST(StepDetector, TriggerGivesTheOnsetOfAFirstOrderResponse) {
  // Power feedback with no command logged: P = 100 kW + 400 kW·(1 − e^{−(t − 30)/τ}), τ = 1 s,
  // noise σ = 2 kW, 50 Hz. The onset line through the samples up to 30 % of the change is
  // tangent-like: for a concave rise it meets the old level at or before the true onset,
  // never after; the chord from the band exit (≈ 2.5 % of the change) to 30 % lands within
  // about 0.01τ early, and noise in ~15 samples adds a few hundredths of τ. Bound: [−0.1, +0.02] s.
  const std::vector<double> t = time_axis(0.0, 0.02, 5001);
  const std::vector<double> p = sample(
      t, [](double x) { return x < 30.0 ? 100e3 : 100e3 + 400e3 * (1.0 - std::exp(-(x - 30.0))); },
      2e3, 21);
  StepDetectorOptions options;
  options.timing = StepTiming::kTrigger;
  const StepDetection found = detect_steps(t, p, options);
  ASSERT_EQ(found.steps.size(), 1u);
  EXPECT_GT(found.steps.front().t_step, 30.0 - 0.1);
  EXPECT_LT(found.steps.front().t_step, 30.0 + 0.02);
  // The end of the transition is the first sample within the band (±5σ̂ ≈ ±10 kW) of the new
  // level. Noise-free that is at 30 + τ·ln(400/10) = 33.7 s; noise can only move it by the
  // time the response needs to change by a few σ there (≈ 0.5 s). At 1τ (31 s) the response
  // is still 147 kW from its level, far outside the band.
  EXPECT_GT(found.steps.front().t_ramp_end, 31.0);
  EXPECT_LT(found.steps.front().t_ramp_end, 34.5);
}

TEST(StepDetector, ExplicitWindows) {
  const std::vector<double> t = time_axis(0.0, 0.01, 70001, 0.3, 3);
  const std::vector<double> u = sample(
      t, [](double x) { return command(kProgramme, x); }, 0.002, 4);
  // Detection inside a window around one step; the window is kept as given.
  const Step one = step_from_window(t, u, window(200.0, 380.0));
  EXPECT_NEAR(one.t_step, 250.0, 0.02);
  EXPECT_EQ(one.t_begin, 200.0);
  EXPECT_EQ(one.t_end, 380.0);
  // A given step time: levels are the medians either side (the ramp shifts the median of
  // 130 s of samples by nothing, being 3 s of 130 s above the median).
  const Step given = step_from_window(t, u, window(200.0, 380.0, 250.0));
  EXPECT_EQ(given.t_step, 250.0);
  EXPECT_NEAR(*given.u_before, 0.10, 2e-4);
  EXPECT_NEAR(*given.u_after, 0.40, 2e-4);
  // No input logged: the levels are missing, not zero.
  const Step bare = step_from_window(t, {}, window(200.0, 380.0, 250.0));
  EXPECT_FALSE(bare.u_before.has_value());
  EXPECT_FALSE(bare.delta_u().has_value());
}

// Real orders at 2 Hz (an azimuth in degrees): the traps of a sea-trial log.
const std::vector<double> kTwoHz = time_axis(0.0, 0.5, 2401);  // 20 min

// `moves` plus a held offset, uniform in ±amplitude and redrawn every `every_s` seconds while
// the order holds (none during the ramps): the wiggles of a held order.
std::vector<double> wiggled(const std::vector<Move>& moves, double amplitude, double every_s,
                            std::uint64_t seed) {
  testing::Normal rng(seed);
  std::vector<double> u;
  double offset = 0.0;
  double next = 0.0;
  for (const double x : kTwoHz) {
    const bool ramping = std::any_of(moves.begin(), moves.end(), [x](const Move& m) {
      return x >= m.at && x <= m.at + m.ramp + 0.5;
    });
    if (x >= next) {
      offset = amplitude * (2.0 * rng.uniform() - 1.0);
      next = x + every_s;
    }
    u.push_back(command(moves, x) + (ramping ? 0.0 : offset));
  }
  return u;
}

TEST(StepDetector, WigglesAndDitherOfAHeldOrderAreNoSteps) {
  // Dither: a new value in 30 ± 1° every sample. σ̂ ≈ 0.58° sets the band h ≈ 2.9°.
  const StepDetection dither = detect_steps(kTwoHz, wiggled({{0.0, 30.0, 30.0, 0.0}}, 1.0, 0.1, 3));
  EXPECT_TRUE(dither.steps.empty()) << dither.steps.size() << " steps";
  // Held wiggles of ±1° (redrawn every 5 s) in a programme 0 → 35 → −35 → 0°: the 70° change
  // sets the threshold to 3.5°, above the 2° the wiggles move at most, and the three orders
  // are found, ramps over 4 or 6 samples timed at their start (the line through the ramp
  // samples, which the offsets leave alone: within one sample, 0.5 s, of the true start).
  const std::vector<Move> zigzag{
      {100.0, 0.0, 35.0, 2.0}, {400.0, 35.0, -35.0, 3.0}, {800.0, -35.0, 0.0, 2.0}};
  const StepDetection found = detect_steps(kTwoHz, wiggled(zigzag, 1.0, 5.0, 4));
  EXPECT_NEAR(found.threshold, 3.5, 0.2);
  ASSERT_EQ(found.steps.size(), zigzag.size());
  for (std::size_t k = 0; k < zigzag.size(); ++k) {
    EXPECT_NEAR(found.steps[k].t_step, zigzag[k].at, 0.5);
    // Levels are medians of held values uniform in ±1°: within 0.5° for ≥ 40 of them.
    EXPECT_NEAR(*found.steps[k].delta_u(), zigzag[k].to - zigzag[k].from, 1.0);
  }
}

TEST(StepDetector, RampOverFourSamplesIsOneStepTimedAtItsStart) {
  // 0 → 30° from 100.2 s over 2 s: four samples on the ramp at 2 Hz. The samples lie on the
  // ramp exactly, so the line through them gives its start and end to round-off.
  const std::vector<double> u = sample(kTwoHz, [](double x) {
    return command({{100.2, 0.0, 30.0, 2.0}}, x);
  });
  const StepDetection found = detect_steps(kTwoHz, u);
  ASSERT_EQ(found.steps.size(), 1u);
  EXPECT_NEAR(found.steps[0].t_step, 100.2, 1e-9);
  EXPECT_NEAR(found.steps[0].t_ramp_end, 102.2, 1e-9);
  EXPECT_EQ(*found.steps[0].u_after, 30.0);
}

// An order that ramps fast and slows to its new level (a first-order-like ramp): the line
// through its 10–90 % samples reaches back before the ramp's start. A command's step time is
// never before its last sample at the old level (600.0 s; the ramp starts at 600.05 s). A
// 20 min log at 10 Hz: the ramp's 100 samples are among the 2 % of differences the noise
// estimate leaves out, so σ̂ is the held order's, 0, and the bound is exact.
TEST(StepDetector, ACurvedRampIsNeverTimedBeforeTheLastSampleAtTheOldLevel) {
  const std::vector<double> t = time_axis(0.0, 0.1, 12001);
  const std::vector<double> u = sample(t, [](double x) {
    const double s = std::clamp((x - 600.05) / 10.0, 0.0, 1.0);
    return 20.0 * (1.0 - (1.0 - s) * (1.0 - s));
  });
  const StepDetection found = detect_steps(t, u);
  ASSERT_EQ(found.steps.size(), 1u);
  EXPECT_EQ(found.noise_sigma, 0.0);
  EXPECT_GE(found.steps[0].t_step, 600.0);
  EXPECT_LE(found.steps[0].t_step, 600.1);
}

// Every reported step changes the input by at least the threshold between the levels it
// reports: random programmes of holds, ramps, drifts and jumps of every size around the
// threshold, with noise.
TEST(StepDetector, EveryStepReportedChangesTheLevelByTheThreshold) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const std::vector<double> t = time_axis(0.0, 0.5, 4001);
  std::size_t steps = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> u(t.size());
    double level = 0.0, rate = 0.0;
    std::normal_distribution<double> noise(0.0, 0.02 * unit(rng));
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (unit(rng) < 0.01) level += 4.0 * (unit(rng) - 0.5);  // jumps of up to ±2
      if (unit(rng) < 0.005) rate = 0.02 * (unit(rng) - 0.5);  // drifts of up to 0.01/s
      level += rate * 0.5;
      u[i] = level + noise(rng);
    }
    StepDetectorOptions options;
    options.min_step = 1.0;
    const StepDetection found = detect_steps(t, u, options);
    for (const Step& step : found.steps) {
      ++steps;
      EXPECT_GE(std::abs(*step.delta_u()), found.threshold) << trial << " at " << step.t_step;
    }
  }
  EXPECT_GT(steps, 200u);  // the programmes do have steps
}

TEST(StepDetector, ReSettlingAfterAStepIsPartOfIt) {
  // The order is set to 33.3°, held for 2, 5 or 8 s, and re-settled to 30.7° (a change back
  // of 2.6°, above the 1.7° threshold of this log but 8 % of the step): one step to 30.7°.
  for (const double hold_s : {2.0, 5.0, 8.0}) {
    SCOPED_TRACE(hold_s);
    const std::vector<double> u = sample(
        kTwoHz,
        [hold_s](double x) {
          return command({{100.0, 0.0, 33.3, 1.5}, {101.5 + hold_s, 33.3, 30.7, 0.0}}, x);
        },
        0.02, 5);
    const StepDetection found = detect_steps(kTwoHz, u);
    ASSERT_EQ(found.steps.size(), 1u);
    EXPECT_NEAR(found.steps[0].t_step, 100.0, 0.5);
    // The median of ≥ 2 000 samples with σ = 0.02°.
    EXPECT_NEAR(*found.steps[0].u_after, 30.7, 0.01);
  }
}

TEST(StepDetector, SlowDriftIsNoStep) {
  // A held order drifting 10° in 20 min, noise-free and with σ = 0.05°: no step, though it
  // changes by 20 times the threshold.
  for (const double sigma : {0.0, 0.05}) {
    SCOPED_TRACE(sigma);
    const auto drift = [](double x) { return 10.0 * x / 1200.0; };
    const StepDetection none = detect_steps(kTwoHz, sample(kTwoHz, drift, sigma, 6));
    EXPECT_TRUE(none.steps.empty()) << none.steps.size() << " steps";
    // The same drift with one 30° order at 600 s: that one step only.
    const std::vector<double> u = sample(
        kTwoHz, [&](double x) { return drift(x) + (x < 600.0 ? 0.0 : 30.0); }, sigma, 6);
    const StepDetection one = detect_steps(kTwoHz, u);
    ASSERT_EQ(one.steps.size(), 1u);
    EXPECT_NEAR(one.steps[0].t_step, 600.0, 0.5);
  }
}

TEST(StepDetector, BadInputIsAnInputError) {
  const std::vector<double> t = time_axis(0.0, 0.1, 1001);
  StepDetectorOptions named;
  named.input_name = "rudder_cmd";
  // No step is a result, not an error: an empty list and the reason.
  const std::vector<double> flat(t.size(), 0.3);
  EXPECT_THAT(detect_steps(t, flat, named).message, ::testing::HasSubstr("constant input"));
  // Non-constant but one level only: a single large spike.
  std::vector<double> spike = flat;
  spike[300] = 5.0;
  EXPECT_THAT(detect_steps(t, spike).message, ::testing::HasSubstr("one level only"));
  // Never settles: a clean ramp changes by 0.03 in 3 s, over four times the 2h = 0.007 that
  // its constant differences give (σ̂ = 0.001/√2, h = 5σ̂), so it holds no level for 3 s.
  const std::vector<double> wave = sample(t, [](double x) { return 0.01 * x; });
  const StepDetection ramp = detect_steps(t, wave);
  EXPECT_TRUE(ramp.steps.empty());
  EXPECT_THAT(ramp.message, ::testing::HasSubstr("never holds a level"));
  const std::vector<double> nan(t.size(), std::nan(""));
  EXPECT_THROW_MATCHING(detect_steps(t, nan), InputError, "only 0 valid input samples");
  EXPECT_THROW_MATCHING(detect_steps(t, std::vector<double>(5, 1.0)), InputError,
                        "has 5 samples but the time axis has 1001");
  std::vector<double> t_bad = t;
  t_bad[10] = t_bad[9];
  EXPECT_THROW_MATCHING(detect_steps(t_bad, flat), InputError,
                        "not strictly increasing at index 10");

  const std::vector<double> u = sample(t, [](double x) { return x < 50.0 ? 0.0 : 1.0; });
  EXPECT_THROW_MATCHING(step_from_window(t, u, window(-10.0, 60.0)), InputError,
                        R"(window \[-10, 60\] s is outside the log \[0, 100\] s)");
  EXPECT_THROW_MATCHING(step_from_window(t, u, window(60.0, 40.0)), InputError,
                        "empty or reversed");
  EXPECT_THROW_MATCHING(step_from_window(t, u, window(10.0, 40.0)), InputError,
                        R"(constant input.* in the window \[10, 40\] s)");
  EXPECT_THROW_MATCHING(step_from_window(t, u, window(10.0, 40.0, 20.0)), InputError,
                        "constant input");
  EXPECT_THROW_MATCHING(step_from_window(t, u, window(10.0, 40.0, 45.0)), InputError,
                        "not inside the window");
  EXPECT_THROW_MATCHING(step_from_window(t, {}, window(10.0, 90.0)), InputError,
                        "no input and no step time");
  const std::vector<double> two = sample(t, [](double x) {
    return x < 30.0 ? 0.0 : x < 60.0 ? 1.0 : 0.0;
  });
  EXPECT_THROW_MATCHING(step_from_window(t, two, window(0.0, 100.0)), InputError,
                        "2 steps found in the window");
  // Rows of a window only (a log read within it): the log's reach is given, not the rows'.
  const auto in_window = [&](double from, double to) {
    std::vector<double> tw, uw;
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (t[i] >= from && t[i] <= to) {
        tw.push_back(t[i]);
        uw.push_back(u[i]);
      }
    }
    return std::pair{tw, uw};
  };
  const auto [tw, uw] = in_window(40.05, 60.0);
  const Step inner = step_from_window(tw, uw, window(40.05, 60.0, {}, 0.0, 100.0));
  EXPECT_NEAR(inner.t_step, 50.0, 0.1);
  EXPECT_EQ(inner.t_begin, 40.05);
  EXPECT_THROW_MATCHING(step_from_window(tw, uw, window(40.05, 160.0, {}, 0.0, 100.0)), InputError,
                        R"(window \[40.05, 160\] s is outside the log \[0, 100\] s)");
  EXPECT_THROW_MATCHING(step_from_window({}, {}, window(40.01, 40.02, {}, 0.0, 100.0)), InputError,
                        "holds no sample of the log");
  StepDetectorOptions bad;
  bad.min_plateau_s = 0.0;
  EXPECT_THROW_MATCHING(detect_steps(t, u, bad), InputError, "minimum plateau");
  bad = {};
  bad.band = -1.0;
  EXPECT_THROW_MATCHING(bad.validate(), InputError, "band");
}

// A long log for the scans in pieces: steps and ramps of many sizes every 150 s, a logging gap,
// a noisy hold of 900 s (a piece with no step, whose plateau runs in from the piece before) and
// a slow drift. 100 Hz with jitter, 3600 s.
std::vector<double> long_input(const std::vector<double>& t, double quantum) {
  std::vector<Move> moves;
  double level = 0.0;
  for (int k = 0; k < 12; ++k) {
    const double to = 0.05 * ((k * 7) % 11) - 0.2;
    moves.push_back({100.0 + 150.0 * k, level, to, k % 3 == 0 ? 0.0 : 0.5 * k});
    level = to;
  }
  std::vector<double> u = sample(
      t,
      [&](double x) {
        const double drift = x > 2900.0 ? 2e-5 * (x - 2900.0) : 0.0;
        return command(moves, std::min(x, 1900.0)) + drift;
      },
      0.002, 21);
  if (quantum > 0.0) {
    for (double& x : u) x = quantum * std::round(x / quantum);
  }
  return u;
}

void expect_same_detection(const StepDetection& a, const StepDetection& b,
                           const std::string& what) {
  EXPECT_EQ(a.noise_sigma, b.noise_sigma) << what;
  EXPECT_EQ(a.band, b.band) << what;
  EXPECT_EQ(a.threshold, b.threshold) << what;
  EXPECT_EQ(a.message, b.message) << what;
  ASSERT_EQ(a.steps.size(), b.steps.size()) << what;
  for (std::size_t k = 0; k < a.steps.size(); ++k) {
    const Step& x = a.steps[k];
    const Step& y = b.steps[k];
    EXPECT_EQ(x.t_step, y.t_step) << what << " step " << k;
    EXPECT_EQ(x.t_ramp_end, y.t_ramp_end) << what << " step " << k;
    EXPECT_EQ(x.t_begin, y.t_begin) << what << " step " << k;
    EXPECT_EQ(x.t_end, y.t_end) << what << " step " << k;
    EXPECT_EQ(x.u_before, y.u_before) << what << " step " << k;
    EXPECT_EQ(x.u_after, y.u_after) << what << " step " << k;
  }
}

// The plateaus and the largest change are scanned in pieces, one per thread, and joined: the
// steps, levels, times and threshold are the same on any number of threads, to the bit. With 16
// threads the 360 000 samples are cut into 16 pieces; the noisy hold has pieces with no step.
TEST(StepDetector, SameStepsOnAnyNumberOfThreads) {
  const std::vector<double> t = time_axis(0.0, 0.01, 360'001, 0.3, 17);
  for (const double quantum : {0.0, 0.001}) {  // selected noise, and counted (a quantized order)
    std::vector<double> u = long_input(t, quantum);
    if (quantum == 0.0) make_gap(t, u, 1210.0, 1214.0);
    StepDetectorOptions one;
    const StepDetection serial = detect_steps(t, u, one);
    ASSERT_GE(serial.steps.size(), 10u);
    for (unsigned jobs : {2u, 3u, 8u, 16u}) {
      StepDetectorOptions many;
      many.jobs = jobs;
      expect_same_detection(serial, detect_steps(t, u, many),
                            "quantum " + std::to_string(quantum) + ", " + std::to_string(jobs));
      const StepThreshold a = step_threshold(t, u, one);
      const StepThreshold b = step_threshold(t, u, many);
      EXPECT_EQ(a.largest_change, b.largest_change);
      EXPECT_EQ(a.noise_sigma, b.noise_sigma);
    }
  }
}

// The steps of a log's channel: the same as of its time axis and values, missing samples
// (counted in pieces) and a gap included; the log checked its own time axis, and a channel of
// another length is still refused.
TEST(StepDetector, StepsOfALogChannelAreThoseOfItsAxisAndValues) {
  std::vector<double> t = time_axis(0.0, 0.01, 360'001, 0.3, 17);
  std::vector<double> u = long_input(t, 0.0);
  make_gap(t, u, 1210.0, 1214.0);
  for (std::size_t i = 1000; i < u.size(); i += 70'001) u[i] = std::nan("");
  core::Log log(t);
  log.add_channel("input", "1", u);
  for (unsigned jobs : {1u, 3u}) {
    StepDetectorOptions options;
    options.jobs = jobs;
    const StepDetection of_spans = detect_steps(t, u, options);
    ASSERT_GE(of_spans.steps.size(), 10u);
    expect_same_detection(of_spans, detect_steps(log, log.values("input"), options),
                          "log, " + std::to_string(jobs));
  }
  const std::vector<double> shorter(u.begin(), u.end() - 1);
  EXPECT_THROW(detect_steps(log, shorter), core::InputError);
}

// detect_steps() finds the threshold and the steps with one check and scan of the input: the
// same as step_threshold() followed by detect_steps() on that threshold. The noise of a gap-free
// quantized order is counted once from its differences (σ̂ from their median, MAD and trimmed
// squares); with one missing sample at the end the separate passes run, and give the same σ̂.
TEST(StepDetector, OnePassGivesWhatTheThresholdAndTheDetectionGiveApart) {
  const std::vector<double> t = time_axis(0.0, 0.01, 360'001, 0.3, 17);
  const std::vector<double> u = long_input(t, 0.001);
  StepDetectorOptions options;
  options.jobs = 2;
  const StepThreshold scale = step_threshold(t, u, options);
  expect_same_detection(detect_steps(t, u, options), detect_steps(t, u, options, scale), "apart");
  std::vector<double> t_more = t, u_more = u;
  t_more.push_back(t.back() + 0.01);
  u_more.push_back(std::nan(""));
  const StepThreshold passes = step_threshold(t_more, u_more, options);
  EXPECT_EQ(scale.noise_sigma, passes.noise_sigma);
  EXPECT_NEAR(scale.noise_sigma, selected_noise_sigma(u), 1e-12 * scale.noise_sigma);
}

// S by its definition: the largest range of the 3-sample running median over every window
// [tᵢ, tᵢ + w], each window taken whole.
double largest_change_by_definition(const std::vector<double>& t, const std::vector<double>& u,
                                    double w) {
  const auto m = [&](std::size_t i) {
    if (i == 0 || i + 1 >= u.size()) return u[i];
    return std::max(std::min(u[i - 1], u[i]), std::min(std::max(u[i - 1], u[i]), u[i + 1]));
  };
  double s = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    double lo = m(i), hi = m(i);
    for (std::size_t j = i + 1; j < t.size() && t[j] <= t[i] + w; ++j) {
      lo = std::min(lo, m(j));
      hi = std::max(hi, m(j));
    }
    s = std::max(s, hi - lo);
  }
  return s;
}

// The largest change skips the blocks of windows that cannot hold a larger range than the one
// found: S is still the largest range of any window, on steps, spikes, ramps and flat stretches,
// and for a clean step placed anywhere against the blocks.
TEST(StepDetector, LargestChangeIsTheLargestRangeOfAnyWindow) {
  const std::vector<double> t = time_axis(0.0, 0.1, 60'001, 0.3, 5);
  std::vector<double> u = sample(
      t,
      [](double x) {
        // Steps of 0.3, 0.2 and then 0.35, all in the last of the three pieces a scan of 60 000
        // samples is cut into: the block that holds the largest change comes after blocks whose
        // ranges are nearly as large.
        double v = x < 4300.0 ? 0.0 : (x < 4800.0 ? 0.3 : (x < 5400.0 ? 0.1 : 0.45));
        if (x > 1000.0 && x < 1100.0) v += 0.001 * (x - 1000.0);  // a ramp over 100 s
        return v;
      },
      0.01, 6);
  u[25'000] += 5.0;  // a spike: one sample, which the running median drops
  u[26'001] += 0.1;  // ... and a two-sample one, which it keeps
  u[26'002] += 0.1;
  for (unsigned jobs : {1u, 3u}) {
    StepDetectorOptions options;
    options.jobs = jobs;
    const double s = largest_change_by_definition(t, u, options.change_window_s);
    EXPECT_GT(s, 0.35);  // set by the last step
    EXPECT_EQ(step_threshold(t, u, options).largest_change, s) << jobs;
  }
  const std::vector<double> t_clean = time_axis(0.0, 0.1, 20'001);
  for (const std::size_t at : {511u, 512u, 513u, 9'000u, 19'990u}) {
    const std::vector<double> u_clean =
        sample(t_clean, [&](double x) { return x < t_clean[at] ? 0.0 : 0.125; });
    EXPECT_EQ(step_threshold(t_clean, u_clean).largest_change, 0.125) << at;
  }
}

}  // namespace
}  // namespace dynpos::ident
