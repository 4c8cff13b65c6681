#include "dynpos/ident/step_detector.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dynpos/core/error.hpp"
#include "dynpos/core/few_valued_median.hpp"
#include "dynpos/core/parallel_for.hpp"
#include "plateaus.hpp"
#include "series.hpp"
#include "window_scan.hpp"

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
  if (!(large_change_fraction >= 0.0 && large_change_fraction < 1.0)) {
    bad("large-change fraction " + fmt(large_change_fraction), "give a fraction in [0, 1)");
  }
  if (!(change_window_s > 0.0 && std::isfinite(change_window_s))) {
    bad("change window " + fmt(change_window_s) + " s", "give a finite duration > 0 s");
  }
  if (!(settle_s >= 0.0 && std::isfinite(settle_s))) {
    bad("settling time " + fmt(settle_s) + " s", "give a finite duration ≥ 0 s");
  }
  if (!(settle_fraction >= 0.0 && settle_fraction < 1.0)) {
    bad("settling fraction " + fmt(settle_fraction), "give a fraction in [0, 1)");
  }
}

namespace {

// The valid (non-NaN) samples of an input, checked: equal lengths, increasing time, ≥ 3 valid.
// Views of the input itself when every sample is valid (the usual case: no copy of a long log),
// else of copies of the valid ones.
struct ValidSamples {
  std::span<const double> t, u;
  std::vector<double> t_copy, u_copy;
  bool all_valid = false;  // t and u are the input's own
};

// `time_checked`: t is a core::Log's time axis, finite and strictly increasing by its invariant.
ValidSamples valid_samples(std::span<const double> t, std::span<const double> u,
                           const StepDetectorOptions& options, bool time_checked = false) {
  const std::string& name = options.input_name;
  detail::check_same_length(t.size(), u.size(), name);
  if (!time_checked) detail::check_time_axis(t, name, options.jobs);
  ValidSamples v;
  const std::size_t missing = core::missing_count(u, options.jobs);
  if (missing == 0) {
    v.t = t;
    v.u = u;
    v.all_valid = true;
  } else {
    v.t_copy.reserve(u.size() - missing);
    v.u_copy.reserve(u.size() - missing);
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (!std::isnan(u[i])) {
        v.t_copy.push_back(t[i]);
        v.u_copy.push_back(u[i]);
      }
    }
    v.t = v.t_copy;
    v.u = v.u_copy;
  }
  if (v.u.size() < 3) {
    throw core::InputError({"", {}, {}, name},
                           "only " + std::to_string(v.u.size()) + " valid input samples",
                           "check the column map; the input must be logged");
  }
  return v;
}

// √(mean Δu²)/√2 from the counts of the squared differences Δu²: the smallest 98 % summed.
double trimmed_rms_of_counts(const core::FewValues& d2) {
  std::size_t left = std::max<std::size_t>(1, d2.n - d2.n / 50);
  const double keep = static_cast<double>(left);
  double sum = 0.0;
  for (std::size_t k = 0; k < d2.distinct && left > 0; ++k) {
    const std::size_t take = std::min(left, d2.counts[k].second);
    sum += d2.counts[k].first * static_cast<double>(take);
    left -= take;
  }
  return std::sqrt(sum / keep / 2.0);
}

// √(mean Δu²)/√2 over the differences of consecutive valid samples, the largest 2 % left out
// (the steps and ramps of a log with up to a few percent of its samples in transitions).
double trimmed_rms_sigma(std::span<const double> uv) {
  // Squared differences of few values (a command): summed from their counts.
  const auto d2_at = [&](std::size_t i) { return (uv[i + 1] - uv[i]) * (uv[i + 1] - uv[i]); };
  if (const auto few = core::few_values(uv.size() - 1, d2_at)) return trimmed_rms_of_counts(*few);
  std::vector<double> d2;
  d2.reserve(uv.size());
  for (std::size_t i = 1; i < uv.size(); ++i)
    d2.push_back((uv[i] - uv[i - 1]) * (uv[i] - uv[i - 1]));
  const std::size_t keep = std::max<std::size_t>(1, d2.size() - d2.size() / 50);
  std::nth_element(d2.begin(), d2.begin() + static_cast<std::ptrdiff_t>(keep - 1), d2.end());
  double sum = 0.0;
  for (std::size_t i = 0; i < keep; ++i) sum += d2[i];
  return std::sqrt(sum / static_cast<double>(keep) / 2.0);
}

