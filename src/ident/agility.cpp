#include "dynpos/ident/agility.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "dynpos/core/error.hpp"
#include "series.hpp"

namespace dynpos::ident {

using detail::fmt;

namespace {

// 63.2 % = 1 − e⁻¹: the share of a first-order response covered after one time constant,
// section 3.2 (the agility plots use the time to it, dead time included).
constexpr double kLevel632 = 0.632;

core::InputError option_error(const std::string& what, const std::string& hint) {
  return core::InputError({"", {}, {}, "agility options"}, what, hint);
}

double mean(const std::vector<double>& v) {
  double s = 0.0;
  for (const double x : v) s += x;
  return v.empty() ? std::numeric_limits<double>::quiet_NaN() : s / static_cast<double>(v.size());
}

// Range max − min of the valid samples; NaN when there is none.
double valid_range(std::span<const double> y) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const double v : y) {
    if (!std::isfinite(v)) continue;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  return hi >= lo ? hi - lo : std::numeric_limits<double>::quiet_NaN();
}

// Wraps an angle [deg] to (−180, 180].
double wrap_deg(double a) {
  double w = std::fmod(a, 360.0);
  if (w > 180.0) w -= 360.0;
  if (w <= -180.0) w += 360.0;
  return w;
}

void check_channels(std::span<const double> t, std::span<const AgilityChannel> thrusters,
                    std::span<const double> speed_mps) {
  if (thrusters.empty()) {
    throw core::InputError({"", {}, {}, "thrust.NAME"}, "no thruster channel to time",
                           "give the thrust (or shaft speed) of at least one thruster");
  }
  for (const AgilityChannel& c : thrusters) {
    detail::check_same_length(t.size(), c.values.size(), c.name);
    if (!std::isfinite(valid_range(c.values))) {
      throw core::InputError({"", {}, {}, c.name}, "thruster channel has no valid sample",
                             "check the column mapping and the unit of the channel");
    }
  }
  if (!speed_mps.empty()) {
    detail::check_same_length(t.size(), speed_mps.size(), "speed");
  }
}

AgilityResult respond(std::span<const double> t, std::vector<AgilityStep> steps,
                      std::span<const AgilityChannel> thrusters, std::span<const double> speed,
                      const AgilityOptions& options) {
  std::vector<double> ranges;
  for (const AgilityChannel& c : thrusters) {
    ranges.push_back(c.range ? *c.range : valid_range(c.values));
  }
  AgilityResult result;
  int timed = 0;
  for (AgilityStep& s : steps) {
    if (s.t_end - s.t_step < options.min_window_s) {
      throw core::InputError(
          {"", {}, {}, "step at t = " + fmt(s.t_step) + " s"},
          "step too short: " + fmt(s.t_end - s.t_step) +
              " s to the next change or the end of "
              "the log, under the minimum " +
              fmt(options.min_window_s) + " s",
          "hold each thrust demand longer, cut the log before a short last step, or lower the "
          "minimum window");
    }
    for (std::size_t k = 0; k < thrusters.size(); ++k) {
      // No response below min_response_fraction of the channel's range; a constant
      // channel (range 0) never responds.
      const double min_change = std::isfinite(ranges[k]) && ranges[k] > 0.0
                                    ? options.min_response_fraction * ranges[k]
                                    : std::numeric_limits<double>::infinity();
      s.thrusters.push_back(response_time_632(t, thrusters[k].values, s.t_step, s.t_end, min_change,
                                              options, thrusters[k].name));
      if (s.thrusters.back().response_s) ++timed;
    }
    if (!speed.empty()) {
      s.speed = response_time_632(t, speed, s.t_step, s.t_end, options.min_speed_change_mps,
                                  options, "speed");
    }
  }
  result.steps = std::move(steps);
  if (timed == 0) {
    result.status = FitStatus::kFailed;
    result.message =
        "no thruster responded to any of the " + std::to_string(result.steps.size()) + " step(s)";
  } else {
    result.status = FitStatus::kOk;
    result.message = std::to_string(result.steps.size()) + " step(s), " + std::to_string(timed) +
                     " thruster response time(s)";
  }
  return result;
}

}  // namespace

