#include "dynpos/core/units.hpp"

#include <array>
#include <cctype>
#include <numbers>
#include <string>

namespace dynpos::core {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;  // rad per degree
constexpr double kKnot = 1852.0 / 3600.0;          // m/s per knot (international nautical mile)
constexpr double kStandardGravity = 9.80665;       // m/s^2, CGPM 1901

// UTF-8 spellings, written as escapes so the table does not depend on the source encoding.
#define DYNPOS_DEG "\xC2\xB0"  // ° U+00B0 degree sign
#define DYNPOS_ORD "\xC2\xBA"  // º U+00BA ordinal indicator, often typed for the degree sign
#define DYNPOS_SQ "\xC2\xB2"   // ² U+00B2 superscript two
#define DYNPOS_DOT "\xC2\xB7"  // · U+00B7 middle dot

// One accepted spelling. `symbol` is the canonical spelling returned in Unit::symbol.
// `any_case`: the spelling also matches with different ASCII letter case (see units.hpp).
struct Spelling {
  std::string_view spelling;
  std::string_view symbol;
  Quantity quantity;
  double scale;
  bool any_case;
};

constexpr bool kCase = false;  // case-sensitive
constexpr bool kAny = true;    // any case

using Q = Quantity;
// clang-format off
constexpr std::array kSpellings{
    // time
    Spelling{"s", "s", Q::kTime, 1.0, kCase},
    Spelling{"sec", "s", Q::kTime, 1.0, kAny},
    Spelling{"ms", "ms", Q::kTime, 1e-3, kCase},
    Spelling{"us", "us", Q::kTime, 1e-6, kCase},
    Spelling{"\u00b5s", "us", Q::kTime, 1e-6, kCase},  // micro sign
    Spelling{"\u03bcs", "us", Q::kTime, 1e-6, kCase},  // Greek mu
    Spelling{"ns", "ns", Q::kTime, 1e-9, kCase},
    Spelling{"min", "min", Q::kTime, 60.0, kAny},
    Spelling{"h", "h", Q::kTime, 3600.0, kCase},
    // length
    Spelling{"m", "m", Q::kLength, 1.0, kCase},
    Spelling{"km", "km", Q::kLength, 1000.0, kCase},
    Spelling{"nmi", "nmi", Q::kLength, 1852.0, kAny},
    // angle
    Spelling{"rad", "rad", Q::kAngle, 1.0, kAny},
    Spelling{"radian", "rad", Q::kAngle, 1.0, kAny},
    Spelling{"radians", "rad", Q::kAngle, 1.0, kAny},
    Spelling{"deg", "deg", Q::kAngle, kDeg, kAny},
    Spelling{"degree", "deg", Q::kAngle, kDeg, kAny},
    Spelling{"degrees", "deg", Q::kAngle, kDeg, kAny},
    Spelling{DYNPOS_DEG, "deg", Q::kAngle, kDeg, kCase},
    Spelling{DYNPOS_ORD, "deg", Q::kAngle, kDeg, kCase},
    // angular rate
    Spelling{"rad/s", "rad/s", Q::kAngularRate, 1.0, kAny},
    Spelling{"deg/s", "deg/s", Q::kAngularRate, kDeg, kAny},
    Spelling{DYNPOS_DEG "/s", "deg/s", Q::kAngularRate, kDeg, kCase},
    Spelling{DYNPOS_ORD "/s", "deg/s", Q::kAngularRate, kDeg, kCase},
    Spelling{"deg/min", "deg/min", Q::kAngularRate, kDeg / 60.0, kAny},
    Spelling{DYNPOS_DEG "/min", "deg/min", Q::kAngularRate, kDeg / 60.0, kCase},
    Spelling{DYNPOS_ORD "/min", "deg/min", Q::kAngularRate, kDeg / 60.0, kCase},
    // speed
    Spelling{"m/s", "m/s", Q::kSpeed, 1.0, kCase},
    Spelling{"kn", "kn", Q::kSpeed, kKnot, kCase},
    Spelling{"knot", "kn", Q::kSpeed, kKnot, kAny},
    Spelling{"knots", "kn", Q::kSpeed, kKnot, kAny},
    Spelling{"kt", "kn", Q::kSpeed, kKnot, kAny},
    Spelling{"kts", "kn", Q::kSpeed, kKnot, kAny},
    Spelling{"km/h", "km/h", Q::kSpeed, 1000.0 / 3600.0, kCase},
    // acceleration
    Spelling{"m/s^2", "m/s^2", Q::kAcceleration, 1.0, kCase},
    Spelling{"m/s2", "m/s^2", Q::kAcceleration, 1.0, kCase},
    Spelling{"m/s" DYNPOS_SQ, "m/s^2", Q::kAcceleration, 1.0, kCase},
    Spelling{"g", "g", Q::kAcceleration, kStandardGravity, kCase},
    // angular acceleration
    Spelling{"rad/s^2", "rad/s^2", Q::kAngularAccel, 1.0, kAny},
    Spelling{"rad/s2", "rad/s^2", Q::kAngularAccel, 1.0, kAny},
    Spelling{"rad/s" DYNPOS_SQ, "rad/s^2", Q::kAngularAccel, 1.0, kAny},
    Spelling{"deg/s^2", "deg/s^2", Q::kAngularAccel, kDeg, kAny},
    Spelling{"deg/s2", "deg/s^2", Q::kAngularAccel, kDeg, kAny},
    Spelling{"deg/s" DYNPOS_SQ, "deg/s^2", Q::kAngularAccel, kDeg, kAny},
    Spelling{DYNPOS_DEG "/s^2", "deg/s^2", Q::kAngularAccel, kDeg, kCase},
    Spelling{DYNPOS_DEG "/s" DYNPOS_SQ, "deg/s^2", Q::kAngularAccel, kDeg, kCase},
    // force
    Spelling{"N", "N", Q::kForce, 1.0, kCase},
    Spelling{"kN", "kN", Q::kForce, 1e3, kCase},
    Spelling{"MN", "MN", Q::kForce, 1e6, kCase},
    // moment
    Spelling{"N*m", "N*m", Q::kMoment, 1.0, kCase},
    Spelling{"N" DYNPOS_DOT "m", "N*m", Q::kMoment, 1.0, kCase},
    Spelling{"N.m", "N*m", Q::kMoment, 1.0, kCase},
    Spelling{"Nm", "N*m", Q::kMoment, 1.0, kCase},
    Spelling{"kN*m", "kN*m", Q::kMoment, 1e3, kCase},
    Spelling{"kN" DYNPOS_DOT "m", "kN*m", Q::kMoment, 1e3, kCase},
    Spelling{"kN.m", "kN*m", Q::kMoment, 1e3, kCase},
    Spelling{"kNm", "kN*m", Q::kMoment, 1e3, kCase},
    // power
    Spelling{"W", "W", Q::kPower, 1.0, kCase},
    Spelling{"kW", "kW", Q::kPower, 1e3, kCase},
    Spelling{"MW", "MW", Q::kPower, 1e6, kCase},
    // energy
    Spelling{"J", "J", Q::kEnergy, 1.0, kCase},
    Spelling{"kJ", "kJ", Q::kEnergy, 1e3, kCase},
    Spelling{"MJ", "MJ", Q::kEnergy, 1e6, kCase},
    Spelling{"Wh", "Wh", Q::kEnergy, 3600.0, kCase},
    Spelling{"kWh", "kWh", Q::kEnergy, 3.6e6, kCase},
    // impulse
    Spelling{"N*s", "N*s", Q::kImpulse, 1.0, kCase},
    Spelling{"N" DYNPOS_DOT "s", "N*s", Q::kImpulse, 1.0, kCase},
    Spelling{"N.s", "N*s", Q::kImpulse, 1.0, kCase},
    Spelling{"Ns", "N*s", Q::kImpulse, 1.0, kCase},
    Spelling{"kN*s", "kN*s", Q::kImpulse, 1e3, kCase},
    Spelling{"kN" DYNPOS_DOT "s", "kN*s", Q::kImpulse, 1e3, kCase},
    Spelling{"kN.s", "kN*s", Q::kImpulse, 1e3, kCase},
    Spelling{"kNs", "kN*s", Q::kImpulse, 1e3, kCase},
    // shaft speed
    Spelling{"rps", "rps", Q::kShaftSpeed, 1.0, kAny},
    Spelling{"rev/s", "rps", Q::kShaftSpeed, 1.0, kAny},
    Spelling{"Hz", "rps", Q::kShaftSpeed, 1.0, kAny},
    Spelling{"1/s", "rps", Q::kShaftSpeed, 1.0, kCase},
    Spelling{"rpm", "rpm", Q::kShaftSpeed, 1.0 / 60.0, kAny},
    Spelling{"rev/min", "rpm", Q::kShaftSpeed, 1.0 / 60.0, kAny},
    Spelling{"r/min", "rpm", Q::kShaftSpeed, 1.0 / 60.0, kAny},
    // fraction
    Spelling{"%", "%", Q::kFraction, 0.01, kCase},
    Spelling{"percent", "%", Q::kFraction, 0.01, kAny},
    // dimensionless
    Spelling{"1", "1", Q::kDimensionless, 1.0, kCase},
    Spelling{"-", "1", Q::kDimensionless, 1.0, kCase},
};
// clang-format on

#undef DYNPOS_DEG
#undef DYNPOS_ORD
#undef DYNPOS_SQ
#undef DYNPOS_DOT

bool equal_any_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto ca = static_cast<unsigned char>(a[i]);
    const auto cb = static_cast<unsigned char>(b[i]);
    if (std::tolower(ca) != std::tolower(cb)) return false;
  }
  return true;
}

