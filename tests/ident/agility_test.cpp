#include "dynpos/ident/agility.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "dynpos/core/error.hpp"
#include "synthetic.hpp"

namespace dynpos::ident {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A FOPDT step response (3.7) of amplitude a, dead time d, time constant tc from t0.
double fopdt(double t, double t0, double a, double d, double tc) {
  return t < t0 + d ? 0.0 : a * (1.0 - std::exp(-(t - t0 - d) / tc));
}

// A rate-limited step: a straight ramp over `ramp` seconds after a dead time d.
double ramp(double t, double t0, double a, double d, double ramp_s) {
  return a * std::clamp((t - t0 - d) / ramp_s, 0.0, 1.0);
}

// A 200 s log at 10 Hz: 50 % thrust towards 45° at 20-60 s, 100 % towards 90° at 100-140 s.
struct Trial {
  std::vector<double> t, surge, sway, yaw, a, b, c, speed;
};

Trial make_trial(double noise_a = 0.0) {
  Trial x;
  testing::Normal rng(7);
  for (int k = 0; k <= 2000; ++k) {
    const double t = 0.1 * k;
    x.t.push_back(t);
    const bool s1 = t >= 20.0 && t < 60.0;
    const bool s2 = t >= 100.0 && t < 140.0;
    x.surge.push_back(s1 ? 35.355 : 0.0);
    x.sway.push_back(s1 ? 35.355 : (s2 ? 100.0 : 0.0));
    x.yaw.push_back(0.0);
    // Thruster a: FOPDT δ = 1.5 s, T = 3 s in both steps (decays after each step ends).
    double a = 0.0;
    if (t >= 20.0) a = fopdt(t, 20.0, 40e3, 1.5, 3.0) - fopdt(t, 60.0, 40e3, 1.5, 3.0);
    if (t >= 100.0) a = fopdt(t, 100.0, 40e3, 1.5, 3.0) - fopdt(t, 140.0, 40e3, 1.5, 3.0);
    x.a.push_back(a + noise_a * rng());
    // Thruster b: a ramp over 6 s after 1 s (rate-limited), down the same way.
    double b = 0.0;
    if (t >= 20.0) b = ramp(t, 20.0, -30e3, 1.0, 6.0) - ramp(t, 60.0, -30e3, 1.0, 6.0);
    if (t >= 100.0) b = ramp(t, 100.0, -30e3, 1.0, 6.0) - ramp(t, 140.0, -30e3, 1.0, 6.0);
    x.b.push_back(b);
    // Thruster c: idle in the first step, a FOPDT in the second; logged at 1 Hz only.
    const double c =
        t >= 100.0 ? fopdt(t, 100.0, 20e3, 1.0, 2.0) - fopdt(t, 140.0, 20e3, 1.0, 2.0) : 0.0;
    x.c.push_back(k % 10 == 0 ? c : kNaN);
    // Speed: first order with T = 5 s in the step (no dead time).
    double u = 0.0;
    if (t >= 20.0) u = fopdt(t, 20.0, 1.0, 0.0, 5.0) - fopdt(t, 60.0, 1.0, 0.0, 5.0);
    if (t >= 100.0) u = fopdt(t, 100.0, 1.0, 0.0, 5.0) - fopdt(t, 140.0, 1.0, 0.0, 5.0);
    x.speed.push_back(u);
  }
  return x;
}

// The exact 63.2 % time of a FOPDT when y∞ is the mean of the response over [t_from, t_to]
// (times from the step): solve A(1 − e^{−(τ−δ)/T}) = 0.632·ȳ.
double fopdt_t63(double d, double tc, double t_from, double t_to) {
  const double mean =
      1.0 - tc * (std::exp(-(t_from - d) / tc) - std::exp(-(t_to - d) / tc)) / (t_to - t_from);
  return d - tc * std::log(1.0 - 0.632 * mean);
}

TEST(Agility, FindsStepsAndDirections) {
  const Trial x = make_trial();
  const auto steps = find_agility_steps(x.t, {x.surge, x.sway, x.yaw});
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_NEAR(steps[0].direction_deg, 45.0, 1e-3);
  EXPECT_NEAR(steps[0].magnitude_pct, 50.0, 1e-3);
  EXPECT_DOUBLE_EQ(steps[0].t_step, 20.0);
  EXPECT_NEAR(steps[0].t_end, 59.9, 1e-9);  // the last sample before the return to zero
  EXPECT_NEAR(steps[1].direction_deg, 90.0, 1e-9);
  EXPECT_NEAR(steps[1].magnitude_pct, 100.0, 1e-9);
  ASSERT_TRUE(steps[1].yaw_pct.has_value());
  EXPECT_EQ(agility_case_label(steps[0]), "50 % thrust, no yaw");
  EXPECT_EQ(agility_case_label(steps[1]), "100 % thrust, no yaw");
}

TEST(Agility, DirectionConventionIsCompassLike) {
  // 0 = ahead, 90 = starboard, 180 = astern, −90 = port, −135 = astern to port.
  const std::vector<std::pair<std::pair<double, double>, double>> cases = {
      {{50, 0}, 0.0}, {{0, 50}, 90.0}, {{-50, 0}, 180.0}, {{0, -50}, -90.0}, {{-35, -35}, -135.0}};
  for (const auto& [cmd, expected] : cases) {
    std::vector<double> t, su, sw;
    for (int k = 0; k < 200; ++k) {
      t.push_back(0.1 * k);
      su.push_back(k >= 50 ? cmd.first : 0.0);
      sw.push_back(k >= 50 ? cmd.second : 0.0);
    }
    const auto steps = find_agility_steps(t, {su, sw, {}});
    ASSERT_EQ(steps.size(), 1u);
    EXPECT_NEAR(steps[0].direction_deg, expected, 1e-9);
    EXPECT_FALSE(steps[0].yaw_pct.has_value());
    EXPECT_EQ(agility_case_label(steps[0]), "50 % thrust, yaw not logged");
  }
}

TEST(Agility, ResponseTimesMatchAnalyticFopdtAndRamp) {
  const Trial x = make_trial();
  const std::vector<AgilityChannel> ch = {{"a", x.a, {}}, {"b", x.b, {}}, {"c", x.c, {}}};
  const AgilityResult r = analyse_agility(x.t, {x.surge, x.sway, x.yaw}, ch, x.speed);
  ASSERT_EQ(r.status, FitStatus::kOk) << r.message;
  ASSERT_EQ(r.steps.size(), 2u);
  // y∞ is the mean over the last 20 % of the 39.9 s window: 31.92 … 39.9 s after the step.
  const double a63 = fopdt_t63(1.5, 3.0, 31.92, 39.9);
  EXPECT_NEAR(a63, 4.5, 0.01);  // δ + T, the tail being settled
  for (const AgilityStep& s : r.steps) {
    ASSERT_EQ(s.thrusters.size(), 3u);
    // Noise-free 10 Hz samples of a smooth curve: linear interpolation between samples is
    // exact to the curvature error, (Δt)²·|y''|/8 / |y'| < 0.01 s here.
    ASSERT_TRUE(s.thrusters[0].response_s);
    EXPECT_NEAR(*s.thrusters[0].response_s, a63, 0.01);
    // The ramp: δ + 0.632·ramp = 1 + 0.632·6 = 4.792 s, exact for a straight line.
    ASSERT_TRUE(s.thrusters[1].response_s);
    EXPECT_NEAR(*s.thrusters[1].response_s, 1.0 + 0.632 * 6.0, 1e-6);
    EXPECT_TRUE(s.thrusters[1].notes.empty());
    EXPECT_EQ(s.thrusters[1].crossing_span_s, 0.0);  // monotone: one crossing
    ASSERT_TRUE(s.speed && s.speed->response_s);
    EXPECT_NEAR(*s.speed->response_s, fopdt_t63(0.0, 5.0, 31.92, 39.9), 0.01);
  }
  // Thruster c does not move in the first step: absent, never 0.
  EXPECT_FALSE(r.steps[0].thrusters[2].response_s.has_value());
  EXPECT_THAT(r.steps[0].thrusters[2].notes.at(0), ::testing::HasSubstr("no response"));
  // At 1 Hz the crossing is interpolated on a coarse grid: the chord of 1 − e^{−τ/2} between
  // samples 1 s apart lies below the curve by up to (1 s)²·|y''|/8, which shifts the crossing
  // late by at most ≈ 0.25 s at the 63.2 % level (y''/y' = −1/T = −0.5 1/s).
  const double c63 = fopdt_t63(1.0, 2.0, 31.92, 39.9);
  ASSERT_TRUE(r.steps[1].thrusters[2].response_s);
  EXPECT_NEAR(*r.steps[1].thrusters[2].response_s, c63, 0.25);
}

TEST(Agility, NoiseMovesTheCrossingLittle) {
  // 1 % noise (400 N) on a 40 kN response: the slope at the crossing is 0.368·40 kN/3 s =
  // 4.9 kN/s, so one σ of noise is 0.08 s of time; 0.3 s is about 4σ.
  const Trial x = make_trial(400.0);
  const std::vector<AgilityChannel> ch = {{"a", x.a, {}}};
  const AgilityResult r = analyse_agility(x.t, {x.surge, x.sway, x.yaw}, ch, {});
  ASSERT_EQ(r.steps.size(), 2u);
  for (const AgilityStep& s : r.steps) {
    ASSERT_TRUE(s.thrusters[0].response_s);
    EXPECT_NEAR(*s.thrusters[0].response_s, fopdt_t63(1.5, 3.0, 31.92, 39.9), 0.3);
    EXPECT_FALSE(s.speed.has_value());
  }
}

TEST(Agility, WindowsGiveTheSameAnswer) {
  const Trial x = make_trial();
  const std::vector<AgilityChannel> ch = {{"b", x.b, {}}};
  const std::vector<AgilityWindow> w = {{100.0, 139.9, 90.0, 100.0, 0.0},
                                        {20.0, 59.9, 45.0, 50.0, {}}};
  const AgilityResult r = analyse_agility(x.t, w, ch, {});
  ASSERT_EQ(r.steps.size(), 2u);
  EXPECT_DOUBLE_EQ(r.steps[0].t_step, 20.0);  // sorted by time
  EXPECT_NEAR(*r.steps[0].thrusters[0].response_s, 4.792, 1e-6);
  EXPECT_NEAR(*r.steps[1].thrusters[0].response_s, 4.792, 1e-6);
}

TEST(Agility, SwingingResponseGivesTheMidpointAndSpanOfItsCrossings) {
  // 1 Hz, step at 0: 0 before; 0.5/0.7 alternating for 1–31 s (through the 63.2 % level at
  // every rise), then 0.9/1.1 alternating (mean 1.0 over the tail, 32–39 s). The first
  // crossing from below is at 1 + 0.132/0.2 = 1.66 s, the last at 31 + 0.132/0.4 = 31.33 s;
  // the swings keep the response under the clearing level 0.632 + 3σ (σ ≈ 0.21 from the
  // ±0.2 differences), so every rise counts.
  std::vector<double> t, y;
  for (int k = -5; k <= 39; ++k) {
    t.push_back(k);
    if (k <= 0) {
      y.push_back(0.0);
    } else if (k <= 31) {
      y.push_back(k % 2 == 1 ? 0.5 : 0.7);
    } else {
      y.push_back(k % 2 == 0 ? 0.9 : 1.1);
    }
  }
  const AgilityResponse r = response_time_632(t, y, 0.0, 39.0, 0.1, AgilityOptions{}, "a");
  ASSERT_TRUE(r.response_s);
  EXPECT_NEAR(r.crossing_span_s, 31.33 - 1.66, 1e-9);
  EXPECT_NEAR(*r.response_s, 0.5 * (1.66 + 31.33), 1e-9);
}

TEST(Agility, NotesAReversingResponse) {
  // Up to 40 kN after 1 s, then back to 5 kN: y∞ = 5 kN, the 63.2 % crossing is early and the
  // response overshoots its final level by far more than 30 %.
  std::vector<double> t, su, sw, y;
  for (int k = 0; k < 600; ++k) {
    const double tt = 0.1 * k;
    t.push_back(tt);
    su.push_back(tt >= 10.0 ? 50.0 : 0.0);
    sw.push_back(0.0);
    y.push_back(tt < 11.0 ? 0.0 : (tt < 20.0 ? 40e3 : 5e3));
  }
  const std::vector<AgilityChannel> ch = {{"a", y, {}}};
  const AgilityResult r = analyse_agility(t, {su, sw, {}}, ch, {});
  ASSERT_EQ(r.steps.size(), 1u);
  ASSERT_TRUE(r.steps[0].thrusters[0].response_s);
  EXPECT_THAT(r.steps[0].thrusters[0].notes,
              ::testing::Contains(::testing::HasSubstr("overshoot")));
}

TEST(Agility, BadInputIsAnInputError) {
  const Trial x = make_trial();
  const AgilityCommand cmd{x.surge, x.sway, x.yaw};
  const std::vector<AgilityChannel> ch = {{"a", x.a, {}}};
  EXPECT_THROW_MATCHING(analyse_agility(x.t, cmd, {}, {}), core::InputError, "no thruster channel");
  EXPECT_THROW_MATCHING(analyse_agility(x.t, AgilityCommand{}, ch, {}), core::InputError,
                        "no joystick demand");
  EXPECT_THROW_MATCHING(analyse_agility(x.t, std::span<const AgilityWindow>{}, ch, {}),
                        core::InputError, "no joystick demand and no step window");
  const std::vector<double> flat(x.t.size(), 50.0);
  EXPECT_THROW_MATCHING(analyse_agility(x.t, {flat, flat, {}}, ch, {}), core::InputError,
                        "constant");
  const std::vector<double> nan(x.t.size(), kNaN);
  const std::vector<AgilityChannel> bad = {{"a", nan, {}}};
  EXPECT_THROW_MATCHING(analyse_agility(x.t, cmd, bad, {}), core::InputError, "no valid sample");
  const std::vector<double> zero(x.t.size(), 0.0);
  EXPECT_THROW_MATCHING(analyse_agility(x.t, {zero, zero, {}}, ch, {}), core::InputError,
                        "constant");
  // A step held for 3 s only (the log ends): too short.
  std::vector<double> t, su;
  for (int k = 0; k < 230; ++k) {
    t.push_back(0.1 * k);
    su.push_back(k >= 200 ? 50.0 : 0.0);
  }
  const std::vector<double> sw(t.size(), 0.0), y(t.size(), 1.0);
  const std::vector<AgilityChannel> ych = {{"a", y, {}}};
  EXPECT_THROW_MATCHING(analyse_agility(t, {su, sw, {}}, ych, {}), core::InputError,
                        "step too short");
  // A window outside the log.
  const std::vector<AgilityWindow> w = {{150.0, 250.0, 0.0, 50.0, {}}};
  EXPECT_THROW_MATCHING(analyse_agility(x.t, w, ch, {}), core::InputError, "not inside the log");
  AgilityOptions o;
  o.tail_fraction = 0.8;
  EXPECT_THROW_MATCHING(o.validate(), core::InputError, "tail fraction");
}

TEST(Agility, ConstantOutputGivesNullNotZero) {
  const Trial x = make_trial();
  const std::vector<double> flat(x.t.size(), 1000.0);
  const std::vector<AgilityChannel> ch = {{"idle", flat, {}}};
  // A speed change of 0.03 m/s is below the 0.05 m/s a speed log resolves reliably.
  std::vector<double> creep;
  for (const double v : x.speed) creep.push_back(0.03 * v);
  const AgilityResult r = analyse_agility(x.t, {x.surge, x.sway, x.yaw}, ch, creep);
  EXPECT_EQ(r.status, FitStatus::kFailed);
  for (const AgilityStep& s : r.steps) {
    EXPECT_FALSE(s.thrusters[0].response_s.has_value());
    ASSERT_TRUE(s.speed.has_value());
    EXPECT_FALSE(s.speed->response_s.has_value());
  }
}

}  // namespace
}  // namespace dynpos::ident
