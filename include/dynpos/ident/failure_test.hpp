#pragma once
/// \file
/// Thruster failure tests (DP annual trials, IMCA M 190; FMEA proving trials): the trips of
/// units found in their feedback, and per trip the excursion of the control origin, the heading
/// excursion, the recovery and the redistribution of thrust to the other units.
///
/// Detection, per unit on a = |feedback| (docs/theory.md, "Failure test"):
/// - a is smoothed by a centered running median over `median_window_s` (single spikes go);
///   S = its largest value in the log (the unit's full scale there); σ̂ = the noise of a from
///   first differences of its valid samples;
/// - near zero: smoothed a ≤ z = max(zero_fraction·S, 4σ̂);
/// - a trip is a stretch near zero that starts at t_z after a sample above z and lasts at least
///   `min_off_s`, where
///   - the level before is clearly non-zero: L, the median of a over the `level_window_s`
///     ending `max_fall_s` before t_z, is ≥ max(min_level_fraction·S, 2·z);
///   - the fall is fast: the last sample before t_z with smoothed a ≥ fall_from_fraction·L is
///     at most `max_fall_s` before t_z (a commanded ramp to zero over tens of seconds is not a
///     trip: its level `max_fall_s` + `level_window_s`/2 before t_z is too low for that);
///   - it was not ordered: with the unit's order logged, when the feedback has fallen below
///     half its value of the 2 s before t_f, the order (its mean |order| over the 1 s up to
///     then, `commanded_within_s` later) is still above a third of its mean from 5 s to 2 s
///     before t_f (an order the feedback follows leads the fall; a tripped unit's holds or drifts;
///     means: an order chattering at the control rate is followed as its mean);
///   - another unit takes over: its mean |feedback| over `redistribution_window_s` after the
///     failure differs from the mean over as long before by ≥ max(takeover_fraction·S', 3σ̂')
///     with S', σ̂' its own scale and noise (not required when no other unit is logged, nor
///     when the tripped unit's order is: the order tells a trip from a stop, and after a bus
///     failure no unit may be left to take over).
/// - the failure instant t_f is the start of the fall, timed between the feedback's samples:
///   on the shaft speed (a^(1/shaft_speed_exponent)), a level line before t_f and the unit's
///   speed control decaying to zero after it (an acceleration limit, then first order), fitted
///   by least squares over onsets from 0.4·`max_fall_s` before the last sample at
///   fall_from_fraction·L to the next sample, each with its best time constant and limit; t_f
///   is the middle of the onsets that fit within 4σ² of the best (fall_onset.hpp); with the
///   unit's order logged, the samples before an onset may follow the order (dead time and lag
///   fitted on the minute before) instead of the line, and the search reaches on to the first
///   sample below fall_from_fraction of what following it gives (while that is above a third
///   of the level). Without
///   samples for it, the last sample before the fall still at the level: smoothed
///   a ≥ L − max(0.1·L, 3σ̂). A unit whose feedback lags its shaft has t_f that much late.
/// Trips of several units starting within `max_fall_s` of each other are one event (a bus
/// failure), named after the first.
///
/// Figures per event, with t_f its failure instant:
/// - the pre-failure window [t_f − pre_window_s, t_f], cut at the previous event: the mean
///   position, the circular mean heading, and the footprint: the largest horizontal distance
///   from the mean position during the window;
/// - the response span: from t_f to the first of t_f + response_window_s, the next event and
///   the end of the log; in it the peak excursion (largest distance from the pre-failure mean)
///   and its time after t_f, and the largest |heading − pre-failure mean|;
/// - the position at every row: fixes at most `fix_gap_s` apart joined by a natural cubic
///   spline (a 1 Hz position reference in a 10 Hz log), so that the footprint, the peak and the
///   recovery are those of the motion, not of where the fixes fell on its waves;
/// - recovery: from t_f to the first sample at or after the peak from which the distance,
///   through a centered running median over `recovery_median_s` (a single noisy fix above the
///   footprint does not hold it back), stays within the footprint for `hold_s`, inside the
///   response span; missing when there is none; 0 when that median distance never leaves the
///   footprint (a single wave crest or fix above it is no departure);
/// - redistribution: per other unit the mean |feedback| over `redistribution_window_s` before
///   t_f (cut at the previous event) and after it (cut at the next one), and the change.

#include <optional>
#include <string>
#include <vector>

