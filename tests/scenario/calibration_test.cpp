// The virtual Gunnerus against the thesis: run the built-in scenarios and check that the
// magnitudes land in the ranges of DESIGN.md's calibration table (thesis tables 3.2, 3.23–3.36).
// Responses are fitted with Smith's two-point method (3.8)–(3.9), timed from the command, the
// way the thesis read them off its plots.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <span>

#include "../source_dir.hpp"
#include "dynpos/core/circular_stats.hpp"
#include "dynpos/model/fopdt_truth.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/scenario/scenario_spec.hpp"

namespace dynpos::scenario {
namespace {

const std::filesystem::path kScenarios =
    std::filesystem::path(DYNPOS_SOURCE_DIR) / "data" / "scenarios";

// Smith fit of channel y between commands i and i+1 (the response to command i).
model::FopdtTruth fit_step(const core::Log& log, const std::vector<double>& y, double t_step,
                           double t_next) {
  const auto& t = log.time();
  std::size_t first = 0;
  while (first < t.size() && t[first] < t_step - 1e-9) ++first;
  std::size_t last = first;
  while (last < t.size() && t[last] < t_next - 1e-9) ++last;
  // Final value: the mean of the last 5 s before the next command, robust to the bias noise.
  const std::size_t tail = std::min<std::size_t>(50, last - first);
  double final_value = 0.0;
  for (std::size_t i = last - tail; i < last; ++i) final_value += y[i] / static_cast<double>(tail);
  std::vector<double> tt(t.begin() + first, t.begin() + last);
  std::vector<double> yy(y.begin() + first, y.begin() + last);
  yy.back() = final_value;
  const auto fit = model::fopdt_two_point(tt, yy, t_step);
  EXPECT_TRUE(fit.has_value()) << "step at " << t_step;
  return fit.value_or(model::FopdtTruth{});
}

// Mean of the samples of y with t in [t0, t1); NaN (failing every comparison) if there are none.
double window_mean(const core::Log& log, const std::vector<double>& y, double t0, double t1) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    if (log.time()[i] < t0 || log.time()[i] >= t1) continue;
    sum += y[i];
    ++n;
  }
  return n > 0 ? sum / static_cast<double>(n) : std::numeric_limits<double>::quiet_NaN();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The joystick command times and the end of the run: step k lasts from t[k] to t[k + 1].
std::vector<double> command_times(const ScenarioSpec& spec) {
  std::vector<double> t;
  for (const auto& c : spec.joystick) t.push_back(c.t_s);
  t.push_back(spec.duration_s);
  return t;
}

TEST(Calibration, SurgeStepsForwardMatchTheThesisShape) {
  // Table 3.24: T = 16.4 s (δ 8.5 s) for 0–80 %, 34.2 s for 25–40 %, 59.2 s for 15–25 %: the
  // time constant grows as the steps get smaller. One run is at the mercy of the current
  // (0.2 m/s, varying) and the heading's drift in open loop, so all but the 0–80 % step are
  // checked on the median over seeds 1–5 (measured 25–40 %: 30.4–33.7 s, 15–25 %: 41.4–49.5 s).
  // The small steps 0–5, 5–10 and 10–15 % (0.25, 0.75 and 1.25 % of full thrust through the
  // lever curve: 0.37, 1.1 and 1.8 kN) are the thesis' 65.5, 63.3 and 135 s; with the vessel
  // settled in the current and wind before the log (settle_s) and no bias in calm water they
  // are fitted at 28.9–113.0 s, 56.6–91.2 s and 51.4–76.0 s (medians 87.7, 71.4 and 63.3 s).
  const ScenarioSpec spec = load_scenario(kScenarios / "surge-steps-forward.toml");
  ASSERT_GT(spec.settle_s, 0.0);
  const std::vector<double> t_cmd = command_times(spec);
  // Commands: 0→5, 5→10, 10→15, 15→25, 25→40, 40→0, 0→80, 80→0 %.
  std::vector<double> t_0_5, t_5_10, t_10_15, t_15_25, t_25_40, t_0_80;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const ScenarioRun run = run_scenario(spec, VesselConfig{}, seed);
    const auto& u = run.truth_log.values("u");
    const model::FopdtTruth step_0_5 = fit_step(run.truth_log, u, t_cmd[0], t_cmd[1]);
    const model::FopdtTruth step_5_10 = fit_step(run.truth_log, u, t_cmd[1], t_cmd[2]);
    const model::FopdtTruth step_10_15 = fit_step(run.truth_log, u, t_cmd[2], t_cmd[3]);
    const model::FopdtTruth step_15_25 = fit_step(run.truth_log, u, t_cmd[3], t_cmd[4]);
    const model::FopdtTruth step_25_40 = fit_step(run.truth_log, u, t_cmd[4], t_cmd[5]);
    const model::FopdtTruth step_0_80 = fit_step(run.truth_log, u, t_cmd[6], t_cmd[7]);
    std::printf(
        "seed %llu: T 0-5 %% %.1f s, 5-10 %% %.1f s, 10-15 %% %.1f s, 15-25 %% %.1f s, 25-40 %% "
        "%.1f s, 0-80 %% %.1f s (delay %.1f s)\n",
        static_cast<unsigned long long>(seed), step_0_5.time_constant, step_5_10.time_constant,
        step_10_15.time_constant, step_15_25.time_constant, step_25_40.time_constant,
        step_0_80.time_constant, step_0_80.dead_time);
    t_0_5.push_back(step_0_5.time_constant);
    t_5_10.push_back(step_5_10.time_constant);
    t_10_15.push_back(step_10_15.time_constant);
    t_15_25.push_back(step_15_25.time_constant);
    t_25_40.push_back(step_25_40.time_constant);
    t_0_80.push_back(step_0_80.time_constant);
    // 0–80 %: we accept 10–25 s and 4–12 s in every run (bias noise).
    EXPECT_GT(step_0_80.time_constant, 10.0);
    EXPECT_LT(step_0_80.time_constant, 25.0);
    EXPECT_GT(step_0_80.dead_time, 4.0);
    EXPECT_LT(step_0_80.dead_time, 12.0);
    // The 0–80 % step reached ≈ 10 kn on the trial (section 3.5.4).
    const double u80 = u[static_cast<std::size_t>(std::round(t_cmd[7] * spec.log_rate_hz)) - 1];
    EXPECT_GT(u80 * 3600.0 / 1852.0, 9.0);
    EXPECT_LT(u80 * 3600.0 / 1852.0, 12.5);
  }
  // 25–40 % within ±30 % of the thesis' 34.2 s, and the growth for smaller steps: the 15–25 %
  // step slower than the 25–40 % one, which is slower than 1.5 × the 0–80 % one (thesis: 2.1).
  EXPECT_GT(median(t_25_40), 0.7 * 34.2);
  EXPECT_LT(median(t_25_40), 1.3 * 34.2);
  EXPECT_GT(median(t_15_25), median(t_25_40));
  EXPECT_GT(median(t_25_40), 1.5 * median(t_0_80));
  // Small steps: each median within the thesis' 63–135 s widened by a third (42–180 s), and
  // slower than the 25–40 % step.
  for (const auto* small : {&t_0_5, &t_5_10, &t_10_15}) {
    EXPECT_GT(median(*small), 42.0);
    EXPECT_LT(median(*small), 180.0);
    EXPECT_GT(median(*small), median(t_25_40));
  }
}