// σ̂ of the file comment. A gap-free input whose differences take few values (a command) is
// counted once: the median and MAD of Δu and the trimmed sum of Δu² all follow from the counts
// of Δu, each the value its own pass gives.
double input_noise_sigma(std::span<const double> u, const ValidSamples& v) {
  if (v.all_valid && u.size() >= 3) {
    const auto du = core::few_values(u.size() - 1, [&](std::size_t i) { return u[i + 1] - u[i]; });
    if (du) {
      const double m = du->median();
      const auto deviation = du->mapped([m](double d) { return std::abs(d - m); });
      const auto d2 = du->mapped([](double d) { return d * d; });
      if (deviation && d2) {
        return std::max(1.4826 * deviation->median() / std::sqrt(2.0), trimmed_rms_of_counts(*d2));
      }
    }
  }
  return std::max(detail::difference_noise_sigma(u), trimmed_rms_sigma(v.u));
}

// The 3-sample running median of a series, sample by sample as it is asked for (no copy of a
// day-long input); the end samples are their own.
struct RunningMedian3 {
  std::span<const double> u;
  double operator[](std::size_t i) const {
    if (i == 0 || i + 1 >= u.size()) return u[i];
    return std::max(std::min(u[i - 1], u[i]), std::min(std::max(u[i - 1], u[i]), u[i + 1]));
  }
};

// What the threshold is set from: the input's noise, its largest change within change_window_s
// (S, after a 3-sample running median, so one bad sample does not set the scale of the steps)
// and its range (the first smallest and last largest value, as std::minmax_element).
struct InputScan {
  static constexpr std::size_t kBlock = 512;  // window starts taken at a time

  double noise_sigma = 0.0;
  double largest_change = 0.0;
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();

  // The scan of the windows starting in [i0, i1) and of their first samples. The windows are
  // taken a block of starts at a time, and a block is scanned only when the range of the
  // samples its windows can hold exceeds the largest change found so far: S is the same as
  // scanning every window, and the flat stretches of a command are passed over.
  void scan_windows(std::span<const double> tv, std::span<const double> uv, double w,
                    std::size_t i0, std::size_t i1) {
    const RunningMedian3 m{uv};
    std::size_t last = i0;  // the last sample of the window of the block's last start
    const auto extremes = detail::block_extremes(tv, m, w, i0, i1, kBlock);
    for (std::size_t b0 = i0; b0 < i1; b0 += kBlock) {
      const std::size_t b1 = std::min(i1, b0 + kBlock);
      while (last + 1 < tv.size() && tv[last + 1] <= tv[b1 - 1] + w) ++last;
      const auto [lo, hi] = detail::bounds_of(extremes, (b0 - i0) / kBlock, (last - i0) / kBlock);
      if (!(hi - lo > largest_change)) continue;
      detail::for_each_window(tv, m, w, b0, b1, [&](std::size_t, std::size_t, double l, double h) {
        largest_change = std::max(largest_change, h - l);
        return true;
      });
    }
    for (std::size_t i = i0; i < i1; ++i) {
      if (uv[i] < min) min = uv[i];
      if (uv[i] >= max) max = uv[i];
    }
  }

  // Joins the scan of the pieces after this one's.
  void join(const InputScan& later) {
    largest_change = std::max(largest_change, later.largest_change);
    if (later.min < min) min = later.min;
    if (later.max >= max) max = later.max;
  }
};

// The noise and the windows of the whole input, in pieces on `jobs` threads: the same result
// for any number.
InputScan scan_input(std::span<const double> u, const ValidSamples& v,
                     const StepDetectorOptions& options) {
  const std::size_t n = v.u.size();
  const std::size_t pieces =
      core::piece_count(n, 4 * core::job_count(options.jobs, n), detail::kShortestScanPiece);
  std::vector<InputScan> scans(pieces);
  double noise = 0.0;
  core::parallel_for(pieces + 1, options.jobs, [&](std::size_t k) {
    if (k == 0) {
      noise = input_noise_sigma(u, v);
      return;
    }
    // Scanned into a local, not into its slot: neighbouring slots share cache lines.
    const auto [i0, i1] = core::piece_of(n, pieces, k - 1);
    InputScan scan;
    scan.scan_windows(v.t, v.u, options.change_window_s, i0, i1);
    scans[k - 1] = scan;
  });
  for (std::size_t k = 1; k < pieces; ++k) scans.front().join(scans[k]);
  scans.front().noise_sigma = noise;
  return scans.front();
}

