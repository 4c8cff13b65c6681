#pragma once
/// \file
/// Finding the steps of a step test in a logged input (a command) or in a trigger signal.
///
/// A step test (section 3.2) changes an input from one constant level to another. In a log the
/// input is sampled with jitter and gaps (NaN), carries a little noise, and a rate-limited
/// command ramps over a few seconds instead of jumping. The detector splits the input into
/// plateaus (stretches where it stays inside a band of ±h around a level for at least
/// `min_plateau_s`) and transitions between them; every transition between two plateaus whose
/// levels differ by at least the step threshold is one step, up or down, from any baseline.
///
/// Noise level: σ̂ is the larger of 1.4826·MAD(Δu)/√2 and √(mean Δu²)/√2 over the differences
/// Δu of consecutive valid samples, the largest 2 % left out. The first is robust to the few
/// large differences at steps and to ramps; the second sees the wiggles of a held order that
/// changes in only a few samples (MAD = 0 for an order that mostly holds its value exactly).
///
/// Threshold (the smallest level change that is a step): with `min_step` given, min_step, and
/// the band narrowed to at most min_step/2 (the user knows the steps of the programme: a 9 rpm
/// step on an order dithered by ±2 rpm, 10 σ̂ of the adapted threshold, is found); otherwise
/// max(2·noise_factor·σ̂, large_change_fraction·S), S the largest change of the input within any
/// `change_window_s` (after a 3-sample running median, so one bad sample does not set it). The
/// large changes of a log set the scale of its steps: a 5 % fraction keeps sub-degree wiggles and
/// re-settling of a 30–70° azimuth programme, and a few rpm of dither on a 150 rpm programme, out,
/// and still finds 5 % lever steps. Band: h = max(noise_factor·σ̂, threshold/4), or `band` when
/// given.
///
/// A transition whose reported levels (the medians below) differ by less than the threshold is
/// no step, though the levels next to it did (a wiggle on a drift).
///
/// Levels: neighbouring plateaus are one level (a spike, a gap, wiggles or a slow drift split
/// them) unless the input changes by at least the threshold between the end of the one and the
/// start of the next (medians over min_plateau_s/2): comparing the levels next to the transition,
/// not whole plateaus, keeps a drift of any length from adding up to a step. A level held less
/// than `settle_s` after a step and left by a change back of less than `settle_fraction` of that
/// step (an order set to 33.3° and re-settled to 30.7° a few seconds later) belongs to the step:
/// its level after is the settled one. A step goes from the median of the last 20·min_plateau_s
/// before it to that of the first 20·min_plateau_s after it (the plateaus' edges on the ramps
/// left out).
///
/// Timing: the plateau before the step has level L₀, the one after L₁. For a command
/// (StepTiming::kCommand) the samples of the transition between 10 % and 90 % of L₁ − L₀ are
/// fitted by a straight line, and its crossings of L₀ and L₁ give the step time (start of the
/// ramp) and the end of the ramp, the start never before the last sample at L₀ (within 3σ̂,
/// less the time the ramp takes to cross 3σ̂: a ramp that starts fast and slows, whose line
/// reaches back before its start, is timed at that sample); with fewer than 3 such samples (an
/// ideal step) the step time is the first sample that left the band around L₀. A ramp is one step,
/// timed at its start: a FOPDT fitted from there sees the ramp's delay to its mid-point, R/2, in
/// the dead time, K and T unchanged to first order in R/T. For a trigger (StepTiming::kTrigger,
/// e.g. power feedback, which the thesis used to time steps when no setpoint was logged, section
/// 3.5.4) the onset of change is wanted: the line is fitted to the transition samples between
/// leaving the band and 30 % of the change, and extended back to L₀; this is exact for a
/// straight onset and a little early (never late) for a concave one such as a first-order
/// response, so dead times timed from it are not shortened.

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "dynpos/core/log.hpp"
#include "dynpos/core/parallel_for.hpp"

namespace dynpos::ident {

/// How step times are read from the signal the detector runs on.
enum class StepTiming {
  kCommand,  ///< the signal is the input itself: step time = start of the step or ramp
  kTrigger,  ///< the signal responds to the input (power feedback): step time = onset of change
};

/// Options for detect_steps() and step_from_window().
struct StepDetectorOptions {
  /// Smallest level change counted as a step [input unit], ≥ 0. 0 = adapted to the log from
  /// its noise and its largest changes (see the file comment).
  double min_step = 0.0;
  /// Fraction of the largest change that the adapted threshold is at least, in [0, 1).
  double large_change_fraction = 0.05;
  /// Window [s] > 0 over which the largest change of the input is measured (a ramp shorter than
  /// this counts whole).
  double change_window_s = 20.0;
  /// A level held less than this [s] ≥ 0 after a step can be re-settling (0: no re-settling).
  double settle_s = 10.0;
  /// Re-settling is a change back of less than this fraction of the step, in [0, 1).
  double settle_fraction = 0.25;
  /// Band half-width h in noise standard deviations, > 0 (used when `band` is not given).
  double noise_factor = 5.0;
  /// Band half-width h [input unit], > 0; overrides the noise estimate (use for a trigger with
  /// slow fluctuations, e.g. power in waves, that the difference-based estimate misses).
  std::optional<double> band;
  /// Shortest time [s] the input must stay within ±h of a level to count as a plateau, > 0.
  /// A step is found only if the input holds its new level this long.
  double min_plateau_s = 3.0;
  StepTiming timing = StepTiming::kCommand;
  /// Channel name used in error messages.
  std::string input_name = "input";
  /// Threads for the passes over the whole input (the time check, the largest change and the
  /// plateaus in pieces, the noise beside them); 0 = every core. The result does not depend on it.
  unsigned jobs = core::kEveryCore;