TEST(Calibration, SurgeStepsBackwardInTheThesisRange) {
  // Table 3.26: astern T = 30.7 s for 0–40 %, 36.6 s (15–20 %), 76.6 s (10–15 %), 64.6 s
  // (5–10 %), 51.4 s (20–0 %): 31–77 s. Medians over seeds 1–5, as ahead. Measured: 0–40 %
  // 35.5 s (35.1–35.9 s), 15–20 % 51.1 s, 10–15 % 64.1 s, 5–10 % 81.0 s, 20–0 % 73.0 s, 0–5 %
  // 75.8 s (47.9–171.5 s). Checked: 0–40 % within ±30 % of 30.7 s (as the 25–40 % step ahead),
  // every other median within 31–77 s widened by a quarter (23–96 s, as the yaw steps), and the
  // small steps slower than the 0–40 % one.
  const ScenarioSpec spec = load_scenario(kScenarios / "surge-steps-backward.toml");
  ASSERT_GT(spec.settle_s, 0.0);
  const std::vector<double> t_cmd = command_times(spec);
  // Commands: 0→5, 5→10, 10→15, 15→20, 20→0, 0→40, 40→0 % astern.
  ASSERT_EQ(t_cmd.size(), 8u);
  const char* names[] = {"0-5", "5-10", "10-15", "15-20", "20-0", "0-40"};
  std::vector<std::vector<double>> fits(6);
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const ScenarioRun run = run_scenario(spec, VesselConfig{}, seed);
    const auto& u = run.truth_log.values("u");
    for (std::size_t k = 0; k < fits.size(); ++k) {
      const model::FopdtTruth f = fit_step(run.truth_log, u, t_cmd[k], t_cmd[k + 1]);
      std::printf("seed %llu, %s %% astern: T %.1f s, delay %.1f s\n",
                  static_cast<unsigned long long>(seed), names[k], f.time_constant, f.dead_time);
      fits[k].push_back(f.time_constant);
    }
  }
  const double t_0_40 = median(fits[5]);
  EXPECT_GT(t_0_40, 0.7 * 30.7);
  EXPECT_LT(t_0_40, 1.3 * 30.7);
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_GT(median(fits[k]), 0.75 * 31.0) << names[k];
    EXPECT_LT(median(fits[k]), 1.25 * 77.0) << names[k];
    EXPECT_GT(median(fits[k]), t_0_40) << names[k];
  }
}