StepThreshold threshold_from(const InputScan& scan, const StepDetectorOptions& options) {
  StepThreshold s;
  s.noise_sigma = scan.noise_sigma;
  s.largest_change = scan.largest_change;
  const double h_noise = options.band ? *options.band : options.noise_factor * s.noise_sigma;
  s.from_min_step = options.min_step > 0.0;
  const double threshold =
      s.from_min_step ? options.min_step
                      : std::max(2.0 * h_noise, options.large_change_fraction * s.largest_change);
  double h = options.band ? *options.band : std::max(h_noise, 0.25 * threshold);
  // The user's min_step overrides the noise: the band narrows to half of it, so a step of
  // min_step leaves the band of its old level (a dithered order, whose dither is bounded).
  if (s.from_min_step && !options.band) h = std::min(h, 0.5 * threshold);
  // A noise-free input: a band of round-off size only (and > 0 for an input of zeros).
  h = std::max({h, 1e-9 * std::max({scan.max - scan.min, std::abs(scan.min), std::abs(scan.max)}),
                std::numeric_limits<double>::min()});
  s.band = h;
  s.threshold = std::max(threshold, 2.0 * h);
  return s;
}

// Crossing of the line u = a + b·t with the level L.
double line_time(const detail::LineFit& line, double level) { return (level - line.a) / line.b; }

// The step between plateaus p0 and p1, timed from the levels next to the transition.
Step step_between(const detail::Plateau& p0, const detail::Plateau& p1, std::span<const double> tv,
                  std::span<const double> uv, const StepThreshold& scale, StepTiming timing) {
  const double h = scale.band;
  const double l0 = p0.end_level;
  const double l1 = p1.start_level;
  // Last sample in the band around the old level, first in the band around the new one.
  std::size_t i_old = p1.begin - 1;
  while (i_old > p0.begin && std::abs(uv[i_old] - l0) > h) --i_old;
  // Last sample still at the old level (within 3σ̂ of it: exactly on it for a clean order).
  std::size_t i_at_old = i_old;
  while (i_at_old > p0.begin && std::abs(uv[i_at_old] - l0) > 3.0 * scale.noise_sigma) {
    --i_at_old;
  }
  std::size_t i_new = i_old + 1;
  while (i_new < p1.end && std::abs(uv[i_new] - l1) > h) ++i_new;

  Step step;
  step.u_before = p0.tail_level;
  step.u_after = p1.head_level;
  step.t_begin = tv[p0.begin];
  step.t_step = tv[i_old + 1];
  step.t_ramp_end = tv[i_new];
  const double jump = l1 - l0;
  const bool trigger = timing == StepTiming::kTrigger;
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
      // A command's ramp starts after its last sample at the old level, however its line
      // extends (less the time the ramp takes to cross 3σ̂ of noise, which a sample on it may
      // still be within); a trigger's onset may be earlier (see the file comment).
      const double earliest =
          trigger
              ? step.t_begin
              : std::max(step.t_begin, tv[i_at_old] - 3.0 * scale.noise_sigma / std::abs(line.b));
      step.t_step = std::clamp(line_time(line, l0), earliest, tv[i_old + 1]);
      if (!trigger) {
        step.t_ramp_end =
            std::clamp(line_time(line, l1), std::max(tv[i_new - 1], step.t_step), tv[p1.end]);
      }
    }
  }
  return step;
}

}  // namespace