// Removes spaces and tabs everywhere, then one pair of surrounding [] or ().
std::string normalise(std::string_view spelling) {
  std::string s;
  s.reserve(spelling.size());
  for (char c : spelling) {
    if (c != ' ' && c != '\t') s.push_back(c);
  }
  if (s.size() >= 2 &&
      ((s.front() == '[' && s.back() == ']') || (s.front() == '(' && s.back() == ')'))) {
    s = s.substr(1, s.size() - 2);
  }
  return s;
}

Unit to_unit(const Spelling& entry) {
  return Unit{std::string(entry.symbol), entry.quantity, entry.scale, 0.0};
}

}  // namespace

std::optional<Unit> find_unit(std::string_view spelling) {
  const std::string s = normalise(spelling);
  if (s.empty()) return std::nullopt;
  for (const Spelling& entry : kSpellings) {
    if (entry.spelling == s) return to_unit(entry);
  }
  for (const Spelling& entry : kSpellings) {
    if (entry.any_case && equal_any_case(entry.spelling, s)) return to_unit(entry);
  }
  return std::nullopt;
}

const Unit& si_unit(Quantity quantity) {
  static const std::array<Unit, 15> kSi{
      Unit{"s", Quantity::kTime},
      Unit{"m", Quantity::kLength},
      Unit{"rad", Quantity::kAngle},
      Unit{"rad/s", Quantity::kAngularRate},
      Unit{"m/s", Quantity::kSpeed},
      Unit{"m/s^2", Quantity::kAcceleration},
      Unit{"rad/s^2", Quantity::kAngularAccel},
      Unit{"N", Quantity::kForce},
      Unit{"N*m", Quantity::kMoment},
      Unit{"W", Quantity::kPower},
      Unit{"J", Quantity::kEnergy},
      Unit{"N*s", Quantity::kImpulse},
      Unit{"rps", Quantity::kShaftSpeed},
      Unit{"1", Quantity::kFraction},
      Unit{"1", Quantity::kDimensionless},
  };
  return kSi.at(static_cast<std::size_t>(quantity));
}

std::string_view quantity_name(Quantity quantity) {
  switch (quantity) {
    case Quantity::kTime:
      return "time";
    case Quantity::kLength:
      return "length";
    case Quantity::kAngle:
      return "angle";
    case Quantity::kAngularRate:
      return "angular rate";
    case Quantity::kSpeed:
      return "speed";
    case Quantity::kAcceleration:
      return "acceleration";
    case Quantity::kAngularAccel:
      return "angular acceleration";
    case Quantity::kForce:
      return "force";
    case Quantity::kMoment:
      return "moment";
    case Quantity::kPower:
      return "power";
    case Quantity::kEnergy:
      return "energy";
    case Quantity::kImpulse:
      return "impulse";
    case Quantity::kShaftSpeed:
      return "shaft speed";
    case Quantity::kFraction:
      return "fraction";
    case Quantity::kDimensionless:
      return "dimensionless";
  }
  return "unknown quantity";
}

std::vector<std::string> unit_spellings(Quantity quantity) {
  std::vector<std::string> out;
  for (const Spelling& entry : kSpellings) {
    if (entry.quantity == quantity) out.emplace_back(entry.spelling);
  }
  return out;
}

}  // namespace dynpos::core
