#pragma once
/// \file
/// Units: the spellings users write in logs and maps, and their conversion to SI.
///
/// Inside the library everything is SI (m, s, rad, N, W, J, m/s, rad/s, rps for shaft speed,
/// and dimensionless fractions for percent). A Unit says how a value in that unit becomes SI:
/// si = value * scale + offset. Units of one Quantity convert into each other.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dynpos::core {

/// The physical quantity a unit measures; roles declare which quantity they expect.
enum class Quantity {
  kTime,           ///< SI: s
  kLength,         ///< SI: m
  kAngle,          ///< SI: rad
  kAngularRate,    ///< SI: rad/s
  kSpeed,          ///< SI: m/s
  kAcceleration,   ///< SI: m/s^2
  kAngularAccel,   ///< SI: rad/s^2
  kForce,          ///< SI: N
  kMoment,         ///< SI: N*m
  kPower,          ///< SI: W
  kEnergy,         ///< SI: J
  kImpulse,        ///< SI: N*s
  kShaftSpeed,     ///< SI: rps (revolutions per second, 1/s)
  kFraction,       ///< SI: 1 (percent is 0.01)
  kDimensionless,  ///< SI: 1
};

/// A unit spelling and its conversion to SI: si = value * scale + offset.
struct Unit {
  std::string symbol;  ///< canonical spelling, e.g. "deg/s"
  Quantity quantity;
  double scale = 1.0;
  double offset = 0.0;

  double to_si(double value) const { return value * scale + offset; }
  double from_si(double si) const { return (si - offset) / scale; }
};

/// Looks a spelling up, ignoring surrounding spaces and brackets ("[deg]", "(m/s)").
/// Accepts at least: s, ms, min, h, m, km, nmi, deg, rad, deg/s, rad/s, m/s, kn, km/h,
/// m/s^2 (also m/s2), g, N, kN, N*m, kNm, W, kW, MW, J, kJ, MJ, kWh, Ns, kNs, rpm, rps, Hz,
/// %, 1, -. Returns nullopt for an unknown spelling.
///
/// Matching: spaces and tabs are removed everywhere ("kN m" is "kNm", "deg / s" is "deg/s"),
/// then one pair of surrounding [] or () is stripped. SI-prefixed symbols are case-sensitive,
/// because case changes their meaning: "kn" is knots but "kN" kilonewton, "MW" is not "mW",
/// "s" is not "S"; a spelling such as "KN" that is neither is rejected, not guessed. Angle,
/// shaft-speed and word spellings, whose case carries no meaning, match in any case: "deg",
/// "Deg", "DEG"; also rad, degree(s), radian(s), rpm, rps, rev/min, rev/s, Hz, knot(s), kt,
/// kts, sec, min, nmi, percent and the rates deg/s, deg/min, rad/s, deg/s^2, rad/s^2.
/// Further variants: "°" and "º" for deg ("°/s", "°/min"), "²" or "2" for "^2" ("m/s²"),
/// "·", "." or nothing for "*" ("N·m", "N.m", "Nm"; "kN·s", "kNs"). Shaft speed is in
/// revolutions per second: "rps", "rev/s", "Hz" and "1/s" are the same unit, and rpm is
/// rps/60. "deg/min" (NMEA rate of turn) is an angular rate. "%" is the fraction 0.01.
/// "1" and "-" are dimensionless; an empty spelling is not a unit (nullopt).
std::optional<Unit> find_unit(std::string_view spelling);

/// The SI unit of a quantity ("m", "rad", ...).
const Unit& si_unit(Quantity quantity);

/// Human name of a quantity ("angle", "speed", ...), for messages.
std::string_view quantity_name(Quantity quantity);

/// All accepted spellings of a quantity, for error hints and docs.
std::vector<std::string> unit_spellings(Quantity quantity);

}  // namespace dynpos::core
