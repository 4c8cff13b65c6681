#pragma once
/// \file
/// Thrust agility from a log (thesis section 3.5.1, figures 3.1–3.3): the time to 63.2 % of the
/// response of every thruster, and of the vessel's speed √(u²+v²) (3.19), after a joystick
/// thrust step in each direction; the steps grouped into cases (thrust %, yaw %) with the mean
/// wind of each. The adapters give the JSON document, the text table and one polar plot per case.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/analysis/log_source.hpp"
#include "dynpos/analysis/outputs.hpp"
#include "dynpos/ident/agility.hpp"
#include "dynpos/report/table.hpp"

namespace dynpos::analysis {

/// A current as an operator reads it off the DP display: its speed and where it goes to.
struct ObservedCurrent {
  double speed_mps = 0.0;  ///< [m/s], ≥ 0
  double to_deg = 0.0;     ///< direction it flows towards, true [deg]
};

/// What `identify agility` analyses; request keys in parentheses (analysis/options.hpp).
struct AgilityRequest {
  /// Roles: time, command.surge, command.sway, command.yaw [%], thrust.NAME or rpm.NAME per
  /// thruster, u, v, wind_speed, wind_dir, heading.
  LogSource source;
  /// The steps given explicitly (window): T_STEP, T_END, DIR_DEG and the thrust (100 % when
  /// not given) and yaw demands [%] of each; empty: found in the joystick demands.
  std::vector<ident::AgilityWindow> windows;
  /// The current as observed (current), drawn as an arrow; absent: none drawn.
  std::optional<ObservedCurrent> current;
  /// Time the shaft speed (rpm.NAME) even when thrust is logged (rpm).
  bool use_rpm = false;
  /// A thruster whose change is below this % of its range has no response, in [0, 99]
  /// (min_response).
  double min_response_pct = 5.0;
  /// Thrust demands below this [%] count as no thrust, ≥ 0 (min_demand).
  double min_demand_pct = 5.0;

  /// Throws option_error naming the key of the first bad field.
  void validate() const;
};

/// Mean wind over the steps of a case.
struct AgilityWind {
  double speed_mps = 0.0;  ///< mean speed [m/s]
  double from_deg = 0.0;   ///< circular mean of the direction it comes from, true, [0, 360) [deg]
  std::optional<double> heading_deg;  ///< circular mean heading [0, 360) [deg], when logged
};

/// The steps of one case (thrust %, yaw %): one polar panel.
struct AgilityCase {
  std::string label;                ///< ident::agility_case_label
  std::vector<std::size_t> steps;   ///< indices into AgilityReport::result.steps, in time order
  std::optional<AgilityWind> wind;  ///< absent when the wind is not logged
};

/// The agility of every step, with what the outputs need to show it.
struct AgilityReport {
  std::filesystem::path log;            ///< the log, as given
  io::InputReport input;                ///< the files read, their formats and skipped lines
  std::string channel;                  ///< the timed channel: "thrust" or "rpm"
  std::vector<std::string> thrusters;   ///< thruster names NAME of the channels, in log order
  bool has_speed = false;               ///< u (and v) logged: the speed response is timed
  double min_response_fraction = 0.05;  ///< as a fraction of the channel's range
  double min_demand_pct = 5.0;          ///< [%]
  std::optional<ObservedCurrent> current;
  ident::AgilityResult result;     ///< status, message and the steps in time order
  std::vector<AgilityCase> cases;  ///< in order of first appearance
};

/// Validates the request, reads the log and times every step. Throws core::InputError naming
/// the log (and the channel by its role, e.g. thrust.port) on bad input.
AgilityReport run_agility(const AgilityRequest& request);

/// Envelope of the thrust response of a step: the time until every thruster has covered
/// 63.2 % of its response [s], i.e. the slowest one; absent when none responded.
std::optional<double> thrust_envelope_s(const ident::AgilityStep& step);

// The report's adapters: agility_report.cpp.

/// The JSON document of `identify agility --json`.
nlohmann::json to_json(const AgilityReport& report);

/// The table of the steps: case, direction, step time, the time of each thruster, the thrust
/// envelope and the speed response [s]; "—" = no response.
report::Table agility_table(const AgilityReport& report);

/// The text `identify agility` prints: a line on what is timed, the table (one row per step),
/// the mean wind of each case and a warning when the analysis failed.
std::string to_text(const AgilityReport& report);

/// Writes the polar plot (SVG), one panel per case: a series per thruster, the thrust envelope,
/// the speed response, the wind and current arrows relative to the bow. Title: `title`, or
/// "Thrust agility: LOG_FILE_NAME" when empty.
void write_plot(const AgilityReport& report, const std::filesystem::path& svg,
                const std::string& title = {});

/// The polar plot to outputs.figures (an SVG file) when given, then the JSON.
Written write_outputs(const AgilityReport& report, const Outputs& outputs);

}  // namespace dynpos::analysis
