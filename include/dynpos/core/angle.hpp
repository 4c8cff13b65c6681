#pragma once
/// \file
/// Angle functions: wrapping to a principal range, differences of headings, degree conversion.
///
/// Angles inside the library are radians. Headings near 0°/360° wrap, so a difference of two
/// headings must be wrapped (angle_diff) and an average of headings is a circular mean (see
/// core/circular_stats.hpp). NaN (a missing sample) passes through every function unchanged;
/// ±∞ has no principal value and gives NaN.

#include <cmath>
#include <numbers>

namespace dynpos::core {

/// π [rad].
inline constexpr double kPi = std::numbers::pi;
/// 2π [rad], one full turn.
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;
/// Degrees per radian, 180/π.
inline constexpr double kDegPerRad = 180.0 / std::numbers::pi;
/// Radians per degree, π/180.
inline constexpr double kRadPerDeg = std::numbers::pi / 180.0;

/// Converts degrees to radians: x_rad = x_deg·π/180.
constexpr double deg_to_rad(double angle_deg) { return angle_deg * kRadPerDeg; }

/// Converts radians to degrees: x_deg = x_rad·180/π.
constexpr double rad_to_deg(double angle_rad) { return angle_rad * kDegPerRad; }

/// Wraps an angle [rad] to (−π, π]: the a − 2πk nearest zero, with −π mapped to π.
/// Idempotent, and exact: the result is computed without rounding from the double a and kTwoPi.
inline double wrap_pi(double angle_rad) {
  // std::remainder is exact and returns [−π, π] (ties to even, so ±π stay ±π); only −π moves.
  double wrapped = std::remainder(angle_rad, kTwoPi);
  if (wrapped <= -kPi) wrapped += kTwoPi;
  return wrapped;
}

/// Wraps an angle [rad] to [0, 2π): a − 2πk with k = ⌊a/2π⌋.
/// Idempotent; −0 and tiny negative angles that round up to 2π give +0.
inline double wrap_2pi(double angle_rad) {
  double wrapped = std::fmod(angle_rad, kTwoPi);  // exact, in (−2π, 2π)
  if (wrapped < 0.0) wrapped += kTwoPi;           // may round up to exactly 2π
  if (wrapped >= kTwoPi) wrapped = 0.0;
  return wrapped + 0.0;  // −0 → +0
}

/// The signed smallest rotation from b to a [rad], in (−π, π]: wrap_pi(a − b).
inline double angle_diff(double a_rad, double b_rad) { return wrap_pi(a_rad - b_rad); }

}  // namespace dynpos::core
