#pragma once
/// \file
/// Thrust agility (thesis section 3.5.1, figures 3.1–3.3): a joystick thrust step in each of a
/// set of directions, and for each step the time until every thruster (and the vessel's speed)
/// has covered 63.2 % of its response, dead time included (the "total response" of section
/// 3.2: for the FOPDT (3.7) this time is δ + T).
///
/// Steps. From the joystick demands surge and sway [%] (and yaw [%]): the log is split where a
/// demand changes by more than `command_tolerance_pct`; a change that holds for less than
/// `min_step_s` is part of the transition to the next level. Every level whose thrust demand
/// m = √(surge² + sway²) is at least `min_demand_pct` is one agility step in the direction
/// θ = atan2(sway, surge) [deg], 0 = ahead, 90 = starboard (a return to zero thrust has no
/// direction and is skipped; so is a pure yaw demand). The step lasts until the next change or
/// the end of the log. Alternatively the steps are given as windows.
///
/// Response time of one signal y (thrust [N] of a thruster, or its shaft speed, or the total
/// speed U (3.19)) after a step at t₀ with window end t₁:
///  - y₀ = mean of y over the last `pre_step_s` before t₀ (at least one sample),
///  - y∞ = mean of y over the last `tail_fraction` of [t₀, t₁], Δy = y∞ − y₀,
///  - the 63.2 % level L = y₀ + 0.632·Δy; the response time is the time from t₀ to the first
///    crossing of L (linear interpolation between samples); with noise σ̂ (robust, from first
///    differences), the mean of the first and the last crossing of L before y is 3σ̂ past L.
/// A thruster "does not respond" when |Δy| < `min_response_fraction` of its range (max − min
/// of the channel over the whole log, or the range given), the speed when |ΔU| <
/// `min_speed_change_mps`: the time is then absent (JSON null), never 0. Notes flag a response that
/// reverses (an excursion against Δy larger than `reversal_fraction`·|Δy| after the crossing) or
/// has not settled in the window.

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "dynpos/ident/fit_status.hpp"

namespace dynpos::ident {

/// A signal whose response is timed: one thruster's thrust [N] (or shaft speed [rps]).
struct AgilityChannel {
  std::string name;                ///< thruster name, e.g. "port"
  std::span<const double> values;  ///< same length as t; NaN = missing
  /// Range of the channel [same unit] for the "does not respond" test; absent: max − min of
  /// the valid samples over the whole log.
  std::optional<double> range;
};

/// The joystick demands [%]; yaw may be empty (not logged).
struct AgilityCommand {
  std::span<const double> surge_pct;
  std::span<const double> sway_pct;
  std::span<const double> yaw_pct;
};

/// One agility step given explicitly.
struct AgilityWindow {
  double t_step = 0.0;            ///< [s] time of the step
  double t_end = 0.0;             ///< [s] end of the analysis window, > t_step
  double direction_deg = 0.0;     ///< commanded direction [deg], 0 = ahead, 90 = starboard
  double magnitude_pct = 0.0;     ///< thrust demand [%]
  std::optional<double> yaw_pct;  ///< yaw demand [%], if known
};

/// Options for analyse_agility().
struct AgilityOptions {
  /// A demand change smaller than this [%] (> 0) is not a change of level.
  double command_tolerance_pct = 0.5;
  /// Thrust demands below this [%] (≥ 0) are "no thrust": no step, no direction.
  double min_demand_pct = 5.0;
  /// A level held for less than this [s] (> 0) is part of a transition.
  double min_step_s = 2.0;
  /// Seconds [s] (> 0) before the step averaged for y₀.
  double pre_step_s = 5.0;
  /// Fraction of the window after the step averaged for y∞, in (0, 0.5].
  double tail_fraction = 0.2;
  /// |Δy| below this fraction (in [0, 1)) of a channel's range: no response (absent).
  double min_response_fraction = 0.05;
  /// A speed change below this [m/s] (≥ 0) is no response (a speed log resolves 0.01 m/s; the
  /// range of the speed over a trial says nothing about one step).
  double min_speed_change_mps = 0.05;
  /// An excursion against Δy after the 63.2 % crossing larger than this fraction (> 0) of
  /// |Δy| is noted as a reversing response.
  double reversal_fraction = 0.3;
  /// A step window shorter than this [s] (> 0) is too short to analyse: InputError.
  double min_window_s = 5.0;

