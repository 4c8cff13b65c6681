#pragma once
/// \file
/// Stationkeeping (pure DP): position, heading, wind and thrust statistics of a log over one
/// window or per DP setpoint hold (thesis tables 3.11–3.22), as a request → report analysis.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/analysis/log_source.hpp"
#include "dynpos/analysis/outputs.hpp"
#include "dynpos/ident/station_keeping.hpp"
#include "dynpos/report/table.hpp"

namespace dynpos::analysis {

/// The options of the analysis; request keys in parentheses (analysis/options.hpp).
struct StationKeepingRequest {
  /// time; north, east [m, any offset] or lat, lon; heading, wind_speed, wind_dir;
  /// thrust.NAME, power.NAME; setpoint.north/east/heading.
  LogSource source;
  /// The window [s] (from, to): only its rows are read; a window without a row of the log is
  /// an error of "from/to" (LogSource::load), as is one not inside the log.
  std::optional<double> t_from_s;
  std::optional<double> t_to_s;
  /// Window length [s] when t_from_s or t_to_s is missing: the last duration_s of the log, or
  /// of each setpoint hold (duration), > 0.
  double duration_s = 300.0;
  /// One window per DP setpoint hold (per_setpoint); t_from_s/t_to_s take precedence.
  bool per_setpoint = false;
  /// The waves and the current as observed, free text kept in the report (waves, current).
  std::string waves;
  std::string current;

  /// Throws option_error naming the key of the first bad option.
  void validate() const;
};

/// The statistics of each window, with the inputs the outputs name.
struct StationKeepingReport {
  std::filesystem::path log;  ///< the log as given
  io::InputReport input;      ///< the files read, their formats and skipped lines
  std::string waves;          ///< as observed; empty = not given
  std::string current;        ///< as observed; empty = not given
  bool per_setpoint = false;  ///< the windows were asked per setpoint hold
  std::vector<ident::StationKeepingResult> windows;
};

/// Validates the request, reads the log and analyses each window. core::InputError naming the
/// log when it holds no position, or no setpoints with per_setpoint; naming the window when it
/// is not inside the log.
StationKeepingReport run_station_keeping(const StationKeepingRequest& request);

/// The document `identify station-keeping --json` writes: analysis, log, observed, and the one
/// window's figures at the top level, or "windows" (per setpoint or several windows).
nlohmann::json to_json(const StationKeepingReport& report);

/// Rows of thesis tables 3.14–3.22, one column per window; missing figures are "—".
report::Table station_keeping_table(const StationKeepingReport& report);

/// What `identify station-keeping` prints: the log and its windows, the observed conditions
/// and the table.
std::string to_text(const StationKeepingReport& report);

/// Writes the outputs of `identify station-keeping`: the JSON (it draws no figure).
Written write_outputs(const StationKeepingReport& report, const Outputs& outputs);

}  // namespace dynpos::analysis
