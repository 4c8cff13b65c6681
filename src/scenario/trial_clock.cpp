#include "dynpos/scenario/trial_clock.hpp"

namespace dynpos::scenario {

TrialClock::TrialClock(const ScenarioSpec& spec)
    : grid_(spec.dt_s),
      settle_ticks_(grid_.ticks(spec.settle_s, "settle_s")),
      end_time_s_(spec.settle_s + spec.duration_s),
      log_period_s_(1.0 / spec.log_rate_hz),
      // The loggers are periodic tasks from tick 0 (Simulator::add_periodic_task, offset 0).
      log_schedule_{grid_.ticks_for_period(log_period_s_, "task 'log' period"), 0} {}

}  // namespace dynpos::scenario
