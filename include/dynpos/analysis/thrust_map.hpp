#pragma once
/// \file
/// The thrust map T = c·n|n| (3.17) of every thruster of a log: back-calculated from logged
/// thrust and shaft speed, or applied to a log with shaft speed only (3.18).

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/analysis/log_source.hpp"
#include "dynpos/analysis/outputs.hpp"
#include "dynpos/core/log.hpp"
#include "dynpos/ident/thrust_map.hpp"

namespace dynpos::analysis {

/// What to do with the log's roles time, rpm.NAME (shaft speed) and thrust.NAME per thruster
/// NAME.
struct ThrustMapRequest {
  LogSource source;
  /// Samples with |n| below this [rpm] ≥ 0 are left out of the fit: near zero the thrust is
  /// noise. Request key "min_speed".
  double min_speed_rpm = 3.0;
  /// Apply the vessel file's maps to the shaft speeds instead of fitting.
  bool apply = false;
  /// With apply: the log has |n| only, so use the mean coefficient (3.18).
  bool abs_speed = false;
  /// With apply: the vessel file; empty for the built-in Gunnerus.
  std::filesystem::path vessel;
  /// With apply: the CSV the applied thrust goes to (request key "out"). The analysis' further
  /// output: write_outputs() writes it, next to Outputs' JSON, and the report's text names it.
  std::filesystem::path out;

  /// Throws option_error("min_speed") for a negative speed, option_error("out") for apply
  /// without a CSV to write.
  void validate() const;
};

/// The back-calculated map of one thruster.
struct ThrusterMapFit {
  std::string name;               ///< NAME of rpm.NAME and thrust.NAME
  ident::ThrustMapFitResult fit;  ///< c₊, c₋ [N/rps²] with 1σ, sample counts, R², status
  std::optional<double> c_mean;   ///< c̄ = (c₊ + |c₋|)/2 [N/rps²] (3.18), when both are known
};

/// The thrust of a log's shaft speeds through the vessel file's maps.
struct AppliedThrust {
  core::Log log;              ///< time, rpm.NAME [rpm] and thrust.NAME [kN] per thruster
  std::size_t thrusters = 0;  ///< how many thrusters
  std::string vessel_source;  ///< the vessel file, or "" for the built-in vessel
  bool abs_speed = false;     ///< |n| only: the mean coefficient (3.18)
  std::filesystem::path csv;  ///< where write_outputs() writes `log` (the request's out)
};

/// The result of run_thrust_map(): the fits, or with apply the applied thrust.
struct ThrustMapReport {
  std::filesystem::path log;
  io::InputReport input;  ///< the files read, their formats and skipped lines
  double min_speed_rpm = 3.0;
  std::vector<ThrusterMapFit> thrusters;  ///< every thruster with shaft speed and thrust
  std::optional<AppliedThrust> applied;   ///< set with apply
};

/// Validates, reads the log and back-calculates c₊ and c₋ of T = c·n|n| (3.17) per thruster;
/// with apply, computes T from n by the vessel file's maps, c = ρK_T·D⁴ of each thruster model,
/// or from |n| by c̄ (3.18). Throws InputError naming the log when it has no thruster to fit or
/// to apply a map to.
ThrustMapReport run_thrust_map(const ThrustMapRequest& request);

// The report's adapters: thrust_map_report.cpp.

/// The `identify thrust-map --json` document: {analysis, log, unit, thrusters: [{name, c_pos,
/// c_neg, sigma {c_pos, c_neg}, c_mean, n_samples {pos, neg}, r_squared, status, message}]}, in
/// N/rps². With apply the thrusters are empty (nothing is fitted).
nlohmann::json to_json(const ThrustMapReport& report);

/// What `identify thrust-map` prints: the table of the fits in kN/rps², or with apply one line
/// that names the CSV the applied thrust goes to.
std::string to_text(const ThrustMapReport& report);

/// With apply, writes the applied thrust to its CSV (AppliedThrust::csv; named by to_text(),
/// so not listed in the files written); then the JSON where outputs.json says.
Written write_outputs(const ThrustMapReport& report, const Outputs& outputs);

}  // namespace dynpos::analysis
