#pragma once
/// \file
/// The DP 4-corner maneuver from a log (thesis section 3.5.2, tables 3.6–3.10): the log cut into
/// its legs, with the duration, accumulated thrust ∫|T|dt and energy ∫P dt of each thruster per
/// leg and in total. The adapters give the JSON document, the table (thesis table 3.6) and the
/// NE plot of the track (figure 3.5).

#include <array>
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "dynpos/analysis/log_source.hpp"
#include "dynpos/ident/four_corner.hpp"
#include "dynpos/report/table.hpp"

namespace dynpos::analysis {

/// What `identify four-corner` analyses; request keys in parentheses (analysis/options.hpp).
struct FourCornerRequest {
  /// Roles: time, north, east [m, any offset] or lat, lon; heading; setpoint.north/east/heading;
  /// thrust.NAME, power.NAME.
  LogSource source;
  double radius_m = 2.0;         ///< operating circle radius [m], > 0 (radius)
  double heading_tol_deg = 2.0;  ///< operating circle heading tolerance [deg], > 0 (heading_tol)
  /// How the legs are found (segment).
  ident::LegSegmentation segmentation = ident::LegSegmentation::kAuto;
  /// Horizontal lever arm (x forward, y starboard, BODY) [m] of the antenna whose position is
  /// logged; the position is moved to the control origin (arm). Absent: the logged position
  /// is the control origin's.
  std::optional<std::array<double, 2>> arm_m;
  std::optional<double> t_from_s;  ///< analyse from this log time [s] (from)
  std::optional<double> t_to_s;    ///< analyse up to this log time [s] (to)

  /// The analysis options of the request. Throws option_error("radius/heading_tol") when the
  /// operating circle is not > 0.
  ident::FourCornerOptions options() const;
  /// Throws option_error naming the key of the first bad field.
  void validate() const;
};

/// The segmentation named "auto", "setpoints" or "track". Throws option_error("segment")
/// for another name.
ident::LegSegmentation parse_leg_segmentation(const std::string& name);

/// The legs of the maneuver, with what the outputs need to show them.
struct FourCornerReport {
  std::filesystem::path log;  ///< the log, as given
  io::InputReport input;      ///< the files read, their formats and skipped lines
  double radius_m = 2.0;
  double heading_tol_deg = 2.0;
  std::optional<std::array<double, 2>> arm_m;
  /// The logged channels of the analysed window, SI: the track the NE plot draws.
  ident::FourCornerInput track;
  ident::FourCornerResult result;  ///< the legs and the total
};

/// Validates the request, reads the log, cuts out the window [from, to] and finds the legs.
/// Throws core::InputError naming the log on bad input (no position, no heading, a window
/// outside the log, no leg).
FourCornerReport run_four_corner(const FourCornerRequest& request);

/// The JSON document of `identify four-corner --json`.
nlohmann::json to_json(const FourCornerReport& report);

/// The text `identify four-corner` prints: a line with the number of legs, then table 3.6 (a
/// row per leg and the total).
std::string to_text(const FourCornerReport& report);

/// Thesis table 3.6: per leg and in total the duration, the accumulated thrust [kNs] and the
/// energy [kJ] of each thruster and their total.
report::Table four_corner_table(const FourCornerReport& report);

/// Writes the NE plot (SVG, figure 3.5): the whole track, each leg in its own colour, and the
/// setpoints. Title: `title`, or "DP 4-corner: LOG" when empty.
void write_plot(const FourCornerReport& report, const std::filesystem::path& svg,
                const std::string& title = {});

}  // namespace dynpos::analysis