namespace {

// The steps of the valid samples v of u(t), on the scale found for them; `range` is the largest
// minus the smallest valid sample.
StepDetection detect_in(std::span<const double> t, const ValidSamples& v,
                        const StepDetectorOptions& options, const StepThreshold& scale,
                        double range) {
  const std::span<const double> tv = v.t;
  const std::span<const double> uv = v.u;
  const double h = scale.band;
  StepDetection out;
  out.noise_sigma = scale.noise_sigma;
  out.band = h;
  out.threshold = scale.threshold;
  if (range <= out.threshold) {
    out.message = "constant input: it varies by " + fmt(range) + ", less than the step threshold " +
                  fmt(out.threshold);
    return out;
  }
  const std::vector<detail::Plateau> plateaus =
      detail::merge_levels(detail::find_plateaus(tv, uv, h, options.min_plateau_s, options.jobs),
                           tv, uv, h, out.threshold, options);
  if (plateaus.size() < 2) {
    out.message = plateaus.empty() ? "no step found: the input never holds a level (±" + fmt(h) +
                                         ") for " + fmt(options.min_plateau_s) + " s"
                                   : "no step found: the input holds one level only";
    return out;
  }
  std::size_t below_threshold = 0;
  for (std::size_t k = 0; k + 1 < plateaus.size(); ++k) {
    Step step = step_between(plateaus[k], plateaus[k + 1], tv, uv, scale, options.timing);
    // The levels next to the transition changed by the threshold, but the levels the step
    // reports (the medians before and after it) did not: a wiggle on a drift, no step.
    if (std::abs(*step.u_after - *step.u_before) < out.threshold) {
      ++below_threshold;
      continue;
    }
    // The plateau may begin on the last ±2h of the previous ramp; the window starts after it,
    // but never after this step (a slow drift can end the previous ramp late).
    if (!out.steps.empty()) {
      step.t_begin = std::min(std::max(step.t_begin, out.steps.back().t_ramp_end), step.t_step);
    }
    out.steps.push_back(step);
  }
  if (out.steps.empty()) {
    out.message = "no step found: the " + std::to_string(below_threshold) +
                  " level change(s) found differ by less than the step threshold " +
                  fmt(out.threshold) + " between the levels before and after them";
    return out;
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

}  // namespace

StepThreshold step_threshold(std::span<const double> t, std::span<const double> u,
                             const StepDetectorOptions& options) {
  options.validate();
  const ValidSamples v = valid_samples(t, u, options);
  return threshold_from(scan_input(u, v, options), options);
}

namespace {

StepDetection detect_with_threshold(std::span<const double> t, std::span<const double> u,
                                    const StepDetectorOptions& options, bool time_checked) {
  options.validate();
  const ValidSamples v = valid_samples(t, u, options, time_checked);
  const InputScan scan = scan_input(u, v, options);
  return detect_in(t, v, options, threshold_from(scan, options), scan.max - scan.min);
}

}  // namespace

StepDetection detect_steps(std::span<const double> t, std::span<const double> u,
                           const StepDetectorOptions& options) {
  return detect_with_threshold(t, u, options, false);
}

StepDetection detect_steps(const core::Log& log, std::span<const double> u,
                           const StepDetectorOptions& options) {
  return detect_with_threshold(log.time(), u, options, true);
}

StepDetection detect_steps(std::span<const double> t, std::span<const double> u,
                           const StepDetectorOptions& options, const StepThreshold& scale) {
  options.validate();
  const ValidSamples v = valid_samples(t, u, options);
  const auto [min_it, max_it] = std::minmax_element(v.u.begin(), v.u.end());
  return detect_in(t, v, options, scale, *max_it - *min_it);
}

Step step_from_window(std::span<const double> t, std::span<const double> u,
                      const StepWindow& window, const StepDetectorOptions& options) {
  options.validate();
  const std::string& name = options.input_name;
  const core::InputLocation where{"", {}, {}, name};
  if (!u.empty()) detail::check_same_length(t.size(), u.size(), name);
  detail::check_time_axis(t, name, options.jobs);
  if (t.empty() && !(window.log_start_s && window.log_end_s)) {
    throw core::InputError(where, "the log is empty", "");
  }
  const double log_start = window.log_start_s.value_or(t.empty() ? 0.0 : t.front());
  const double log_end = window.log_end_s.value_or(t.empty() ? 0.0 : t.back());
  std::string window_text = "[";
  window_text += fmt(window.t_from);
  window_text += ", ";
  window_text += fmt(window.t_to);
  window_text += "] s";
  if (!(window.t_from < window.t_to)) {
    throw core::InputError::for_option("from/to", "window " + window_text + " is empty or reversed",
                                       "give from < to");
  }
  const double slack = detail::time_rounding_slack_s(log_start, log_end);
  if (window.t_from < log_start - slack || window.t_to > log_end + slack) {
    throw core::InputError::for_option("from/to",
                                       "window " + window_text + " is outside the log [" +
                                           fmt(log_start) + ", " + fmt(log_end) + "] s",
                                       "choose a window inside the logged time");
  }
  if (t.empty()) {
    throw core::InputError(where, "window " + window_text + " holds no sample of the log",
                           "choose a wider window");
  }
  const auto first = std::lower_bound(t.begin(), t.end(), window.t_from - slack);
  const auto last = std::upper_bound(t.begin(), t.end(), window.t_to + slack);
  const auto i0 = static_cast<std::size_t>(first - t.begin());
  const auto i1 = static_cast<std::size_t>(last - t.begin());

  if (window.t_step) {
    const double ts = *window.t_step;
    if (!(ts >= window.t_from && ts < window.t_to)) {
      throw core::InputError::for_option(
          "step_at", "step time " + fmt(ts) + " s is not inside the window " + window_text,
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
  if (found.steps.empty()) {
    throw core::InputError(where, found.message + " in the window " + window_text,
                           "check the input channel, or adjust min_plateau_s / band / min_step");
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
