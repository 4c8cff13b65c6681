#include "dynpos/sim/sim_time.hpp"

#include "format_number.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace dynpos::sim {

namespace {}  // namespace

TimeGrid::TimeGrid(double dt_s) : dt_s_(dt_s) {
  if (!std::isfinite(dt_s) || dt_s <= 0.0) {
    throw std::invalid_argument("time step dt = " + detail::format_number(dt_s, 17) +
                                " s must be finite and > 0; give a positive step such as 0.01 s");
  }
}

Tick TimeGrid::ticks(double duration_s, std::string_view what) const {
  if (!std::isfinite(duration_s) || duration_s < 0.0) {
    throw std::invalid_argument(std::string(what) + " = " + detail::format_number(duration_s, 17) +
                                " s must be finite and >= 0");
  }
  const double ratio = duration_s / dt_s_;
  const double n = std::round(ratio);
  if (std::abs(ratio - n) > kTickTolerance * ratio) {
    throw std::invalid_argument(
        std::string(what) + " = " + detail::format_number(duration_s, 17) +
        " s is not an integer multiple of the time step dt = " + detail::format_number(dt_s_, 17) +
        " s (ratio " + detail::format_number(ratio, 17) +
        "); choose a dt that divides every rate's period");
  }
  return static_cast<Tick>(n);
}

Tick TimeGrid::ticks_for_period(double period_s, std::string_view what) const {
  const Tick n = ticks(period_s, what);
  if (n < 1) {
    throw std::invalid_argument(
        std::string(what) + " = " + detail::format_number(period_s, 17) +
        " s must be at least one time step dt = " + detail::format_number(dt_s_, 17) + " s");
  }
  return n;
}

Tick TimeGrid::ticks_for_rate(double rate_hz, std::string_view what) const {
  if (!std::isfinite(rate_hz) || rate_hz <= 0.0) {
    throw std::invalid_argument(std::string(what) + " = " + detail::format_number(rate_hz, 17) +
                                " Hz must be finite and > 0");
  }
  return ticks_for_period(1.0 / rate_hz, std::string(what) + " period (1/rate)");
}

}  // namespace dynpos::sim