TEST(Calibration, PropellerStepTruthsInThesisRanges) {
  const ScenarioSpec spec = load_scenario(kScenarios / "surge-steps-forward.toml");
  const ScenarioRun run = run_scenario(spec, VesselConfig{}, 1);
  double largest_step_T = 0.0, smallest_step_T = 1e9;
  for (const PropellerStepTruth& step : run.truth.propeller_steps) {
    const double tn = step.shaft_speed.time_constant;
    const double dn = step.shaft_speed.dead_time;
    // Tables 3.23–3.29: T_n 0.5–5.5 s, δ_n 1.2–3.3 s.
    EXPECT_GE(tn, 0.5);
    EXPECT_LE(tn, 5.5);
    EXPECT_GE(dn, 1.2);
    EXPECT_LE(dn, 3.3);
    // Thrust: T 0.3–4.7 s, δ 1–5.6 s (same tables).
    const double tt = step.thrust.time_constant;
    const double dt = step.thrust.dead_time;
    EXPECT_GE(tt, 0.3);
    EXPECT_LE(tt, 4.7);
    EXPECT_GE(dt, 1.0);
    EXPECT_LE(dt, 5.6);
    const double dn_rps = std::abs(step.n_to_rps - step.n_from_rps);
    if (dn_rps > 2.0) largest_step_T = std::max(largest_step_T, tn);
    if (dn_rps < 0.5) smallest_step_T = std::min(smallest_step_T, tn);
  }
  EXPECT_GT(largest_step_T, 3.0 * smallest_step_T);  // larger steps slower
}