  /// Throws core::InputError naming the bad option.
  void validate() const;
};

/// The response of one signal to one step.
struct AgilityResponse {
  std::string name;                  ///< thruster name, or "speed"
  std::optional<double> response_s;  ///< time to 63.2 % from the step [s]; absent: no response
  /// Spread of the 63.2 % crossings from below before the response clears the level [s]: 0 for
  /// a single crossing. response_s is the midpoint of the first and the last; where the signal
  /// swings back through the level, a small change of the final level moves response_s by up
  /// to half this spread.
  double crossing_span_s = 0.0;
  std::optional<double> y0;        ///< level before [signal unit]
  std::optional<double> y_final;   ///< level at the end of the window [signal unit]
  std::vector<std::string> notes;  ///< "no response", "reverses", "not settled", …
};

/// One agility step and its responses.
struct AgilityStep {
  double direction_deg = 0.0;              ///< (−180, 180], 0 = ahead, 90 = starboard
  double magnitude_pct = 0.0;              ///< thrust demand √(surge² + sway²) [%]
  std::optional<double> yaw_pct;           ///< yaw demand [%], absent when not logged
  double t_step = 0.0;                     ///< [s]
  double t_end = 0.0;                      ///< [s]
  std::vector<AgilityResponse> thrusters;  ///< one per channel, in channel order
  std::optional<AgilityResponse> speed;    ///< when a speed signal was given
};

/// Result of analyse_agility().
struct AgilityResult {
  FitStatus status = FitStatus::kFailed;
  std::string message;
  std::vector<AgilityStep> steps;  ///< in time order
};

/// The 63.2 % response of y to a step at t_step within [t_step, t_end] (see the file
/// comment); a change |Δy| below `min_change` [unit of y] is no response.
/// Throws core::InputError if the lengths differ or t is not increasing.
AgilityResponse response_time_632(std::span<const double> t, std::span<const double> y,
                                  double t_step, double t_end, double min_change,
                                  const AgilityOptions& options = {}, std::string name = {});

/// The agility steps found in the joystick demands (see the file comment), without responses.
/// Throws core::InputError if the lengths differ, t is not increasing, the demands are
/// missing or constant, or no step with a thrust demand is found.
std::vector<AgilityStep> find_agility_steps(std::span<const double> t,
                                            const AgilityCommand& command,
                                            const AgilityOptions& options = {});

/// Thrust agility from the joystick demands. `speed_mps` may be empty (not logged).
/// Throws core::InputError on bad input: no thruster channel, lengths that differ, no step,
/// a step window shorter than min_window_s, a thruster channel with no valid sample.
AgilityResult analyse_agility(std::span<const double> t, const AgilityCommand& command,
                              std::span<const AgilityChannel> thrusters,
                              std::span<const double> speed_mps,
                              const AgilityOptions& options = {});

/// Thrust agility over explicit windows (same checks; the windows must lie in the log).
AgilityResult analyse_agility(std::span<const double> t, std::span<const AgilityWindow> windows,
                              std::span<const AgilityChannel> thrusters,
                              std::span<const double> speed_mps,
                              const AgilityOptions& options = {});

/// A label for the case of a step: the thrust demand rounded to 5 %, and the yaw demand rounded
/// to 5 % when at least min_demand_pct, e.g. "50 % thrust, no yaw", "100 % thrust, yaw 100 %"
/// ("yaw not logged" without a yaw channel). Steps of one case share a polar plot.
std::string agility_case_label(const AgilityStep& step, double min_demand_pct = 5.0);

}  // namespace dynpos::ident
