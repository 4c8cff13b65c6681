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
  kTime,             ///< SI: s
  kLength,           ///< SI: m
  kAngle,            ///< SI: rad
  kAngularRate,      ///< SI: rad/s
  kSpeed,            ///< SI: m/s
  kAcceleration,     ///< SI: m/s^2
  kAngularAccel,     ///< SI: rad/s^2
  kForce,            ///< SI: N
  kMoment,           ///< SI: N*m
  kPower,            ///< SI: W
  kEnergy,           ///< SI: J
  kImpulse,          ///< SI: N*s
  kShaftSpeed,       ///< SI: rps (revolutions per second, 1/s)
  kFraction,         ///< SI: 1 (percent is 0.01)
  kDimensionless,    ///< SI: 1
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
std::optional<Unit> find_unit(std::string_view spelling);

/// The SI unit of a quantity ("m", "rad", ...).
const Unit& si_unit(Quantity quantity);

/// Human name of a quantity ("angle", "speed", ...), for messages.
std::string_view quantity_name(Quantity quantity);

/// All accepted spellings of a quantity, for error hints and docs.
std::vector<std::string> unit_spellings(Quantity quantity);

}  // namespace dynpos::core
