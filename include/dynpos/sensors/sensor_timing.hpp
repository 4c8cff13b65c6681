#pragma once
/// \file
/// When a sensor samples: its rate and latency, on the integer tick grid of a logger.
///
/// A logger records at rate f_log; a sensor of rate f ≤ f_log fires every N = f_log/f logger
/// ticks (N must be an integer), one of rate f > f_log is recorded at f_log (as a 50 Hz trial
/// logger records a 100 Hz MRU). A time offset δ ≥ 0 is a latency: the sample stamped t holds the
/// truth at t − δ; δ must be a whole number of logger ticks so that runs stay exact.

#include <cstddef>

namespace dynpos::sensors {

struct SensorTiming {
  double rate_hz = 1.0;        ///< sample rate [Hz]; 0 switches the sensor off
  double time_offset_s = 0.0;  ///< latency δ [s]

  bool enabled() const noexcept { return rate_hz > 0.0; }
  /// Throws core::InputError naming `what`.KEY for a value outside its range (the vessel file's
  /// rate_hz and time_offset_s, sensor_suite.hpp).
  void validate(const char* what) const;
};

/// A sensor's schedule on a logger's tick grid.
struct SampleSchedule {
  std::size_t every = 1;  ///< fires on logger ticks k with k mod every = 0
  std::size_t delay = 0;  ///< latency in logger ticks
  double period_s = 0.0;  ///< time between its samples [s]

  bool fires(std::size_t tick) const noexcept { return tick % every == 0; }
};

/// The schedule of `timing` on a logger of rate log_rate_hz (> 0). Throws core::InputError for
/// a timing outside its range (validate), std::invalid_argument naming `what` if the rate does
/// not divide the logger rate or the offset is not a whole number of logger ticks (within 1e-9
/// relative); the scenario runner reports the latter with the file and the log rate.
SampleSchedule make_schedule(const SensorTiming& timing, double log_rate_hz, const char* what);

}  // namespace dynpos::sensors
