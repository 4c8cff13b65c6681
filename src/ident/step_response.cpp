#include "step_response.hpp"

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

StepResponse prepare_step_response(std::span<const double> t, std::span<const double> y,
                                   const Step& step, const LevelOptions& options) {
  const std::string& name = options.output_name;
  check_same_length(t.size(), y.size(), name);
  check_time_axis(t, name);
  const core::InputLocation where{"", {}, {}, name};
  if (t.empty()) throw core::InputError(where, "the log is empty", "");
  if (!(step.t_begin <= step.t_step && step.t_step < step.t_end)) {
    throw core::InputError(where,
                           "step time " + fmt(step.t_step) + " s is not inside the window [" +
                               fmt(step.t_begin) + ", " + fmt(step.t_end) + "] s",
                           "give a window that starts before the step and ends after it");
  }
  // A window from the same log may differ from its time stamps by rounding only.
  const double slack = 1e-9 * std::max({1.0, std::abs(t.front()), std::abs(t.back())});
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
  bool any_in_window = false;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] < step.t_begin - slack || t[i] > step.t_end + slack) continue;
    any_in_window = true;
    if (t[i] < t_from - slack || std::isnan(y[i])) continue;
    r.tau.push_back(t[i] - step.t_step);
    r.y.push_back(y[i]);
    if (t[i] <= step.t_step) ++r.n_pre;
  }
  if (!any_in_window) {
    throw core::InputError(
        where, "no log sample in the window [" + fmt(step.t_begin) + ", " + fmt(step.t_end) + "] s",
        "widen the window");
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