TEST(Calibration, SwayStepsHoldHeadingAndGrowWithTheStep) {
  // Joystick sway steps with auto heading (thesis 3.5, tables 3.27–3.30). What holds: the
  // heading is held once a step has settled, and the through-water sway speed at the end of each
  // step is to starboard and grows with the step. The total-speed time constants (3.19) are
  // checked over several seeds in SwayTotalSpeedTimeConstantsInThesisRange.
  const ScenarioSpec spec = load_scenario(kScenarios / "sway-steps-starboard.toml");
  ASSERT_TRUE(spec.heading_hold);
  const ScenarioRun run = run_scenario(spec, VesselConfig{}, 1);
  const core::Log& log = run.truth_log;
  const auto& t = log.time();
  std::vector<double> total(log.size()), v_water(log.size());
  for (std::size_t i = 0; i < log.size(); ++i) {
    const double psi = log.values("heading")[i];
    const double vc_b = -std::sin(psi) * log.values("current.north")[i] +
                        std::cos(psi) * log.values("current.east")[i];
    v_water[i] = log.values("v")[i] - vc_b;
    total[i] = std::hypot(log.values("u")[i], log.values("v")[i]);  // (3.19)
  }
  const double psi_set = core::deg_to_rad(spec.initial_heading_deg);
  double max_heading_dev = 0.0;
  std::vector<double> heading_error;
  for (double psi : log.values("heading")) {
    heading_error.push_back(core::wrap_pi(psi - psi_set));
    max_heading_dev = std::max(max_heading_dev, std::abs(heading_error.back()));
  }
  // Auto heading (ω = 0.15 rad/s) against wind, current and the yaw moment of each step. At the
  // onset of a large step the tunnel's force arrives seconds before the stern's side force,
  // which waits for propeller thrust (dead time 1.3 s, 7.5 kN/s), and the bow swings off:
  // peaks of 4.9–7.5° over seeds 1–6 and both sides (seed 1 here: 4.9°). Once the step has
  // settled, the heading is held: the mean over the last 30 s of every step is within
  // 0.47–0.67° of the set heading over the same runs.
  EXPECT_LT(max_heading_dev, core::deg_to_rad(8.0));
  const std::vector<CommandTruth>& cmds = run.truth.commands;
  for (std::size_t k = 0; k < cmds.size(); ++k) {
    const double t0 = cmds[k].t_s;
    const double t1 = k + 1 < cmds.size() ? cmds[k + 1].t_s : t.back() + 1.0 / spec.log_rate_hz;
    EXPECT_LT(std::abs(window_mean(log, heading_error, t1 - 30.0, t1)), core::deg_to_rad(1.0))
        << "held heading, step at " << t0 << " s";
  }
  double previous = 0.0;
  for (std::size_t k = 0; k + 1 < cmds.size(); k += 2) {  // 0–25, 0–50, 0–75, 0–100 %
    const double t0 = cmds[k].t_s, t1 = cmds[k + 1].t_s;
    const double v_end = window_mean(log, v_water, t1 - 30.0, t1);
    const model::FopdtTruth f = fit_step(log, total, t0, t1);
    std::printf("sway 0-%.0f %%: v through water %.2f m/s; total speed T %.1f s, delay %.1f s\n",
                cmds[k].sway_pct, v_end, f.time_constant, f.dead_time);
    EXPECT_GT(v_end, previous) << "step " << cmds[k].sway_pct;
    previous = v_end;
  }
}

