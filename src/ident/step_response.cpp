#include "step_response.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "dynpos/core/error.hpp"
#include "series.hpp"

namespace dynpos::ident::detail {

void validate_window_options(const std::optional<double>& pre_step_s, double tail_fraction,
                             double steady_state_tolerance, double min_r_squared,
                             std::size_t min_samples, const char* owner) {
  const auto bad = [owner](const std::string& what, const std::string& hint) {
    throw core::InputError({"", {}, {}, owner}, what, hint);
  };
  if (pre_step_s && !(*pre_step_s > 0.0)) {
    bad("pre-step duration " + fmt(*pre_step_s) + " s", "give a duration > 0 s");
  }
  if (!(tail_fraction > 0.0 && tail_fraction <= 0.5)) {
    bad("tail fraction " + fmt(tail_fraction), "give a fraction in (0, 0.5]");
  }
  if (!(steady_state_tolerance >= 0.0)) {
    bad("steady-state tolerance " + fmt(steady_state_tolerance), "give a fraction ≥ 0");
  }
  if (!(min_r_squared >= 0.0 && min_r_squared <= 1.0)) {
    bad("minimum R² " + fmt(min_r_squared), "give a value in [0, 1]");
  }
  if (min_samples < 5) bad("minimum samples " + std::to_string(min_samples), "give at least 5");
}

namespace {

// The valid output samples of the step's window, as time after the step τ and value, checked:
// the window inside the log and around the step, an increasing time axis, samples before and
// at least 5 after the step, a change of input.
StepResponse window_samples(std::span<const double> t, std::span<const double> y, const Step& step,
                            const LevelOptions& options) {
  const std::string& name = options.output_name;
  check_same_length(t.size(), y.size(), name);
  const core::InputLocation where{"", {}, {}, name};
  if (t.empty()) throw core::InputError(where, "the log is empty", "");
  if (!(step.t_begin <= step.t_step && step.t_step < step.t_end)) {
    throw core::InputError(where,
                           "step time " + fmt(step.t_step) + " s is not inside the window [" +
                               fmt(step.t_begin) + ", " + fmt(step.t_end) + "] s",
                           "give a window that starts before the step and ends after it");
  }
  // A window from the same log may differ from its time stamps by rounding only.
  const double slack = detail::time_rounding_slack_s(t.front(), t.back());
  if (step.t_begin < t.front() - slack || step.t_end > t.back() + slack) {
    throw core::InputError(where,
                           "window [" + fmt(step.t_begin) + ", " + fmt(step.t_end) +
                               "] s is outside the log [" + fmt(t.front()) + ", " + fmt(t.back()) +
                               "] s",
                           "choose a window inside the logged time");
  }
  const double after = step.t_end - step.t_step;
  double pre = step.t_step - step.t_begin;
  if (options.pre_step_s) {
    pre = std::min(pre, *options.pre_step_s);
  } else {
    pre = std::min(pre, 0.25 * after);
  }
  const double t_from = step.t_step - pre;

  StepResponse r;
  r.t_step = step.t_step;
  r.tau_end = after;
  // Only the window is visited (found by bisection of the increasing time axis) and checked, so
  // one fit per step over a long log costs O(window), not O(log): a day at 100 Hz has 8.6 M
  // samples and hundreds of steps.
  const auto lo = std::lower_bound(t.begin(), t.end(), step.t_begin - slack);
  const auto hi = std::upper_bound(lo, t.end(), step.t_end + slack);
  const auto i0 = static_cast<std::size_t>(lo - t.begin());
  const auto i1 = static_cast<std::size_t>(hi - t.begin());
  if (i0 == i1) {
    throw core::InputError(
        where, "no log sample in the window [" + fmt(step.t_begin) + ", " + fmt(step.t_end) + "] s",
        "widen the window");
  }
  // Bisection found the window's samples on an increasing axis; each is checked as it is taken.
  r.tau.reserve(i1 - i0);
  r.y.reserve(i1 - i0);
  for (std::size_t i = i0; i < i1; ++i) {
    if (!std::isfinite(t[i]) || (i > i0 && !(t[i] > t[i - 1]))) {
      check_time_axis(t, name, 1);  // throws, naming the first bad index of the whole axis
    }
    if (t[i] < t_from - slack || std::isnan(y[i])) continue;
    r.tau.push_back(t[i] - step.t_step);
    r.y.push_back(y[i]);
    if (t[i] <= step.t_step) ++r.n_pre;
  }
  if (r.y.empty()) {
    throw core::InputError(where,
                           "all output samples are missing in the window [" + fmt(step.t_begin) +
                               ", " + fmt(step.t_end) + "] s",
                           "check the column map, or choose a window where the output is logged");
  }
  if (r.n_pre == 0) {
    throw core::InputError(
        where, "no valid output sample at or before the step at " + fmt(step.t_step) + " s",
        "start the window before the step");
  }
  const std::size_t n_post = r.y.size() - r.n_pre;
  if (n_post < 5) {
    throw core::InputError(where,
                           "step too short: " + std::to_string(n_post) +
                               " valid output samples after the step at " + fmt(step.t_step) +
                               " s (at least 5 needed)",
                           "extend the window after the step");
  }
  if (const auto du = step.delta_u(); du && *du == 0.0) {
    throw core::InputError(
        where,
        "constant input: the input is " + fmt(*step.u_before) + " both before and after the step",
        "check the step levels or the input channel");
  }
  return r;
}

}  // namespace

StepResponse prepare_step_response(std::span<const double> t, std::span<const double> y,
                                   const Step& step, const LevelOptions& options) {
  StepResponse r = window_samples(t, y, step, options);
  const double after = r.tau_end;
  const std::size_t n_post = r.y.size() - r.n_pre;
  double sum = 0.0;
  for (std::size_t i = 0; i < r.n_pre; ++i) sum += r.y[i];
  r.y0 = sum / static_cast<double>(r.n_pre);

  // Tail: the last tail_fraction of the window after the step, at least 3 samples.
  const double tail_from = (1.0 - options.tail_fraction) * after;
  std::size_t tail_begin = r.y.size();
  while (tail_begin > r.n_pre && r.tau[tail_begin - 1] >= tail_from) --tail_begin;
  tail_begin = std::min(tail_begin, r.y.size() - 3);
  const std::span<const double> tail_tau(r.tau.data() + tail_begin, r.y.size() - tail_begin);
  const std::span<const double> tail_y(r.y.data() + tail_begin, r.y.size() - tail_begin);
  sum = 0.0;
  for (double v : tail_y) sum += v;
  r.y_final = sum / static_cast<double>(tail_y.size());
  r.delta_y = r.y_final - r.y0;
  r.noise_sigma = difference_noise_sigma(r.y);

  if (n_post < options.min_samples) {
    r.warnings.push_back({WarningCode::kFewSamples,
                          std::to_string(n_post) + " valid samples after the step (fewer than " +
                              std::to_string(options.min_samples) + ")"});
  }
  if (r.n_pre < 3) {
    r.warnings.push_back(
        {WarningCode::kFewPreStepSamples,
         std::to_string(r.n_pre) + " samples before the step: the initial level y₀ is uncertain"});
  }
  // Steady state: a line through the tail must not change by more than the noise (2σ of the
  // tail about the line) nor by more than the tolerance times the step in the output.
  const LineFit line = fit_line(tail_tau, tail_y);
  const double tail_duration = tail_tau.back() - tail_tau.front();
  const double drift = std::abs(line.b) * tail_duration;
  const double limit =
      std::max(2.0 * line.residual_sigma, options.steady_state_tolerance * std::abs(r.delta_y));
  if (drift > limit) {
    r.warnings.push_back({WarningCode::kSteadyStateNotReached,
                          "steady state not reached: the output drifts by " + fmt(drift) +
                              " over the last " + fmt(tail_duration) + " s (limit " + fmt(limit) +
                              ", Δy " + fmt(r.delta_y) + ")"});
  }
  return r;
}

namespace {

// Crossing of `level` by the least-squares quadratic through samples [lo, hi] of a noisy,
// monotone-on-average response, solved on the root nearest the middle of the stretch. A
// quadratic follows the curvature of the response around the level, so the crossing is not
// pulled towards the flatter side as the mean of the first and last crossings is (an early
// 28.3 % crossing on an S-shaped rise makes T too large). nullopt when the fit does not cross
// the level inside the stretch.
std::optional<double> quadratic_crossing(const StepResponse& r, std::size_t lo, std::size_t hi,
                                         double level) {
  const double tm = 0.5 * (r.tau[lo] + r.tau[hi]);
  const double half = 0.5 * (r.tau[hi] - r.tau[lo]);
  if (!(half > 0.0)) return std::nullopt;
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d aty = Eigen::Vector3d::Zero();
  for (std::size_t i = lo; i <= hi; ++i) {
    const double x = (r.tau[i] - tm) / half;  // in [-1, 1]: a well-conditioned basis
    const Eigen::Vector3d a(1.0, x, x * x);
    ata += a * a.transpose();
    aty += a * (r.y[i] - level);
  }
  const Eigen::Vector3d c = ata.ldlt().solve(aty);  // c0 + c1 x + c2 x² = y − level
  std::optional<double> best;
  auto consider = [&](double x) {
    if (std::isfinite(x) && std::abs(x) <= 1.0 && (!best || std::abs(x) < std::abs(*best))) {
      best = x;
    }
  };
  if (std::abs(c[2]) < 1e-12 * (std::abs(c[1]) + std::abs(c[0]))) {
    if (c[1] != 0.0) consider(-c[0] / c[1]);
  } else {
    const double disc = c[1] * c[1] - 4.0 * c[2] * c[0];
    if (disc >= 0.0) {
      const double q = -0.5 * (c[1] + std::copysign(std::sqrt(disc), c[1]));
      if (q != 0.0) consider(c[0] / q);
      consider(q / c[2]);
    }
  }
  if (!best) return std::nullopt;
  return tm + *best * half;
}

}  // namespace

std::optional<double> crossing_time(const StepResponse& r, double fraction) {
  const double level = r.y0 + fraction * r.delta_y;
  const double s = r.delta_y >= 0.0 ? 1.0 : -1.0;
  const double band = 3.0 * r.noise_sigma;
  const std::size_t first = r.n_pre - 1;  // the last sample at or before the step
  const auto z = [&](std::size_t i) { return s * (r.y[i] - level); };
  std::size_t hi = first;
  while (hi < r.y.size() && z(hi) < band) ++hi;
  if (hi == r.y.size()) return std::nullopt;
  if (hi == first) return r.tau[first];
  std::size_t lo = hi;
  while (lo > first && z(lo) > -band) --lo;
  // Noisy data: several samples in the band around the level. Fit through them.
  constexpr std::size_t kMinQuadraticSamples = 5;
  if (hi - lo + 1 >= kMinQuadraticSamples) {
    if (const auto tc = quadratic_crossing(r, lo, hi, level)) return tc;
  }
  std::optional<double> first_cross;
  double last_cross = r.tau[hi];
  for (std::size_t i = lo + 1; i <= hi; ++i) {
    const double z0 = z(i - 1);
    const double z1 = z(i);
    if (z0 < 0.0 && z1 >= 0.0) {
      const double tc = r.tau[i - 1] + (-z0) / (z1 - z0) * (r.tau[i] - r.tau[i - 1]);
      if (!first_cross) first_cross = tc;
      last_cross = tc;
    }
  }
  if (!first_cross) return r.tau[hi];
  return 0.5 * (*first_cross + last_cross);
}

}  // namespace dynpos::ident::detail
