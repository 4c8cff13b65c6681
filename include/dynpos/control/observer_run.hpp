#pragma once
/// \file
/// A DP observer run over logged time series: what the observer (passive_observer.hpp,
/// ekf_observer.hpp) would have estimated along a log — the low-frequency motion and the bias
/// b̂, the environmental load in NED (observer.hpp) — stepped at a fixed rate with the inputs
/// sampled and held.
///
/// The inputs share one increasing time axis, each component NaN where it was not sampled: the
/// control origin's position (N, E), the heading and the thrust τ (BODY). The run starts at the
/// first time t₀ with a position, a heading and a complete τ, at rest there (the observers'
/// start), and steps at t_k = t₀ + k/rate. At step k:
///   - τ is the last complete τ at or before t_k, held however old: a unit's thrust is never
///     taken as zero for not being logged (steps on a τ older than max_hold_s are counted);
///   - the measurement y, per component (the position, the heading): held (a continuous-time
///     observer, the passive one, on the zero-order hold of its input), the last sample at or
///     before t_k while it is at most max_hold_s old; fresh (the EKF), only a sample taken
///     after t_{k−1} — the latest of them when several were, one correction per step, and no
///     max_hold_s. Otherwise y is missing there and the observer coasts on its model: a
///     missing GNSS fix is never a position of zero.
/// An observer's step predicts over 1/rate, so the estimate after step k is the one at t_{k+1};
/// the run ends with the last t_{k+1} within the inputs' time span.

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <vector>

#include "dynpos/control/ekf_observer.hpp"
#include "dynpos/control/observer.hpp"
#include "dynpos/control/passive_observer.hpp"

namespace dynpos::control {

/// What the DP system received, on one time axis (see the file comment).
struct ObserverInputs {
  std::vector<double> t_s;             ///< increasing [s]
  std::vector<double> north_m;         ///< control origin, NED [m]; NaN: no fix
  std::vector<double> east_m;          ///< control origin, NED [m]; NaN: no fix
  std::vector<double> heading_rad;     ///< [rad], any wrapping; NaN: no sample
  std::vector<Eigen::Vector3d> tau_b;  ///< thrust (X, Y, N) BODY [N, N, N·m]; any NaN: none
  /// The time of the oldest sample each τ row was made of (units logged at other rates, held
  /// into the row) [s]; empty: the row's own time. The age max_hold_s is judged on.
  std::vector<double> tau_sampled_s = {};
};

/// How the run steps (see the file comment).
struct ObserverRunOptions {
  ObserverKind kind = ObserverKind::kEkf;  ///< kPassive or kEkf
  double rate_hz = 10.0;                   ///< the observer's step rate [Hz], > 0
  /// Longest time [s] a sample stands for its input, > 0. Source: reasoned — 5 s bridges the
  /// 1 Hz feedback of a tunnel thruster and a GNSS at 1 Hz with a few lost fixes, while a
  /// longer dropout makes the observer coast.
  double max_hold_s = 5.0;
  /// Whether the measurement is held (see the file comment); unset: held for the passive
  /// observer, fresh for the EKF.
  std::optional<bool> hold_measurements;
  PassiveObserverTuning passive;
  EkfObserverTuning ekf;
  /// Throws std::invalid_argument unless the kind is passive or ekf, the rate and the hold are
  /// finite and > 0, and the passive observer's measurements are held.
  void validate() const;
  /// hold_measurements, or the kind's default.
  bool holds_measurements() const noexcept;
};

/// The estimates of a run, one per step.
struct ObserverTrack {
  double start_s = 0.0;                    ///< t₀ (the initial estimate, at rest)
  std::vector<double> t_s;                 ///< t₁, t₂, … [s]
  std::vector<ObserverEstimate> estimate;  ///< the estimate at each t_s
  /// At each t_s, the time since the newest position sample the estimate has seen [s]: a step
  /// or a fix interval while fixes come; through a dropout it grows, the observer coasting on
  /// its model once the sample is older than max_hold_s (held) or one step (fresh).
  std::vector<double> position_age_s;
  std::size_t position_steps = 0;      ///< steps with a position measurement
  std::size_t coasting_steps = 0;      ///< steps without one
  std::size_t stale_thrust_steps = 0;  ///< steps on a τ older than max_hold_s
};

/// Runs the observer of `options.kind` on `model` over `inputs` (see the file comment). Throws
/// std::invalid_argument for inputs of unequal lengths, a time axis that is not increasing and
/// finite, no time with a position, a heading and a complete τ, or no step within the inputs'
/// span after it; and for a bad model or options.
ObserverTrack run_observer(const ObserverModel& model, const ObserverInputs& inputs,
                           const ObserverRunOptions& options);

}  // namespace dynpos::control