  /// Throws core::InputError naming the bad option.
  void validate() const;
};

/// One step of a step test and the stretch of log that belongs to it.
struct Step {
  double t_step = 0.0;             ///< [s] step time: start of the step or ramp (or onset, trigger)
  double t_ramp_end = 0.0;         ///< [s] end of the ramp; == t_step for an ideal step
  double t_begin = 0.0;            ///< [s] start of the plateau before the step (window start)
  double t_end = 0.0;              ///< [s] last sample before the next step, or end of log
  std::optional<double> u_before;  ///< input level before the step [input unit]
  std::optional<double> u_after;   ///< input level after the step [input unit]

  /// Δu = u_after − u_before, or nullopt when either level is unknown.
  std::optional<double> delta_u() const;
  /// Duration [s] of the ramp, t_ramp_end − t_step.
  double ramp_duration() const { return t_ramp_end - t_step; }
};

/// The scale of an input's steps: its noise, the band and the step threshold.
struct StepThreshold {
  double noise_sigma = 0.0;     ///< σ̂ of the input noise [input unit]
  double largest_change = 0.0;  ///< S, the largest change within change_window_s [input unit]
  double band = 0.0;            ///< band half-width h [input unit]
  double threshold = 0.0;       ///< smallest level change counted as a step [input unit]
  bool from_min_step = false;   ///< true when min_step set the threshold, false when adapted
};

/// The threshold and band of detect_steps() for an input u (see the file comment).
/// Throws core::InputError like detect_steps().
StepThreshold step_threshold(std::span<const double> t, std::span<const double> u,
                             const StepDetectorOptions& options = {});

/// Result of detect_steps().
struct StepDetection {
  std::vector<Step> steps;   ///< in time order; empty when none was found
  double noise_sigma = 0.0;  ///< σ̂ of the input noise [input unit]
  double band = 0.0;         ///< band half-width h used [input unit]
  double threshold = 0.0;    ///< smallest level change counted as a step [input unit]
  std::string message;       ///< why no step was found; empty when steps were found
};

/// Finds every step in an input u(t) (see the file comment for the method), with the threshold
/// step_threshold() gives, from one check and scan of the input.
/// t [s] strictly increasing and finite; u same length, NaN = missing.
/// Finding no step (a constant input, one level only) is a result: `steps` is empty and
/// `message` says why. Throws core::InputError if the lengths differ, t is not increasing, or
/// u has fewer than 3 valid samples.
StepDetection detect_steps(std::span<const double> t, std::span<const double> u,
                           const StepDetectorOptions& options = {});

/// detect_steps() of an input u of `log` (one value per row, NaN = missing): the log's time
/// axis, which the log has checked, is not checked again. The same result as detect_steps() of
/// log.time() and u.
StepDetection detect_steps(const core::Log& log, std::span<const double> u,
                           const StepDetectorOptions& options = {});

/// detect_steps() with the band and threshold of `scale`, a step_threshold() of this input (or
/// of the whole log this input is a stretch of): a long log's noise and largest change are then
/// measured once. The returned noise_sigma is scale's.
StepDetection detect_steps(std::span<const double> t, std::span<const double> u,
                           const StepDetectorOptions& options, const StepThreshold& scale);

/// An explicit analysis window [t_from, t_to] [s], with an optional known step time [s].
struct StepWindow {
  double t_from = 0.0;
  double t_to = 0.0;
  std::optional<double> t_step;
  /// How far the log reaches [s] when t holds only the window's rows (a log read within the
  /// window); unset: t.front() and t.back().
  std::optional<double> log_start_s;
  std::optional<double> log_end_s;
};

/// The step in an explicit window. With window.t_step given, the levels are the medians of u
/// before and after it (nullopt when u is empty: no input logged); without it, detect_steps()
/// runs on the window and exactly one step must be found.
/// Throws core::InputError if the window is empty or reversed, or lies (partly) outside the log
/// (option "from/to"), t_step is not inside it (option "step_at"), u is constant in it, or no or
/// several steps are found.
Step step_from_window(std::span<const double> t, std::span<const double> u,
                      const StepWindow& window, const StepDetectorOptions& options = {});

}  // namespace dynpos::ident
