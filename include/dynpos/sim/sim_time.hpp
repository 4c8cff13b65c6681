#pragma once
/// \file
/// Integer simulation time: a tick count k on a grid of fixed step dt.
///
/// Inside the simulator, time is the integer k and the time in seconds is t = k·dt, computed by
/// one multiplication and never by accumulating t += dt (which drifts by one rounding error per
/// step). Multi-rate tasks (controllers, sensors, loggers) fire on integer tick periods, so a
/// 10 Hz task on a 100 Hz grid fires at exactly every 10th tick however long the run.

#include <cstdint>
#include <string_view>

namespace dynpos::sim {

/// A point on the simulation time grid: the number of steps dt since t = 0.
using Tick = std::int64_t;

/// Relative tolerance when a duration must be an integer multiple of dt:
/// |duration − n·dt| ≤ kTickTolerance·duration.
inline constexpr double kTickTolerance = 1e-9;

/// The time grid t_k = k·dt of a simulation, and conversions of durations into ticks.
class TimeGrid {
 public:
  /// A grid of step dt_s [s], finite and > 0. Throws std::invalid_argument otherwise.
  explicit TimeGrid(double dt_s);

  /// The step dt [s].
  double dt() const noexcept { return dt_s_; }

  /// The time of tick k [s]: t_k = k·dt (one multiplication, no accumulation).
  double time(Tick k) const noexcept { return static_cast<double>(k) * dt_s_; }

  /// The number of ticks n with n·dt = duration_s [s] (≥ 0), within kTickTolerance relative.
  /// Throws std::invalid_argument naming `what` if the duration is negative, not finite, or not
  /// an integer multiple of dt.
  Tick ticks(double duration_s, std::string_view what = "duration") const;

  /// The ticks of one period [s] of a periodic task; like ticks() but the period must be > 0.
  Tick ticks_for_period(double period_s, std::string_view what = "period") const;

  /// The ticks of one period 1/rate_hz of a task running at rate_hz [Hz] (> 0); throws
  /// std::invalid_argument if 1/rate_hz is not an integer multiple of dt.
  Tick ticks_for_rate(double rate_hz, std::string_view what = "rate") const;

 private:
  double dt_s_;
};

/// True when a task with period `period` ticks (≥ 1) and offset `offset` ticks (≥ 0) fires at
/// tick k: k ≥ offset and (k − offset) mod period = 0.
constexpr bool fires_at(Tick k, Tick period, Tick offset = 0) noexcept {
  return k >= offset && (k - offset) % period == 0;
}

/// The firing pattern of a periodic task on the tick grid.
struct PeriodicSchedule {
  Tick period = 1;  ///< ticks between firings, ≥ 1
  Tick offset = 0;  ///< tick of the first firing, ≥ 0

  /// True when the task fires at tick k.
  constexpr bool fires_at(Tick k) const noexcept { return sim::fires_at(k, period, offset); }

  /// The first tick ≥ k at which the task fires.
  constexpr Tick next_at_or_after(Tick k) const noexcept {
    if (k <= offset) return offset;
    const Tick since = k - offset;
    return offset + ((since + period - 1) / period) * period;
  }
};

}  // namespace dynpos::sim
