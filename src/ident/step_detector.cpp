#include "dynpos/ident/step_detector.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

#include "dynpos/core/error.hpp"
#include "series.hpp"

namespace dynpos::ident {

using detail::fmt;

std::optional<double> Step::delta_u() const {
  if (!u_before || !u_after) return std::nullopt;
  return *u_after - *u_before;
}

void StepDetectorOptions::validate() const {
  const auto bad = [](const std::string& what, const std::string& hint) {
    throw core::InputError({"", {}, {}, "step detector options"}, what, hint);
  };
  if (!(min_step >= 0.0 && std::isfinite(min_step))) {
    bad("minimum step " + fmt(min_step), "give a finite step size ≥ 0");
  }
  if (!(noise_factor > 0.0 && std::isfinite(noise_factor))) {
    bad("noise factor " + fmt(noise_factor), "give a finite factor > 0");
  }
  if (band && !(*band > 0.0 && std::isfinite(*band))) {
    bad("band " + fmt(*band), "give a finite band half-width > 0");
  }
  if (!(min_plateau_s > 0.0 && std::isfinite(min_plateau_s))) {
    bad("minimum plateau " + fmt(min_plateau_s) + " s", "give a finite duration > 0 s");
  }
}

namespace {

struct Plateau {
  std::size_t begin = 0;  // first and last index into the valid samples
  std::size_t end = 0;
  double level = 0.0;
};

double median_of(const std::vector<double>& x, std::size_t begin, std::size_t end) {
  return detail::median(std::vector<double>(x.begin() + static_cast<std::ptrdiff_t>(begin),
                                            x.begin() + static_cast<std::ptrdiff_t>(end) + 1));
}

// Plateaus: unions of windows [tᵢ, tᵢ + w] in which the input varies by at most 2h, split where
// the window level moves more than h from the plateau's first level (a slow drift).
std::vector<Plateau> find_plateaus(const std::vector<double>& tv, const std::vector<double>& uv,
                                   double h, double w) {
  const std::size_t n = tv.size();
  std::vector<Plateau> plateaus;
  std::deque<std::size_t> max_q;  // indices of decreasing values: front is the window maximum
  std::deque<std::size_t> min_q;
  std::size_t j = 0;  // one past the window end
  double ref = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    while (j < n && tv[j] <= tv[i] + w) {
      while (!max_q.empty() && uv[max_q.back()] <= uv[j]) max_q.pop_back();
      max_q.push_back(j);
      while (!min_q.empty() && uv[min_q.back()] >= uv[j]) min_q.pop_back();
      min_q.push_back(j);
      ++j;
    }
    while (max_q.front() < i) max_q.pop_front();
    while (min_q.front() < i) min_q.pop_front();
    const std::size_t last = j - 1;
    // A window cut short by a gap or the end of the log must still span half the duration.
    if (tv[last] - tv[i] < 0.5 * w) continue;
    const double hi = uv[max_q.front()];
    const double lo = uv[min_q.front()];
    if (hi - lo > 2.0 * h) continue;
    const double mid = 0.5 * (hi + lo);
    if (!plateaus.empty() && i <= plateaus.back().end + 1 && std::abs(mid - ref) <= h) {
      plateaus.back().end = std::max(plateaus.back().end, last);
    } else {
      const std::size_t begin = plateaus.empty() ? i : std::max(i, plateaus.back().end + 1);
      if (begin > last) continue;
      plateaus.push_back({begin, last, 0.0});
      ref = mid;
    }
  }
  for (Plateau& p : plateaus) p.level = median_of(uv, p.begin, p.end);
  return plateaus;
}

// Neighbouring plateaus closer than the threshold are one level (split by a spike or gap).
std::vector<Plateau> merge_levels(const std::vector<Plateau>& in, const std::vector<double>& uv,
                                  double threshold) {
  std::vector<Plateau> out;
  for (const Plateau& p : in) {
    if (!out.empty() && std::abs(p.level - out.back().level) < threshold) {
      out.back().end = p.end;
      out.back().level = median_of(uv, out.back().begin, out.back().end);
    } else {
      out.push_back(p);
    }
  }
  return out;
}

// Crossing of the line u = a + b·t with the level L.
double line_time(const detail::LineFit& line, double level) { return (level - line.a) / line.b; }

}  // namespace