void AgilityOptions::validate() const {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(command_tolerance_pct)) {
    throw option_error("command tolerance " + fmt(command_tolerance_pct) + " %",
                       "give a tolerance > 0 %");
  }
  if (!(std::isfinite(min_demand_pct) && min_demand_pct >= 0.0)) {
    throw option_error("minimum demand " + fmt(min_demand_pct) + " %", "give a demand ≥ 0 %");
  }
  if (!positive(min_step_s)) throw option_error("minimum step " + fmt(min_step_s) + " s", "> 0");
  if (!positive(pre_step_s)) {
    throw option_error("pre-step time " + fmt(pre_step_s) + " s", "give a time > 0 s");
  }
  if (!(tail_fraction > 0.0 && tail_fraction <= 0.5)) {
    throw option_error("tail fraction " + fmt(tail_fraction), "give a fraction in (0, 0.5]");
  }
  if (!(min_response_fraction >= 0.0 && min_response_fraction < 1.0)) {
    throw option_error("minimum response fraction " + fmt(min_response_fraction),
                       "give a fraction in [0, 1)");
  }
  if (!(std::isfinite(min_speed_change_mps) && min_speed_change_mps >= 0.0)) {
    throw option_error("minimum speed change " + fmt(min_speed_change_mps) + " m/s",
                       "give a speed ≥ 0 m/s");
  }
  if (!positive(reversal_fraction)) {
    throw option_error("reversal fraction " + fmt(reversal_fraction), "give a fraction > 0");
  }
  if (!positive(min_window_s)) {
    throw option_error("minimum window " + fmt(min_window_s) + " s", "give a time > 0 s");
  }
}

AgilityResponse response_time_632(std::span<const double> t, std::span<const double> y,
                                  double t_step, double t_end, double min_change,
                                  const AgilityOptions& options, std::string name) {
  detail::check_same_length(t.size(), y.size(), name.empty() ? "output" : name);
  detail::check_time_axis(t, "time", 1);
  AgilityResponse r;
  r.name = std::move(name);

  // Level before the step: mean over [t₀ − pre_step_s, t₀); if that holds no valid sample,
  // the last valid sample before t₀.
  std::vector<double> pre;
  std::optional<std::size_t> last_pre;
  for (std::size_t i = 0; i < t.size() && t[i] < t_step; ++i) {
    if (!std::isfinite(y[i])) continue;
    last_pre = i;
    if (t[i] >= t_step - options.pre_step_s) pre.push_back(y[i]);
  }
  if (!last_pre) {
    r.notes.emplace_back("no sample before the step");
    return r;
  }
  if (pre.empty()) pre.push_back(y[*last_pre]);
  const double y0 = mean(pre);

  // Samples in the window, and the tail for y∞.
  std::vector<std::size_t> post;
  std::vector<double> tail;
  std::vector<double> tail_t;
  const double t_tail = t_end - options.tail_fraction * (t_end - t_step);
  for (std::size_t i = *last_pre + 1; i < t.size() && t[i] <= t_end; ++i) {
    if (!std::isfinite(y[i]) || t[i] < t_step) continue;
    post.push_back(i);
    if (t[i] >= t_tail) {
      tail.push_back(y[i]);
      tail_t.push_back(t[i]);
    }
  }
  r.y0 = y0;
  if (post.size() < 3 || tail.empty()) {
    r.notes.emplace_back("too few samples after the step (" + std::to_string(post.size()) + ")");
    return r;
  }
  const double y_inf = mean(tail);
  r.y_final = y_inf;
  const double dy = y_inf - y0;
  if (!(std::abs(dy) >= min_change) || !(std::abs(dy) > 0.0)) {
    r.notes.emplace_back("no response: |Δy| = " + fmt(std::abs(dy)) + " < " + fmt(min_change));
    return r;
  }

  // Normalised response p = (y − y₀)/Δy; the crossing of 0.632 from below.
  std::vector<double> post_y;
  for (const std::size_t i : post) post_y.push_back(y[i]);
  const double sigma_p = detail::difference_noise_sigma(post_y) / std::abs(dy);
  const auto p = [&](std::size_t i) { return (y[i] - y0) / dy; };
  std::optional<double> t_first;
  std::optional<double> t_last;
  std::optional<std::size_t> i_high;
  std::size_t prev = *last_pre;
  for (const std::size_t i : post) {
    const double pp = p(prev);
    const double pc = p(i);
    if (pp < kLevel632 && pc >= kLevel632) {
      const double tc = t[prev] + (kLevel632 - pp) / (pc - pp) * (t[i] - t[prev]);
      if (!t_first) t_first = tc;
      t_last = tc;
    }
    if (t_first && pc >= kLevel632 + 3.0 * sigma_p) {
      i_high = i;
      break;
    }
    prev = i;
  }
  if (!t_first) {
    r.notes.emplace_back("never crosses 63.2 % of the response from below");
    return r;
  }
  r.response_s = 0.5 * (*t_first + *t_last) - t_step;
  r.crossing_span_s = *t_last - *t_first;

  // Notes on the shape after the crossing.
  double p_min = std::numeric_limits<double>::infinity();
  double p_max = -p_min;
  for (const std::size_t i : post) {
    if (i_high && i < *i_high) continue;
    p_min = std::min(p_min, p(i));
    p_max = std::max(p_max, p(i));
  }
  if (p_max - 1.0 > options.reversal_fraction) {
    r.notes.emplace_back("overshoots the final level by " + fmt((p_max - 1.0) * 100.0) + " %");
  }
  if (p_min < kLevel632 - options.reversal_fraction) {
    r.notes.emplace_back("falls back to " + fmt(p_min * 100.0) +
                         " % of the response after the crossing");
  }
  if (tail.size() >= 3) {
    const detail::LineFit line = detail::fit_line(tail_t, tail);
    const double drift = std::abs(line.b * (tail_t.back() - tail_t.front()));
    if (drift > std::max(0.1 * std::abs(dy), 3.0 * line.residual_sigma)) {
      r.notes.emplace_back("not settled: drifts " + fmt(drift / std::abs(dy) * 100.0) +
                           " % of the response over the end of the window");
    }
  }
  return r;
}