TEST(Calibration, SwayTotalSpeedTimeConstantsInThesisRange) {
  // Tables 3.28 and 3.30: total speed (3.19) T = 9–19 s for the 0–25 … 0–100 % sway steps,
  // larger steps faster; the thesis calls the values of "lower quality". The scenarios head so
  // that the current (0.2 m/s) sets the vessel towards the side of the steps: the total speed
  // then grows from the drift by the through-water response, and every step has a clean rise
  // (with the current across the other way, a 50 % step first stopped the drift and its fit
  // failed). Measured over seeds 1–3 and both sides: every fit 9.8–33.3 s; medians 0–25 %
  // 23.4 s, 0–50 % 20.6 s, 0–100 % 11.4 s; median of the 0–50 … 0–100 % steps 18.4 s. Checked:
  // every single fit within a factor of two of the thesis range (4.5–38 s), the median of the
  // 0–50 … 0–100 % steps in 9–19 s, and the medians shorter for larger steps.
  std::vector<double> t_large, t_25, t_50, t_100;
  for (const char* name : {"sway-steps-starboard.toml", "sway-steps-port.toml"}) {
    const ScenarioSpec spec = load_scenario(kScenarios / name);
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const ScenarioRun run = run_scenario(spec, VesselConfig{}, seed);
      const core::Log& log = run.truth_log;
      const std::vector<double>& u = log.values("u");
      const std::vector<double>& v = log.values("v");
      std::vector<double> total(log.size());
      for (std::size_t i = 0; i < log.size(); ++i) total[i] = std::hypot(u[i], v[i]);  // (3.19)
      const auto& js = spec.joystick;
      for (std::size_t k = 0; k + 1 < js.size(); ++k) {
        const double from = k == 0 ? 0.0 : std::abs(js[k - 1].sway_pct);
        const double to = std::abs(js[k].sway_pct);
        if (from != 0.0 || to == 0.0) continue;
        const model::FopdtTruth f = fit_step(log, total, js[k].t_s, js[k + 1].t_s);
        std::printf("%s seed %llu, 0-%.0f %%: total speed T %.1f s, delay %.1f s\n", name,
                    static_cast<unsigned long long>(seed), to, f.time_constant, f.dead_time);
        EXPECT_GE(f.time_constant, 4.5) << name << " seed " << seed << " 0-" << to;
        EXPECT_LE(f.time_constant, 38.0) << name << " seed " << seed << " 0-" << to;
        if (to >= 50.0) t_large.push_back(f.time_constant);
        if (to == 25.0) t_25.push_back(f.time_constant);
        if (to == 50.0) t_50.push_back(f.time_constant);
        if (to == 100.0) t_100.push_back(f.time_constant);
      }
    }
  }
  ASSERT_EQ(t_25.size(), 6u);      // both sides × 3 seeds
  ASSERT_EQ(t_large.size(), 15u);  // (3 + 2 steps) × 3 seeds: 0–75 % is run to starboard only
  const double m = median(t_large);
  std::printf("median T %.1f s (25 %%: %.1f s, 50 %%: %.1f s, 100 %%: %.1f s)\n", m, median(t_25),
              median(t_50), median(t_100));
  EXPECT_GE(m, 9.0);
  EXPECT_LE(m, 19.0);
  EXPECT_LT(median(t_50), median(t_25));
  EXPECT_LT(median(t_100), median(t_50));
}

TEST(Calibration, ThrustMapBackCalculatesTable32) {
  const ScenarioSpec spec = load_scenario(kScenarios / "surge-steps-backward.toml");
  const ScenarioRun run = run_scenario(spec, VesselConfig{}, 1);
  const auto& n = run.truth_log.values("rpm.port");
  const auto& thrust = run.truth_log.values("thrust.port");
  // Least squares of T = c·n|n| on the astern samples (3.17), in kN/rps².
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < n.size(); ++i) {
    if (n[i] < -0.3) {
      num += thrust[i] * n[i] * std::abs(n[i]);
      den += n[i] * n[i] * n[i] * n[i];
    }
  }
  ASSERT_GT(den, 0.0);
  // Table 3.2: c₋ = −5.8 kN/rps²; the model's map has no advance-speed loss, so it is exact
  // to rounding.
  EXPECT_NEAR(-num / den / 1e3, -5.8, 1e-6);
}