StepDetection detect_steps(std::span<const double> t, std::span<const double> u,
                           const StepDetectorOptions& options) {
  options.validate();
  const std::string& name = options.input_name;
  const core::InputLocation where{"", {}, {}, name};
  detail::check_same_length(t.size(), u.size(), name);
  detail::check_time_axis(t, name);
  std::vector<double> tv;
  std::vector<double> uv;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!std::isnan(u[i])) {
      tv.push_back(t[i]);
      uv.push_back(u[i]);
    }
  }
  if (uv.size() < 3) {
    throw core::InputError(where, "only " + std::to_string(uv.size()) + " valid input samples",
                           "check the column map; the input must be logged");
  }
  const auto [min_it, max_it] = std::minmax_element(uv.begin(), uv.end());
  const double range = *max_it - *min_it;

  StepDetection out;
  out.noise_sigma = detail::difference_noise_sigma(u);
  double h = options.band
                 ? *options.band
                 : std::max(options.noise_factor * out.noise_sigma, 0.25 * options.min_step);
  // A noise-free input: a band of round-off size only.
  h = std::max(h, 1e-9 * std::max({range, std::abs(*min_it), std::abs(*max_it)}));
  out.band = h;
  out.threshold = std::max(options.min_step, 2.0 * h);
  if (range <= out.threshold) {
    throw core::InputError(where,
                           "constant input: it varies by " + fmt(range) +
                               ", less than the step threshold " + fmt(out.threshold),
                           "check the input channel, or lower min_step / band");
  }

  const std::vector<Plateau> plateaus =
      merge_levels(find_plateaus(tv, uv, h, options.min_plateau_s), uv, out.threshold);
  if (plateaus.size() < 2) {
    throw core::InputError(where,
                           plateaus.empty()
                               ? "no step found: the input never holds a level (±" + fmt(h) +
                                     ") for " + fmt(options.min_plateau_s) + " s"
                               : "no step found: the input holds one level only",
                           "check the input channel, or adjust min_plateau_s / band / min_step");
  }

  for (std::size_t k = 0; k + 1 < plateaus.size(); ++k) {
    const Plateau& p0 = plateaus[k];
    const Plateau& p1 = plateaus[k + 1];
    const double l0 = p0.level;
    const double l1 = p1.level;
    // Last sample in the band around the old level, first in the band around the new one.
    std::size_t i_old = p1.begin - 1;
    while (i_old > p0.begin && std::abs(uv[i_old] - l0) > h) --i_old;
    std::size_t i_new = i_old + 1;
    while (i_new < p1.end && std::abs(uv[i_new] - l1) > h) ++i_new;

    Step step;
    step.u_before = l0;
    step.u_after = l1;
    step.t_begin = tv[p0.begin];
    step.t_step = tv[i_old + 1];
    step.t_ramp_end = tv[i_new];
    const double jump = l1 - l0;
    const bool trigger = options.timing == StepTiming::kTrigger;
    // Command: the ramp between 10 % and 90 %; trigger: the onset, up to 30 %.
    const double f_lo = trigger ? -1.0 : 0.1;
    const double f_hi = trigger ? 0.3 : 0.9;
    std::vector<double> xs;
    std::vector<double> ys;
    for (std::size_t i = i_old + 1; i < i_new; ++i) {
      const double f = (uv[i] - l0) / jump;
      if (f >= f_lo && f <= f_hi) {
        xs.push_back(tv[i]);
        ys.push_back(uv[i]);
      }
    }
    const std::size_t needed = trigger ? 2 : 3;
    if (xs.size() >= needed) {
      const detail::LineFit line = detail::fit_line(xs, ys);
      if (line.b * jump > 0.0) {
        step.t_step = std::clamp(line_time(line, l0), step.t_begin, tv[i_old + 1]);
        if (!trigger) {
          step.t_ramp_end =
              std::clamp(line_time(line, l1), std::max(tv[i_new - 1], step.t_step), tv[p1.end]);
        }
      }
    }
    // The plateau may begin on the last ±2h of the previous ramp; the window starts after it,
    // but never after this step (a slow drift can end the previous ramp late).
    if (!out.steps.empty()) {
      step.t_begin = std::min(std::max(step.t_begin, out.steps.back().t_ramp_end), step.t_step);
    }
    out.steps.push_back(step);
  }
  // Each window runs to the last log sample before the next step, the last one to the end.
  for (std::size_t k = 0; k < out.steps.size(); ++k) {
    if (k + 1 < out.steps.size()) {
      const double next = out.steps[k + 1].t_step;
      const auto it = std::lower_bound(t.begin(), t.end(), next);
      out.steps[k].t_end = it == t.begin() ? t.front() : *(it - 1);
    } else {
      out.steps[k].t_end = t.back();
    }
  }
  return out;
}

