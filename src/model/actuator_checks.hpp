#pragma once
// Private utilities shared by the actuator models: saturations and π.

#include <algorithm>
#include <cmath>

namespace dynpos::model::detail {

inline double clamp_abs(double value, double limit) { return std::clamp(value, -limit, limit); }

inline double sign(double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); }

constexpr double kPi = 3.14159265358979323846;

}  // namespace dynpos::model::detail
