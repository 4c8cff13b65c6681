#include "dynpos/io/roles.hpp"

#include <algorithm>
#include <array>

#include "text_util.hpp"

namespace dynpos::io {
namespace {

using core::Interp;
using core::Quantity;

RoleSpec make(std::string name, std::optional<Quantity> quantity, std::string unit, Interp interp,
              std::string description) {
  return RoleSpec{std::move(name), quantity, std::move(unit), interp, std::move(description)};
}

std::vector<RoleSpec> build_catalogue() {
  const auto cont = Interp::kLinear;
  const auto hold = Interp::kHold;
  // Angles that wrap or may cross ±180°/0°/360° go along the shorter arc; latitude never wraps.
  const auto angle = Interp::kAngle;
  return {
      make("time", Quantity::kTime, "s", cont, "time axis, strictly increasing"),
      make("time.sec", Quantity::kTime, "s", cont, "whole seconds of a two-column time stamp"),
      make("time.nsec", std::nullopt, "1", cont,
           "nanoseconds (integer) of a two-column time stamp, with time.sec"),
      make("date", std::nullopt, "1", hold, "date (YYYY-MM-DD) of time-of-day stamps"),
      make("north", Quantity::kLength, "m", cont, "position north of the local origin (NED x)"),
      make("east", Quantity::kLength, "m", cont, "position east of the local origin (NED y)"),
      make("down", Quantity::kLength, "m", cont, "position down (NED z)"),
      make("lat", Quantity::kAngle, "deg", cont, "geodetic latitude"),
      make("lon", Quantity::kAngle, "deg", angle, "geodetic longitude"),
      make("height", Quantity::kLength, "m", cont, "height above the ellipsoid"),
      make("heading", Quantity::kAngle, "deg", angle, "heading ψ, clockwise from north"),
      make("roll", Quantity::kAngle, "deg", angle, "roll φ, starboard down positive"),
      make("pitch", Quantity::kAngle, "deg", angle, "pitch θ, bow up positive"),
      make("p", Quantity::kAngularRate, "deg/s", cont, "roll rate (BODY x)"),
      make("q", Quantity::kAngularRate, "deg/s", cont, "pitch rate (BODY y)"),
      make("r", Quantity::kAngularRate, "deg/s", cont, "yaw rate (BODY z)"),
      make("u", Quantity::kSpeed, "m/s", cont, "surge speed (BODY x)"),
      make("v", Quantity::kSpeed, "m/s", cont, "sway speed (BODY y)"),
      make("w", Quantity::kSpeed, "m/s", cont, "heave speed (BODY z)"),
      make("wind_speed", Quantity::kSpeed, "m/s", cont, "wind speed"),
      make("wind_dir", Quantity::kAngle, "deg", angle, "direction the wind comes from"),
      make("setpoint.north", Quantity::kLength, "m", hold, "DP position setpoint, north"),
      make("setpoint.east", Quantity::kLength, "m", hold, "DP position setpoint, east"),
      make("setpoint.heading", Quantity::kAngle, "deg", hold, "DP heading setpoint"),
      make("input", std::nullopt, "1", hold, "generic test input (e.g. a step command)"),
      make("output", std::nullopt, "1", cont, "generic measured response"),
      make("trigger", std::nullopt, "1", hold, "generic event or trigger signal"),
      make("thrust.NAME", Quantity::kForce, "kN", cont, "thrust of thruster NAME"),
      make("power.NAME", Quantity::kPower, "kW", cont, "power of thruster NAME"),
      make("rpm.NAME", Quantity::kShaftSpeed, "rpm", cont, "shaft speed of thruster NAME"),
      make("rudder.NAME", Quantity::kAngle, "deg", angle, "angle of rudder NAME"),
      make("azimuth.NAME", Quantity::kAngle, "deg", angle,
           "thrust direction of azimuth NAME, clockwise from ahead"),
      make("command.NAME", Quantity::kFraction, "%", hold, "thrust or pitch command to NAME"),
      make("command.rpm.NAME", Quantity::kShaftSpeed, "rpm", hold,
           "commanded shaft speed of thruster NAME"),
      make("command.thrust.NAME", Quantity::kForce, "kN", hold,
           "commanded (allocated) thrust of thruster NAME"),
      make("command.rudder.NAME", Quantity::kAngle, "deg", hold, "commanded angle of rudder NAME"),
      make("command.azimuth.NAME", Quantity::kAngle, "deg", hold,
           "commanded thrust direction of azimuth NAME, clockwise from ahead"),
      make("gnssK.lat", Quantity::kAngle, "deg", cont, "latitude of GNSS antenna K"),
      make("gnssK.lon", Quantity::kAngle, "deg", angle, "longitude of GNSS antenna K"),
      make("gnssK.height", Quantity::kLength, "m", cont, "ellipsoidal height of antenna K"),
      make("gnssK.north", Quantity::kLength, "m", cont, "antenna K position north"),
      make("gnssK.east", Quantity::kLength, "m", cont, "antenna K position east"),
      make("gnssK.down", Quantity::kLength, "m", cont, "antenna K position down"),
      make("mruK.ax", Quantity::kAcceleration, "m/s^2", cont,
           "MRU K linear acceleration, BODY x (kinematic or specific force)"),
      make("mruK.ay", Quantity::kAcceleration, "m/s^2", cont,
           "MRU K linear acceleration, BODY y (kinematic or specific force)"),
      make("mruK.az", Quantity::kAcceleration, "m/s^2", cont,
           "MRU K linear acceleration, BODY z (kinematic or specific force)"),
      make("mruK.roll", Quantity::kAngle, "deg", angle, "roll reported by MRU K"),
      make("mruK.pitch", Quantity::kAngle, "deg", angle, "pitch reported by MRU K"),
      make("mruK.p", Quantity::kAngularRate, "deg/s", cont, "roll rate reported by MRU K"),
      make("mruK.q", Quantity::kAngularRate, "deg/s", cont, "pitch rate reported by MRU K"),
      make("mruK.r", Quantity::kAngularRate, "deg/s", cont, "yaw rate reported by MRU K"),
  };
}

// NAME of a thruster/rudder: letters, digits, '_' or '-'.
bool valid_name_part(std::string_view part) {
  if (part.empty()) return false;
  return std::all_of(part.begin(), part.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-';
  });
}

// K of a sensor index: a positive integer without leading zeros.
bool valid_index_part(std::string_view part) {
  if (part.empty() || part.front() == '0') return false;
  return std::all_of(part.begin(), part.end(), [](char c) { return c >= '0' && c <= '9'; });
}

const RoleSpec* catalogue_entry(std::string_view name) {
  const auto& all = role_catalogue();
  const auto it =
      std::find_if(all.begin(), all.end(), [&](const RoleSpec& r) { return r.name == name; });
  return it == all.end() ? nullptr : &*it;
}

}  // namespace

