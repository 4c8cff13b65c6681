#pragma once
// Private utilities shared by the actuator models: parameter range checks and saturations.

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dynpos::model::detail {

// Throws std::invalid_argument "<owner>.<field> = <value>: must be <rule>" unless ok.
inline void require(bool ok, const char* owner, const char* field, double value, const char* rule) {
  if (!ok) {
    throw std::invalid_argument(std::string(owner) + "." + field + " = " + std::to_string(value) +
                                ": must be " + rule);
  }
}

// lo < value < hi and finite (NaN fails every comparison).
inline bool open_range(double value, double lo, double hi) { return value > lo && value < hi; }
// lo ≤ value < hi and finite.
inline bool half_open_range(double value, double lo, double hi) {
  return value >= lo && value < hi;
}
// lo ≤ value ≤ hi and finite.
inline bool closed_range(double value, double lo, double hi) { return value >= lo && value <= hi; }

inline double clamp_abs(double value, double limit) { return std::clamp(value, -limit, limit); }

inline double sign(double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); }

constexpr double kPi = 3.14159265358979323846;

}  // namespace dynpos::model::detail