Step step_from_window(std::span<const double> t, std::span<const double> u,
                      const StepWindow& window, const StepDetectorOptions& options) {
  options.validate();
  const std::string& name = options.input_name;
  const core::InputLocation where{"", {}, {}, name};
  if (!u.empty()) detail::check_same_length(t.size(), u.size(), name);
  detail::check_time_axis(t, name);
  if (t.empty()) throw core::InputError(where, "the log is empty", "");
  std::string window_text = "[";
  window_text += fmt(window.t_from);
  window_text += ", ";
  window_text += fmt(window.t_to);
  window_text += "] s";
  if (!(window.t_from < window.t_to)) {
    throw core::InputError(where, "window " + window_text + " is empty or reversed",
                           "give from < to");
  }
  const double slack = 1e-9 * std::max({1.0, std::abs(t.front()), std::abs(t.back())});
  if (window.t_from < t.front() - slack || window.t_to > t.back() + slack) {
    throw core::InputError(where,
                           "window " + window_text + " is outside the log [" + fmt(t.front()) +
                               ", " + fmt(t.back()) + "] s",
                           "choose a window inside the logged time");
  }
  const auto first = std::lower_bound(t.begin(), t.end(), window.t_from - slack);
  const auto last = std::upper_bound(t.begin(), t.end(), window.t_to + slack);
  const auto i0 = static_cast<std::size_t>(first - t.begin());
  const auto i1 = static_cast<std::size_t>(last - t.begin());

  if (window.t_step) {
    const double ts = *window.t_step;
    if (!(ts >= window.t_from && ts < window.t_to)) {
      throw core::InputError(where,
                             "step time " + fmt(ts) + " s is not inside the window " + window_text,
                             "give a step time in [from, to)");
    }
    Step step;
    step.t_step = ts;
    step.t_ramp_end = ts;
    step.t_begin = window.t_from;
    step.t_end = window.t_to;
    if (!u.empty()) {
      std::vector<double> before;
      std::vector<double> after;
      for (std::size_t i = i0; i < i1; ++i) {
        if (std::isnan(u[i])) continue;
        (t[i] < ts ? before : after).push_back(u[i]);
      }
      if (!before.empty()) step.u_before = detail::median(std::move(before));
      if (!after.empty()) step.u_after = detail::median(std::move(after));
      if (step.u_before && step.u_after && *step.u_before == *step.u_after) {
        throw core::InputError(where,
                               "constant input: the input is " + fmt(*step.u_before) +
                                   " both before and after " + fmt(ts) + " s",
                               "check the step time and the input channel");
      }
    }
    return step;
  }

  if (u.empty()) {
    throw core::InputError(where, "no input and no step time for the window " + window_text,
                           "give the step time, or an input channel to detect it from");
  }
  StepDetection found;
  try {
    found = detect_steps(t.subspan(i0, i1 - i0), u.subspan(i0, i1 - i0), options);
  } catch (const core::InputError& e) {
    throw core::InputError(e.where(), e.problem() + " in the window " + window_text, e.hint());
  }
  if (found.steps.size() > 1) {
    throw core::InputError(
        where, std::to_string(found.steps.size()) + " steps found in the window " + window_text,
        "give the step time or a window around one step");
  }
  Step step = found.steps.front();
  step.t_begin = window.t_from;
  step.t_end = window.t_to;
  return step;
}

}  // namespace dynpos::ident