const std::vector<RoleSpec>& role_catalogue() {
  static const std::vector<RoleSpec> catalogue = build_catalogue();
  return catalogue;
}

std::optional<RoleSpec> find_role(std::string_view name) {
  if (const RoleSpec* entry = catalogue_entry(name)) {
    // Placeholders ("thrust.NAME", "gnssK.lat") are documentation, not roles.
    if (name.find("NAME") == std::string_view::npos && name.find("K.") == std::string_view::npos) {
      return *entry;
    }
  }
  const auto dot = name.find('.');
  if (dot == std::string_view::npos) return std::nullopt;
  // The catalogue's role `pattern` ("thrust.NAME", "gnssK.lat") under the name asked for.
  const auto instantiate = [name](std::string_view pattern) -> std::optional<RoleSpec> {
    const RoleSpec* entry = catalogue_entry(pattern);
    if (entry == nullptr) return std::nullopt;
    RoleSpec spec = *entry;
    spec.name = std::string(name);
    return spec;
  };
  const std::string_view prefix = name.substr(0, dot);
  const std::string_view suffix = name.substr(dot + 1);

  static constexpr std::array<std::string_view, 6> kNamed = {"thrust", "power",   "rpm",
                                                             "rudder", "azimuth", "command"};
  if (prefix == "command") {
    // command.rpm.NAME, command.thrust.NAME, command.rudder.NAME, command.azimuth.NAME
    const auto dot2 = suffix.find('.');
    if (dot2 != std::string_view::npos) {
      const std::string_view kind = suffix.substr(0, dot2);
      if ((kind == "rpm" || kind == "thrust" || kind == "rudder" || kind == "azimuth") &&
          valid_name_part(suffix.substr(dot2 + 1))) {
        return instantiate("command." + std::string(kind) + ".NAME");
      }
      return std::nullopt;
    }
  }
  if (std::find(kNamed.begin(), kNamed.end(), prefix) != kNamed.end()) {
    if (!valid_name_part(suffix)) return std::nullopt;
    return instantiate(std::string(prefix) + ".NAME");
  }
  for (const std::string_view sensor : {std::string_view("gnss"), std::string_view("mru")}) {
    if (prefix.size() > sensor.size() && prefix.substr(0, sensor.size()) == sensor &&
        valid_index_part(prefix.substr(sensor.size()))) {
      return instantiate(std::string(sensor) + "K." + std::string(suffix));
    }
  }
  return std::nullopt;
}

std::string closest_role(std::string_view name) {
  std::vector<std::string> names;
  for (const auto& role : role_catalogue()) names.push_back(role.name);
  return detail::closest_match(name, names);
}

}  // namespace dynpos::io