std::vector<AgilityStep> find_agility_steps(std::span<const double> t,
                                            const AgilityCommand& command,
                                            const AgilityOptions& options) {
  options.validate();
  if (command.surge_pct.empty() || command.sway_pct.empty()) {
    throw core::InputError({"", {}, {}, "command.surge, command.sway"},
                           "no joystick demand to find the steps in",
                           "log the surge and sway demands [%], or give the steps as windows");
  }
  detail::check_same_length(t.size(), command.surge_pct.size(), "command.surge");
  detail::check_same_length(t.size(), command.sway_pct.size(), "command.sway");
  const bool has_yaw = !command.yaw_pct.empty();
  if (has_yaw) detail::check_same_length(t.size(), command.yaw_pct.size(), "command.yaw");
  detail::check_time_axis(t, "time", 1);

  struct Level {
    std::size_t first = 0;  // first sample of the level
    double t_start = 0.0;   // start of the transition into it
    double surge = 0.0;
    double sway = 0.0;
    double yaw = 0.0;
  };
  std::vector<Level> levels;
  std::size_t valid = 0;
  double t_last_valid = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double su = command.surge_pct[i];
    const double sw = command.sway_pct[i];
    const double ya = has_yaw ? command.yaw_pct[i] : 0.0;
    if (!std::isfinite(su) || !std::isfinite(sw) || !std::isfinite(ya)) continue;
    ++valid;
    t_last_valid = t[i];
    const double tol = options.command_tolerance_pct;
    if (levels.empty() || std::abs(su - levels.back().surge) > tol ||
        std::abs(sw - levels.back().sway) > tol || std::abs(ya - levels.back().yaw) > tol) {
      levels.push_back({i, t[i], su, sw, ya});
    }
  }
  if (valid < 2) {
    throw core::InputError({"", {}, {}, "command.surge, command.sway"},
                           "the joystick demands have fewer than 2 valid samples",
                           "check the column mapping of the demands");
  }
  if (levels.size() < 2) {
    throw core::InputError({"", {}, {}, "command.surge, command.sway"},
                           "the joystick demands are constant: no step",
                           "an agility test steps the thrust demand in each direction");
  }
  // Merge levels held for less than min_step_s into the next (a transition).
  std::vector<Level> merged;
  std::optional<double> pending;
  for (std::size_t k = 0; k < levels.size(); ++k) {
    const double t_next = k + 1 < levels.size() ? levels[k + 1].t_start : t_last_valid;
    const bool last = k + 1 == levels.size();
    if (!last && t_next - levels[k].t_start < options.min_step_s) {
      if (!pending) pending = levels[k].t_start;
      continue;
    }
    Level l = levels[k];
    if (pending) l.t_start = *pending;
    pending.reset();
    merged.push_back(l);
  }
  std::vector<AgilityStep> steps;
  for (std::size_t k = 1; k < merged.size(); ++k) {
    const Level& l = merged[k];
    const double m = std::hypot(l.surge, l.sway);
    if (m < options.min_demand_pct) continue;
    AgilityStep s;
    s.direction_deg = wrap_deg(std::atan2(l.sway, l.surge) * 180.0 / std::numbers::pi);
    s.magnitude_pct = m;
    if (has_yaw) s.yaw_pct = l.yaw;
    s.t_step = l.t_start;
    // The window ends at the last sample before the next level's transition.
    double t_end = t_last_valid;
    if (k + 1 < merged.size()) {
      const double t_next = merged[k + 1].t_start;
      const auto it = std::lower_bound(t.begin(), t.end(), t_next);
      t_end = it == t.begin() ? t_next : *(it - 1);
    }
    s.t_end = t_end;
    steps.push_back(std::move(s));
  }
  if (steps.empty()) {
    throw core::InputError({"", {}, {}, "command.surge, command.sway"},
                           "no step to a thrust demand of at least " + fmt(options.min_demand_pct) +
                               " % in the joystick demands",
                           "an agility test steps the surge/sway demand; check the unit (%)");
  }
  return steps;
}