// Yaw steps (table 3.31), two ways: the truth.json Nomoto T_r of the linearised hull, and the
// thesis' own measure, Smith fits of the yaw rate after the 0→±20° rudder steps (the reference
// log's r, timed from the rudder command). T_r does not see the quadratic yaw damping, which
// shortens the response once the vessel turns; the fits do.
TEST(Calibration, YawRateResponseMatchesTable331) {
  const ScenarioSpec spec = load_scenario(kScenarios / "yaw-steps.toml");
  const ScenarioRun run = run_scenario(spec, VesselConfig{}, 1);
  double tr_3kn = 0.0, tr_6kn = 0.0;
  for (const RudderStepTruth& step : run.truth.rudder_steps) {
    if (std::abs(step.to_deg) != 20.0) continue;
    const double u = step.surge_mps;
    ASSERT_TRUE(step.nomoto.has_value()) << step.t_s;
    const double tr = step.nomoto->Tr_s;
    (u < 2.3 ? tr_3kn : tr_6kn) = tr;
    // Rudder servo 0→20°, tables 3.33–3.36: T 1.7–4.4 s, δ 0.7–1.5 s.
    EXPECT_GE(step.servo.time_constant, 1.7);
    EXPECT_LE(step.servo.time_constant, 4.4);
    EXPECT_GE(step.servo.dead_time, 0.7);
    EXPECT_LE(step.servo.dead_time, 1.5);
  }
  // Table 3.31: 4.7–5.6 s at 3 kn, 2.9–3.0 s at 6 kn; the speed at the step is what the
  // scenario reached, so we allow ± 0.6 s around the bands.
  EXPECT_GT(tr_3kn, 4.1);
  EXPECT_LT(tr_3kn, 6.2);
  EXPECT_GT(tr_6kn, 2.3);
  EXPECT_LT(tr_6kn, 3.6);
  EXPECT_GT(tr_3kn, tr_6kn);

  // Fitted from the log. Single fits trade T against δ (seeds 1–5 at 3 kn: T 2.3–5.5 s with δ
  // 3.6–2.0 s), so the band is on the time to 63 %, T + δ, whose side-averaged value spreads by
  // only ±0.4 s (3 kn) and ±0.15 s (6 kn) over seeds 1–5; T is checked for its trend with speed.
  ASSERT_EQ(spec.joystick.size(), 2u);  // 3 kn, then 6 kn from the second surge demand on
  const double t_6kn = spec.joystick[1].t_s;
  const auto& r = run.truth_log.values("r");
  std::vector<model::FopdtTruth> fits_3kn, fits_6kn;
  for (std::size_t k = 0; k + 1 < spec.rudder.size(); ++k) {
    if (std::abs(spec.rudder[k].angle_deg) != 20.0) continue;
    (spec.rudder[k].t_s < t_6kn ? fits_3kn : fits_6kn)
        .push_back(fit_step(run.truth_log, r, spec.rudder[k].t_s, spec.rudder[k + 1].t_s));
  }
  ASSERT_EQ(fits_3kn.size(), 2u);  // starboard and port
  ASSERT_EQ(fits_6kn.size(), 2u);
  const auto mean_T = [](const std::vector<model::FopdtTruth>& f) {
    return 0.5 * (f[0].time_constant + f[1].time_constant);
  };
  const auto mean_t63 = [&](const std::vector<model::FopdtTruth>& f) {
    return mean_T(f) + 0.5 * (f[0].dead_time + f[1].dead_time);
  };
  // Table 3.31, T + δ: 6.8–7.6 s at 3 kn, 4.9 s at 6 kn; DESIGN.md asks for the thesis'
  // magnitudes "roughly", taken here as ±25 % of its range. (Quadratic yaw damping 4e8 gave
  // 4.6 s at 3 kn: this fails.)
  EXPECT_GT(mean_t63(fits_3kn), 0.75 * 6.8);
  EXPECT_LT(mean_t63(fits_3kn), 1.25 * 7.6);
  EXPECT_GT(mean_t63(fits_6kn), 0.75 * 4.9);
  EXPECT_LT(mean_t63(fits_6kn), 1.25 * 4.9);
  // Shorter at 6 kn, in T and in T + δ (table 3.31: 4.7–5.6 s against 2.9–3.0 s).
  EXPECT_GT(mean_T(fits_3kn), mean_T(fits_6kn));
  EXPECT_GT(mean_t63(fits_3kn), mean_t63(fits_6kn));

  // 47°→0 (table 3.32): T + δ 12.6–16.1 s at 3 kn and 10.7–10.8 s at 6 kn, ±25 % as above
  // (measured over seeds 1–5: 11.7–12.8 s and 10.0–10.5 s; seed 1: 11.9 s and 10.0 s).
  std::vector<model::FopdtTruth> back_3kn, back_6kn;
  // 20°→47° (section 3.5, figures 3.15–3.18): "an initial pulse in yaw rate, but does not
  // significantly change the steady state yaw rate". The ratio of the mean rate over the last
  // 5 s before the next command, after and before the step, averaged over the four steps, is
  // taken within 1 ± 0.3 (measured 1.13 on this seed, 1.09–1.18 for single steps over seeds
  // 1–5; a rudder whose lift fell over 60° after stall gave 1.7–1.95, which fails).
  const auto tail_mean = [&](double t_next) {
    return window_mean(run.truth_log, r, t_next - 5.0, t_next);
  };
  double ratio_sum = 0.0;
  int ratios = 0;
  for (std::size_t k = 1; k < spec.rudder.size(); ++k) {
    const double angle = spec.rudder[k].angle_deg;
    const double t_step = spec.rudder[k].t_s;
    const double t_next = k + 1 < spec.rudder.size() ? spec.rudder[k + 1].t_s : spec.duration_s;
    if (std::abs(angle) == 47.0 && std::abs(spec.rudder[k - 1].angle_deg) == 20.0) {
      ratio_sum += tail_mean(t_next) / tail_mean(t_step);
      ++ratios;
    }
    if (angle == 0.0 && std::abs(spec.rudder[k - 1].angle_deg) == 47.0) {
      (t_step < t_6kn ? back_3kn : back_6kn).push_back(fit_step(run.truth_log, r, t_step, t_next));
    }
  }
  ASSERT_EQ(ratios, 4);
  std::printf(
      "20->47 deg: steady rate ratio %.2f; 47->0 deg: T + delay %.1f s (3 kn), %.1f s "
      "(6 kn)\n",
      ratio_sum / ratios, mean_t63(back_3kn), mean_t63(back_6kn));
  EXPECT_GT(ratio_sum / ratios, 0.7);
  EXPECT_LT(ratio_sum / ratios, 1.3);
  ASSERT_EQ(back_3kn.size(), 2u);
  ASSERT_EQ(back_6kn.size(), 2u);
  EXPECT_GT(mean_t63(back_3kn), 0.75 * 12.6);
  EXPECT_LT(mean_t63(back_3kn), 1.25 * 16.1);
  EXPECT_GT(mean_t63(back_6kn), 0.75 * 10.7);
  EXPECT_LT(mean_t63(back_6kn), 1.25 * 10.8);
}