namespace dynpos::ident {

/// The feedback of one unit (thruster): thrust [N] or shaft speed [rps], NaN = missing.
struct UnitFeedback {
  std::string name;
  std::vector<double> values;
  /// The unit's order as logged (its thrust or shaft speed command, the feedback's kind), NaN
  /// = missing; empty: not logged.
  std::vector<double> order = {};
  /// |values| ∝ |shaft speed|^this: 1 for a shaft speed, 2 for a thrust (the fall is timed on
  /// the shaft speed, whose speed control decays at first order).
  double shaft_speed_exponent = 1.0;
};

/// The logged channels, SI, on one time axis; NaN = missing sample, empty = not logged.
struct FailureTestInput {
  std::vector<double> t_s;              ///< strictly increasing
  std::vector<double> north_m, east_m;  ///< control origin, NED [m], any offset
  std::vector<double> heading_rad;
  std::vector<UnitFeedback> units;
};

struct FailureTestOptions {
  double pre_window_s = 60.0;             ///< pre-failure mean and footprint [s], > 0
  double redistribution_window_s = 30.0;  ///< before/after means of the other units [s], > 0
  double hold_s = 10.0;                   ///< recovered when within the footprint this long [s]
  double response_window_s = 300.0;       ///< peak and recovery searched this long [s], > 0
  double max_fall_s = 5.0;                ///< a trip falls to near zero within this [s], > 0
  double min_off_s = 20.0;                ///< a tripped unit stays near zero this long [s], > 0
  double level_window_s = 20.0;           ///< the level before the fall [s], > 0
  double median_window_s = 1.0;           ///< running median of the feedback [s], ≥ 0
  double recovery_median_s = 3.0;         ///< … of the distance, for the recovery [s], ≥ 0
  /// The recovery is at the footprint's edge when the distance's median peak lies within this
  /// share of the footprint (above or below) [-], ≥ 0. Source: the footprint, the largest of a
  /// minute's distances, moves by that much with where the fixes fall: 1.10 m from the fixes
  /// against 1.18 m of the true motion on the virtual dp-thruster-trip (seed 6), whose median
  /// peak between them made the recovery 83 s from the log and 0 in the truth.
  double footprint_edge_share = 0.1;
  /// Fixes at most this far apart are joined at the rows between them by a cubic spline [s],
  /// ≥ 0; a longer gap (a dropout) stays missing.
  double fix_gap_s = 2.0;
  double zero_fraction = 0.05;      ///< near zero: of the full scale, in (0, 1)
  double min_level_fraction = 0.2;  ///< clearly non-zero: of the full scale, in (0, 1)
  double fall_from_fraction = 0.6;  ///< the fall is timed from this share of the level
  double takeover_fraction = 0.05;  ///< another unit's change, of its full scale, ≥ 0
  /// With the unit's order logged: a fall whose order had dropped below a third of its value
  /// before the fall when the feedback had halved (or at most this long after [s]) was ordered (a
  /// stop), not a trip. A DP system keeps ordering a tripped unit until it flags the fault
  /// from the feedback, seconds later. ≥ 0.
  double commanded_within_s = 0.0;

  /// Throws core::InputError for the first bad option, named by its request key
  /// ("pre_window", "redistribution_window", "hold", "response_window", "max_fall",
  /// "min_off", or the field name for the others).
  void validate() const;
};

/// How the failure instant was found.
enum class OnsetMethod {
  kFallFit,    ///< start of a fit of the unit's fall (its speed control's decay)
  kLastLevel,  ///< last sample still at the pre-failure level
};

/// A unit's scale in the log, as the detection used it (SI, the feedback's unit).
struct UnitScale {
  std::string name;
  double full_scale = 0.0;   ///< S: largest smoothed |feedback|
  double noise_sigma = 0.0;  ///< σ̂ from first differences
  double near_zero = 0.0;    ///< z: the near-zero band
};

/// The mean |feedback| of another unit before and after a failure (SI); missing with fewer
/// than 3 valid samples in a window.
struct UnitRedistribution {
  std::string unit;
  std::optional<double> mean_before;
  std::optional<double> mean_after;
  std::optional<double> change;  ///< after − before
  bool took_over = false;        ///< |change| reached the take-over threshold
};

struct FailureEvent {
  double time_s = 0.0;             ///< t_f, the failure instant (start of the fall) [s]
  std::string unit;                ///< the unit that tripped (the first, if several did)
  std::vector<std::string> units;  ///< every unit that tripped in this event
  OnsetMethod onset = OnsetMethod::kLastLevel;
  double level_before = 0.0;                      ///< L of `unit` (SI, its feedback's unit)
  std::optional<double> fall_time_constant_s;     ///< of the shaft speed's fall, when fitted
  double near_zero_s = 0.0;                       ///< t_z: first sample near zero [s]
  double pre_from_s = 0.0, pre_to_s = 0.0;        ///< the pre-failure window [s]
  double response_to_s = 0.0;                     ///< the end of the response span [s]
  std::optional<double> pre_north_m, pre_east_m;  ///< pre-failure mean position (NED)
  std::optional<double> pre_heading_rad;          ///< pre-failure circular mean heading
  std::optional<double> footprint_m;              ///< largest pre-failure distance from the mean
  std::optional<double> peak_excursion_m;
  std::optional<double> time_to_peak_s;
  std::optional<double> recovery_s;
  /// The peak of the distance's running median, what the recovery is judged on [m].
  std::optional<double> median_peak_m;
  /// The median peak within footprint_edge_share of the footprint: whether the vessel left it,
  /// and so the recovery, turns on where the footprint is drawn.
  bool recovery_at_footprint_edge = false;
  std::optional<double> peak_heading_rad;          ///< largest |heading − pre-failure mean|
  std::vector<UnitRedistribution> redistribution;  ///< the units that did not trip
};

struct FailureTestResult {
  std::vector<UnitScale> units;      ///< in the input's order
  std::vector<FailureEvent> events;  ///< in time order
};

/// Finds the trips and their figures. Position and heading are optional (their figures are
/// missing without them). Throws core::InputError if the options are bad, no unit is given,
/// the time axis is not strictly increasing, or a channel's length differs from it.
FailureTestResult analyse_failure_test(const FailureTestInput& input,
                                       const FailureTestOptions& options = {});

/// The figures of a failure at a known instant t_f [s] (the pre-failure window, the peak and
/// heading excursion, the recovery; no redistribution), as analyse_failure_test() gives them for
/// a trip it found: the simulator's truth of its failures has the same meanings. Throws
/// core::InputError as analyse_failure_test() does (no unit needed).
FailureEvent failure_excursion(const FailureTestInput& input, double t_f_s,
                               const FailureTestOptions& options = {});

}  // namespace dynpos::ident