AgilityResult analyse_agility(std::span<const double> t, const AgilityCommand& command,
                              std::span<const AgilityChannel> thrusters,
                              std::span<const double> speed_mps, const AgilityOptions& options) {
  options.validate();
  check_channels(t, thrusters, speed_mps);
  return respond(t, find_agility_steps(t, command, options), thrusters, speed_mps, options);
}

AgilityResult analyse_agility(std::span<const double> t, std::span<const AgilityWindow> windows,
                              std::span<const AgilityChannel> thrusters,
                              std::span<const double> speed_mps, const AgilityOptions& options) {
  options.validate();
  check_channels(t, thrusters, speed_mps);
  detail::check_time_axis(t, "time", 1);
  if (windows.empty()) {
    throw core::InputError({"", {}, {}, "windows"}, "no joystick demand and no step window",
                           "log command.surge and command.sway, or give the steps as windows");
  }
  if (t.empty()) throw core::InputError({"", {}, {}, "time"}, "the log is empty", "");
  std::vector<AgilityStep> steps;
  for (const AgilityWindow& w : windows) {
    // The windows are the request's option "window": errors name it, and the window by its time.
    const std::string where = "window at t = " + fmt(w.t_step) + " s: ";
    if (!(std::isfinite(w.t_step) && std::isfinite(w.t_end) && w.t_end > w.t_step)) {
      throw core::InputError::for_option(
          "window", where + "window end " + fmt(w.t_end) + " s is not after the step",
          "give t_step < t_end");
    }
    if (w.t_step <= t.front() || w.t_end > t.back()) {
      throw core::InputError::for_option("window",
                                         where + "window [" + fmt(w.t_step) + ", " + fmt(w.t_end) +
                                             "] s is not inside the log (" + fmt(t.front()) +
                                             " to " + fmt(t.back()) + " s)",
                                         "the step needs samples before it; check the times");
    }
    if (!std::isfinite(w.direction_deg) || !std::isfinite(w.magnitude_pct)) {
      throw core::InputError::for_option("window", where + "direction or magnitude is not a number",
                                         "give the commanded direction [deg] and thrust [%]");
    }
    AgilityStep s;
    s.direction_deg = wrap_deg(w.direction_deg);
    s.magnitude_pct = w.magnitude_pct;
    s.yaw_pct = w.yaw_pct;
    s.t_step = w.t_step;
    s.t_end = w.t_end;
    steps.push_back(std::move(s));
  }
  std::sort(steps.begin(), steps.end(),
            [](const AgilityStep& a, const AgilityStep& b) { return a.t_step < b.t_step; });
  return respond(t, std::move(steps), thrusters, speed_mps, options);
}

std::string agility_case_label(const AgilityStep& step, double min_demand_pct) {
  const auto round5 = [](double v) { return 5.0 * std::round(v / 5.0); };
  std::string label = fmt(round5(step.magnitude_pct)) + " % thrust";
  if (!step.yaw_pct) return label + ", yaw not logged";
  if (std::abs(*step.yaw_pct) < min_demand_pct) return label + ", no yaw";
  return label + ", yaw " + fmt(round5(*step.yaw_pct)) + " %";
}

}  // namespace dynpos::ident