// Standard deviation of the samples of y with t in [t0, t1).
double window_std(const core::Log& log, const std::vector<double>& y, double t0, double t1) {
  double sum = 0.0, sum2 = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    if (log.time()[i] < t0 || log.time()[i] >= t1) continue;
    sum += y[i];
    sum2 += y[i] * y[i];
    ++n;
  }
  const double mean = sum / static_cast<double>(n);
  return std::sqrt(std::max(0.0, sum2 / static_cast<double>(n) - mean * mean));
}

TEST(Calibration, PureDpPositionAndHeadingSpreadInHs2) {
  const ScenarioSpec spec = load_scenario(kScenarios / "pure-dp.toml");
  ASSERT_EQ(spec.environment.hs_m, 2.0);
  const ScenarioRun run = run_scenario(spec, VesselConfig{}, 1);
  const std::vector<SetpointTruth>& reached = run.truth.setpoints;
  ASSERT_EQ(reached.size(), spec.setpoints.size());
  for (std::size_t k = 0; k < spec.setpoints.size(); ++k) {
    const SetpointCommand& sp = spec.setpoints[k];
    // 5 min per heading after 130 s to turn and settle, as the thesis logged 5 min windows.
    const double t0 = sp.t_s + 130.0, t1 = sp.t_s + 430.0;
    // Each timed setpoint is reached (operating circle, section 3.5.2) before its window opens.
    ASSERT_TRUE(reached[k].t_reached_s.has_value()) << sp.name;
    EXPECT_GE(*reached[k].t_reached_s, sp.t_s) << sp.name;
    EXPECT_LT(*reached[k].t_reached_s, t0) << sp.name;
    const double std_n = window_std(run.truth_log, run.truth_log.values("north"), t0, t1);
    const double std_e = window_std(run.truth_log, run.truth_log.values("east"), t0, t1);
    // Heading on the circle (0° sits next to 360°): circular standard deviation.
    std::vector<double> psi;
    for (std::size_t i = 0; i < run.truth_log.size(); ++i) {
      if (run.truth_log.time()[i] >= t0 && run.truth_log.time()[i] < t1)
        psi.push_back(run.truth_log.values("heading")[i]);
    }
    const double std_psi_deg = core::circular_stats(psi).std_rad.value() * 180.0 / M_PI;
    // DESIGN.md: pure-DP position std between 0.2 and 1.5 m in Hs ≈ 2 m (tables 3.14–3.22
    // report 0.3–0.9 m); heading std 0.4–0.9° with one case at 2.8°, so ≤ 3°.
    const double std_pos = std::max(std_n, std_e);
    EXPECT_GT(std_pos, 0.2) << sp.name;
    EXPECT_LT(std_pos, 1.5) << sp.name;
    EXPECT_LT(std_psi_deg, 3.0) << sp.name;
    // Mean thrust, the sum of the thrusters' mean |T|: tables 3.14–3.22 give 2–45 kN in total.
    double thrust_sum = 0.0;
    std::size_t n = 0;
    const std::vector<double>& time = run.truth_log.time();
    const std::vector<double>& t_port = run.truth_log.values("thrust.port");
    const std::vector<double>& t_stb = run.truth_log.values("thrust.stb");
    const std::vector<double>& t_tunnel = run.truth_log.values("thrust.tunnel");
    for (std::size_t i = 0; i < time.size(); ++i) {
      if (time[i] < t0 || time[i] >= t1) continue;
      thrust_sum += std::abs(t_port[i]) + std::abs(t_stb[i]) + std::abs(t_tunnel[i]);
      ++n;
    }
    const double mean_thrust_kN = thrust_sum / static_cast<double>(n) / 1e3;
    std::printf("pure DP %s: position std %.2f m, heading std %.2f deg, mean thrust %.1f kN\n",
                sp.name.c_str(), std_pos, std_psi_deg, mean_thrust_kN);
    EXPECT_GT(mean_thrust_kN, 1.0) << sp.name;
    EXPECT_LT(mean_thrust_kN, 45.0) << sp.name;
  }
}

TEST(Calibration, FourCornerCompletesEveryLeg) {
  const ScenarioSpec spec = load_scenario(kScenarios / "four-corner.toml");
  const ScenarioRun run = run_scenario(spec, VesselConfig{}, 1);
  const std::vector<SetpointTruth>& legs = run.truth.setpoints;
  ASSERT_EQ(legs.size(), 5u);  // the initial hold and the four legs
  double total = 0.0;
  for (std::size_t i = 1; i < legs.size(); ++i) {
    ASSERT_TRUE(legs[i].t_reached_s.has_value()) << legs[i].name;
    const double duration = *legs[i].t_reached_s - legs[i].t_start_s;
    // Tables 3.6–3.10: 85–214 s per 50 m leg.
    EXPECT_GT(duration, 85.0) << legs[i].name;
    EXPECT_LT(duration, 214.0) << legs[i].name;
    total += duration;
  }
  // Thesis total 545–624 s. This run (seed 1) gives 594 s; seeds 1–5 give 591–604 s (legs
  // 141–165 s).
  EXPECT_GT(total, 545.0);
  EXPECT_LT(total, 624.0);
}

}  // namespace
}  // namespace dynpos::scenario
