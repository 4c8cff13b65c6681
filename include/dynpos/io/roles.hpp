#pragma once
/// \file
/// Roles: what a log column means, independent of what the file calls it.
///
/// A column map (column_map.hpp) binds roles to column names; the CSV reader loads each mapped
/// column into a channel named after its role, converted to SI. Each role fixes the physical
/// quantity its unit must measure, the unit assumed when none is declared, and how the channel
/// is interpolated between samples.
///
/// Fixed roles: time (or time.sec + time.nsec, and date for times of day), north, east, down, lat,
/// lon, height, heading, roll, pitch, p, q, r, u, v, w, wind_speed, wind_dir, setpoint.north,
/// setpoint.east, setpoint.heading, input, output, trigger. Pattern roles: thrust.NAME, power.NAME,
/// rpm.NAME, rudder.NAME, command.NAME (NAME: letters, digits, '_' or '-', e.g. "port", "tunnel"),
/// gnssK.lat|lon|height|north|east|down and mruK.ax|ay|az (K: a positive integer without leading
/// zeros, e.g. "gnss2.lat"). The full table is in docs/log-format.md.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dynpos/core/log.hpp"
#include "dynpos/core/units.hpp"

namespace dynpos::io {

/// What a role means and how its values are read.
struct RoleSpec {
  /// The role name, e.g. "heading" or "thrust.port". In role_catalogue() the pattern roles
  /// appear with their placeholders, e.g. "thrust.NAME", "gnssK.lat".
  std::string name;
  /// The quantity a declared unit must measure; nullopt for the generic roles (input, output,
  /// trigger), which accept any known unit and are kept as logged when none is declared.
  std::optional<core::Quantity> quantity;
  /// The unit assumed when neither the map nor the CSV header gives one (a core::find_unit
  /// spelling, e.g. "deg", "kN", "1").
  std::string default_unit;
  /// Continuous signals interpolate linearly (kLinear), angles that may wrap (heading, roll,
  /// pitch, lon, wind_dir, rudder.NAME, gnssK.lon, mruK.roll|pitch) along the shorter arc
  /// (kAngle); discrete ones (setpoints, commands, triggers) hold their last value (kHold).
  core::Interp interp = core::Interp::kLinear;
  /// One line for help texts, e.g. "heading ψ, clockwise from north".
  std::string description;

  /// True for a discrete (sample-and-hold) signal.
  bool discrete() const noexcept {
    return interp == core::Interp::kHold || interp == core::Interp::kNearest;
  }
};

/// The spec of a role name, or nullopt if it is not a role (names are case-sensitive).
std::optional<RoleSpec> find_role(std::string_view name);

/// Every role, fixed ones first, pattern roles with their placeholders, for docs and help.
const std::vector<RoleSpec>& role_catalogue();

/// The catalogue name closest to `name` (edit distance), for "did you mean" hints; empty if
/// nothing is reasonably close.
std::string closest_role(std::string_view name);

}  // namespace dynpos::io
