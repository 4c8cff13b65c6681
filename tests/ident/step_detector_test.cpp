#include "dynpos/ident/step_detector.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "dynpos/core/error.hpp"
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
  // A min_step larger than the step leaves nothing: an error, not an empty list.
  StepDetectorOptions coarse;
  coarse.min_step = 1.05;  // above the step, below the range with spikes (1.07)
  EXPECT_THROW_MATCHING(detect_steps(t, u, coarse), InputError, "no step found");
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
  // gathers way): the band is round-off, so the creep may be cut into small steps whose ramps
  // meet. Every window must still begin at or before its step and end after it, or the fit
  // rejects the step with "step time not inside the window".
  const std::vector<double> t = time_axis(0.0, 0.1, 1001);
  const std::vector<double> u = sample(t, [](double x) {
    if (x < 20.0) return 0.0;
    return x < 38.0 ? 40.0 : 40.0 + 2e-4 * (x - 38.0) * (x - 38.0);
  });
  const StepDetection found = detect_steps(t, u);
  ASSERT_GE(found.steps.size(), 2u);
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
  const Step one = step_from_window(t, u, {200.0, 380.0, {}});
  EXPECT_NEAR(one.t_step, 250.0, 0.02);
  EXPECT_EQ(one.t_begin, 200.0);
  EXPECT_EQ(one.t_end, 380.0);
  // A given step time: levels are the medians either side (the ramp shifts the median of
  // 130 s of samples by nothing, being 3 s of 130 s above the median).
  const Step given = step_from_window(t, u, {200.0, 380.0, 250.0});
  EXPECT_EQ(given.t_step, 250.0);
  EXPECT_NEAR(*given.u_before, 0.10, 2e-4);
  EXPECT_NEAR(*given.u_after, 0.40, 2e-4);
  // No input logged: the levels are missing, not zero.
  const Step bare = step_from_window(t, {}, {200.0, 380.0, 250.0});
  EXPECT_FALSE(bare.u_before.has_value());
  EXPECT_FALSE(bare.delta_u().has_value());
}

TEST(StepDetector, BadInputIsAnInputError) {
  const std::vector<double> t = time_axis(0.0, 0.1, 1001);
  StepDetectorOptions named;
  named.input_name = "rudder_cmd";
  const std::vector<double> flat(t.size(), 0.3);
  EXPECT_THROW_MATCHING(detect_steps(t, flat, named), InputError,
                        R"(\(rudder_cmd\): constant input)");
  // Non-constant but one level only: a single large spike.
  std::vector<double> spike = flat;
  spike[300] = 5.0;
  EXPECT_THROW_MATCHING(detect_steps(t, spike), InputError, "no step found: .* one level only");
  // Never settles: a clean ramp (σ̂ = 0, so the band is round-off) holds no level for 3 s.
  const std::vector<double> wave = sample(t, [](double x) { return 0.01 * x; });
  EXPECT_THROW_MATCHING(detect_steps(t, wave), InputError, "never holds a level");
  const std::vector<double> nan(t.size(), std::nan(""));
  EXPECT_THROW_MATCHING(detect_steps(t, nan), InputError, "only 0 valid input samples");
  EXPECT_THROW_MATCHING(detect_steps(t, std::vector<double>(5, 1.0)), InputError,
                        "has 5 samples but the time axis has 1001");
  std::vector<double> t_bad = t;
  t_bad[10] = t_bad[9];
  EXPECT_THROW_MATCHING(detect_steps(t_bad, flat), InputError,
                        "not strictly increasing at index 10");

  const std::vector<double> u = sample(t, [](double x) { return x < 50.0 ? 0.0 : 1.0; });
  EXPECT_THROW_MATCHING(step_from_window(t, u, {-10.0, 60.0, {}}), InputError,
                        R"(window \[-10, 60\] s is outside the log \[0, 100\] s)");
  EXPECT_THROW_MATCHING(step_from_window(t, u, {60.0, 40.0, {}}), InputError, "empty or reversed");
  EXPECT_THROW_MATCHING(step_from_window(t, u, {10.0, 40.0, {}}), InputError,
                        R"(constant input.* in the window \[10, 40\] s)");
  EXPECT_THROW_MATCHING(step_from_window(t, u, {10.0, 40.0, 20.0}), InputError, "constant input");
  EXPECT_THROW_MATCHING(step_from_window(t, u, {10.0, 40.0, 45.0}), InputError,
                        "not inside the window");
  EXPECT_THROW_MATCHING(step_from_window(t, {}, {10.0, 90.0, {}}), InputError,
                        "no input and no step time");
  const std::vector<double> two = sample(t, [](double x) {
    return x < 30.0 ? 0.0 : x < 60.0 ? 1.0 : 0.0;
  });
  EXPECT_THROW_MATCHING(step_from_window(t, two, {0.0, 100.0, {}}), InputError,
                        "2 steps found in the window");
  StepDetectorOptions bad;
  bad.min_plateau_s = 0.0;
  EXPECT_THROW_MATCHING(detect_steps(t, u, bad), InputError, "minimum plateau");
  bad = {};
  bad.band = -1.0;
  EXPECT_THROW_MATCHING(bad.validate(), InputError, "band");
}

}  // namespace
}  // namespace dynpos::ident
