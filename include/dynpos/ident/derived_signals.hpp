#pragma once
/// \file
/// Signals derived from logged channels for the step analyses: the total speed used for the
/// sway tests (3.19) and the yaw rate in degrees per second used for the yaw tests (3.16).
/// A NaN in an input gives NaN in the output (missing stays missing).

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dynpos/core/log.hpp"

namespace dynpos::ident {

/// Total speed, (3.19): U = √(u² + v²) [m/s] from surge u and sway v [m/s].
/// Throws core::InputError if the lengths differ.
std::vector<double> total_speed(std::span<const double> u_mps, std::span<const double> v_mps);

/// Yaw rate in deg/s from r [rad/s], the unit of (3.16) and tables 3.31–3.32.
std::vector<double> yaw_rate_deg_s(std::span<const double> r_rad_s);

/// Adds channel `name` (unit "m/s") = total_speed() of channels `u` and `v` to the log.
/// Throws std::out_of_range if a channel is absent, std::invalid_argument if `name` is taken.
void add_total_speed(core::Log& log, std::string_view u, std::string_view v,
                     std::string name = "U");

/// Adds channel `name` (unit "deg/s") = yaw_rate_deg_s() of channel `r` [rad/s] to the log.
/// Throws std::out_of_range if `r` is absent, std::invalid_argument if `name` is taken.
void add_yaw_rate_deg_s(core::Log& log, std::string_view r, std::string name = "r_deg_s");

}  // namespace dynpos::ident
