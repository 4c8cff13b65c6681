#include "dynpos/sim/sim_time.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace dynpos::sim {

namespace {

std::string number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

}  // namespace

TimeGrid::TimeGrid(double dt_s) : dt_s_(dt_s) {
  if (!std::isfinite(dt_s) || dt_s <= 0.0) {
    throw std::invalid_argument("time step dt = " + number(dt_s) +
                                " s must be finite and > 0; give a positive step such as 0.01 s");
  }
}

Tick TimeGrid::ticks(double duration_s, std::string_view what) const {
  if (!std::isfinite(duration_s) || duration_s < 0.0) {
    throw std::invalid_argument(std::string(what) + " = " + number(duration_s) +
                                " s must be finite and >= 0");
  }
  const double ratio = duration_s / dt_s_;
  const double n = std::round(ratio);
  if (std::abs(ratio - n) > kTickTolerance * ratio) {
    throw std::invalid_argument(
        std::string(what) + " = " + number(duration_s) +
        " s is not an integer multiple of the time step dt = " + number(dt_s_) + " s (ratio " +
        number(ratio) + "); choose a dt that divides every rate's period");
  }
  return static_cast<Tick>(n);
}

Tick TimeGrid::ticks_for_period(double period_s, std::string_view what) const {
  const Tick n = ticks(period_s, what);
  if (n < 1) {
    throw std::invalid_argument(std::string(what) + " = " + number(period_s) +
                                " s must be at least one time step dt = " + number(dt_s_) + " s");
  }
  return n;
}

Tick TimeGrid::ticks_for_rate(double rate_hz, std::string_view what) const {
  if (!std::isfinite(rate_hz) || rate_hz <= 0.0) {
    throw std::invalid_argument(std::string(what) + " = " + number(rate_hz) +
                                " Hz must be finite and > 0");
  }
  return ticks_for_period(1.0 / rate_hz, std::string(what) + " period (1/rate)");
}

}  // namespace dynpos::sim
