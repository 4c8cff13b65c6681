#include "dynpos/sensors/sensor_timing.hpp"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>

#include "param_tables.hpp"

namespace dynpos::sensors {

void SensorTiming::validate(const char* what) const {
  core::check_ranges(what, detail::timing_fields(*this));
}

SampleSchedule make_schedule(const SensorTiming& timing, double log_rate_hz, const char* what) {
  timing.validate(what);
  if (!(log_rate_hz > 0.0)) throw std::invalid_argument("make_schedule: log rate must be > 0");
  if (!timing.enabled()) throw std::invalid_argument(fmt::format("{}: sensor is off", what));
  SampleSchedule s;
  const double ratio = log_rate_hz / timing.rate_hz;
  if (ratio > 1.0) {
    const double every = std::round(ratio);
    if (std::abs(ratio - every) > 1e-9 * ratio) {
      throw std::invalid_argument(fmt::format("{}: rate {} Hz does not divide the log rate {} Hz",
                                              what, timing.rate_hz, log_rate_hz));
    }
    s.every = static_cast<std::size_t>(every);
  }
  const double ticks = timing.time_offset_s * log_rate_hz;
  const double delay = std::round(ticks);
  if (std::abs(ticks - delay) > 1e-9 * std::max(1.0, ticks)) {
    throw std::invalid_argument(
        fmt::format("{}: time_offset_s {} is not a whole number of log periods (1/{} s)", what,
                    timing.time_offset_s, log_rate_hz));
  }
  s.delay = static_cast<std::size_t>(delay);
  s.period_s = static_cast<double>(s.every) / log_rate_hz;
  return s;
}

}  // namespace dynpos::sensors
