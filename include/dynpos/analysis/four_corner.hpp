#pragma once
/// \file
/// The DP 4-corner maneuver from a log (thesis section 3.5.2, tables 3.6–3.10): the log cut into
/// its legs, with the duration, accumulated thrust ∫|T|dt and energy ∫P dt of each thruster per
/// leg and in total. The adapters give the JSON document, the table (thesis table 3.6) and the
/// NE plot of the track (figure 3.5).

#include <Eigen/Core>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "dynpos/analysis/log_source.hpp"
#include "dynpos/analysis/outputs.hpp"
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
  /// How the legs are found (segment; leg_segmentation_names()).
  ident::LegSegmentation segmentation = ident::LegSegmentation::kAuto;
  /// Horizontal lever arm (x forward, y starboard, BODY) [m] of the antenna whose position is
  /// logged; the position is moved to the control origin (arm). Absent: the logged position
  /// is the control origin's.
  std::optional<Eigen::Vector2d> arm_m;
  /// Analyse from / up to this log time [s] (from, to): only these rows are read; a window
  /// without a row of the log is an error of "from/to" (LogSource::load).
  std::optional<double> t_from_s;
  std::optional<double> t_to_s;

  /// The analysis options of the request. Throws option_error("radius/heading_tol") when the
  /// operating circle is not > 0.
  ident::FourCornerOptions options() const;
  /// Throws option_error naming the key of the first bad field.
  void validate() const;
};

/// The name of a segmentation in reports and options: "auto", "setpoints" or "track".
std::string to_string(ident::LegSegmentation segmentation);

/// Every segmentation by its name (to_string), for the front ends' choices.
const std::map<std::string, ident::LegSegmentation>& leg_segmentation_names();

/// The segmentation named "auto", "setpoints" or "track". Throws option_error("segment")
/// for another name.
ident::LegSegmentation parse_leg_segmentation(const std::string& name);

/// The legs of the maneuver, with what the outputs need to show them.
struct FourCornerReport {
  std::filesystem::path log;  ///< the log, as given
  io::InputReport input;      ///< the files read, their formats and skipped lines
  double radius_m = 2.0;
  double heading_tol_deg = 2.0;
  std::optional<Eigen::Vector2d> arm_m;
  /// The logged channels of the analysed window, SI: the track the NE plot draws.
  ident::FourCornerInput track;
  ident::FourCornerResult result;  ///< the legs and the total
};

/// Validates the request, reads the log within the window [from, to] and finds the legs.
/// Throws core::InputError naming the log on bad input (no position, no heading, a window
/// without a row of the log, no leg).
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

/// Writes the outputs of `identify four-corner`: outputs.figures is the SVG file of the NE plot
/// (--plot, plot=), then the JSON.
Written write_outputs(const FourCornerReport& report, const Outputs& outputs);

}  // namespace dynpos::analysis
