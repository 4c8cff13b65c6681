#pragma once
/// \file
/// The time base of a scenario run. The simulator counts ticks k from 0 on the grid dt of the
/// scenario; the run settles for settle_s before the scenario's t = 0, so every part works in
/// scenario time t = (k − k_settle)·dt, exact on the grid like the simulator's own. The
/// loggers fire on the log period's ticks and record from t = 0 on.

#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/sim/sim_time.hpp"
#include "dynpos/sim/simulator.hpp"

namespace dynpos::scenario {

/// Ticks and times of a run (see the file comment).
class TrialClock {
 public:
  /// The clock of `spec` (dt_s, settle_s, duration_s, log_rate_hz). Throws
  /// std::invalid_argument if settle_s or the log period is not a whole number of steps
  /// (ScenarioSpec::validate() rules that out).
  explicit TrialClock(const ScenarioSpec& spec);

  const sim::TimeGrid& grid() const noexcept { return grid_; }
  /// Scenario tick of simulator tick k: k − k_settle.
  sim::Tick scenario_tick(sim::Tick k) const noexcept { return k - settle_ticks_; }
  /// Scenario time of simulator tick k [s]: (k − k_settle)·dt.
  double time(sim::Tick k) const noexcept { return grid_.time(scenario_tick(k)); }
  /// A task's context in scenario time (tick and time; the same state and held input).
  sim::TaskContext scenario_context(sim::TaskContext& context) const {
    return {scenario_tick(context.tick()), time(context.tick()), context.mutable_state(),
            context.mutable_input()};
  }
  /// The simulator's end time [s]: settle_s + duration_s.
  double end_time_s() const noexcept { return end_time_s_; }
  /// The log period [s], 1/log_rate_hz.
  double log_period_s() const noexcept { return log_period_s_; }
  /// True at the ticks where the loggers record: on the log period's ticks from t = 0 on.
  bool logs_at(sim::Tick k) const noexcept {
    return log_schedule_.fires_at(k) && !(time(k) < -0.5 * grid_.dt());
  }

 private:
  sim::TimeGrid grid_;
  sim::Tick settle_ticks_;
  double end_time_s_;
  double log_period_s_;
  sim::PeriodicSchedule log_schedule_;
};

}  // namespace dynpos::scenario
