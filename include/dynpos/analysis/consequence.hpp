#pragma once
/// \file
/// `dynpos consequence LOG`: the consequence analysis of DP (DNV-RU-SHIP Pt.6 Ch.3) along a
/// logged run — would the vessel have lost position had its worst single failure happened here?
///
/// The environmental load is the observer's b̂ (estimate.hpp) in NED, averaged over a trailing
/// window (60 s: the wave-frequency and gust ripple out, a change of the weather kept), and
/// taken into BODY at the estimated heading there: τ_env = R(ψ̂)ᵀ b̄. Every `step` (10 s) the
/// largest factor λ of τ_env held after each single failure of the vessel
/// (capability/consequence.hpp: each unit and redundancy group of a [[thruster]] layout, each
/// actuator of the model) and intact; the margin is λ − 1 of the worst case: negative, the
/// thrusters left would not have held the load.
///
/// consequence.cpp (request, validate, run); consequence_report.cpp (JSON, text, CSV, outputs).

#include <Eigen/Core>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/analysis/estimate.hpp"
#include "dynpos/analysis/outputs.hpp"

namespace dynpos::analysis {

/// The options of the analysis; request keys in parentheses (analysis/options.hpp).
struct ConsequenceRequest {
  /// The observer run over the log (its keys; its `out` is not written).
  EstimateRequest estimate;
  double step_s = 10.0;         ///< one point every this long on the log's clock [s] (step), > 0
  double mean_window_s = 60.0;  ///< the trailing mean of b̂ [s] (window), > 0
  std::filesystem::path out;    ///< the points' CSV (out); empty: none
  /// Throws option_error naming the key of the first bad field.
  void validate() const;
};

/// One point of the log.
struct ConsequencePoint {
  double t_s = 0.0;
  double heading_rad = 0.0;                          ///< ψ̂ at t, [0, 2π)
  Eigen::Vector3d bias_n = Eigen::Vector3d::Zero();  ///< b̄ (NED) [N, N, N·m]
  Eigen::Vector3d load_b = Eigen::Vector3d::Zero();  ///< τ_env = R(ψ̂)ᵀ b̄ (BODY) [N, N, N·m]
  double intact = 0.0;                               ///< λ intact
  bool intact_capped = false;                        ///< held at kMaxLoadFactor
  std::vector<double> factors;        ///< λ per failure case, in ConsequenceReport::cases order
  std::size_t worst = 0;              ///< the case of the smallest λ (the first of equal ones)
  std::vector<std::string> limiting;  ///< actuators at a limit in the worst case at its λ
  double margin() const { return factors.at(worst) - 1.0; }
};

/// The report.
struct ConsequenceReport {
  EstimateReport estimate;         ///< the observer run
  std::string layout;              ///< "[[thruster]]" or "model"
  std::vector<std::string> cases;  ///< the single failures
  double step_s = 10.0;
  double mean_window_s = 60.0;
  std::vector<ConsequencePoint> points;
  std::filesystem::path csv;  ///< where write_outputs() writes the points (the out)
};

/// Validates, runs the observer over the log and computes each point. core::InputError as
/// run_estimate(), and naming the log when it ends before the first point (settle + window
/// after the observer's start).
ConsequenceReport run_consequence(const ConsequenceRequest& request);

/// The summary of the points.
struct ConsequenceSummary {
  std::size_t smallest = 0;             ///< the point of the smallest margin (the first of equal)
  double fraction_negative = 0.0;       ///< of the points with margin < 0 [-]
  double fraction_below_reserve = 0.0;  ///< with λ < DNV's reserve for dynamics (1.25) [-]
  std::vector<std::size_t> case_min;    ///< per case, the point of its smallest λ
  std::vector<double> case_fraction_below_one;  ///< per case, the points with λ < 1 [-]
  std::size_t intact_min = 0;                   ///< the point of the smallest intact λ
};

/// The summary of `report`'s points (at least one).
ConsequenceSummary summarise(const ConsequenceReport& report);

// The report's adapters: consequence_report.cpp.

/// The `consequence --json` document (docs/cli.md).
nlohmann::json to_json(const ConsequenceReport& report);

/// What `consequence` prints: the smallest margin, the fraction of time below zero and per
/// failure case its smallest λ.
std::string to_text(const ConsequenceReport& report);

/// Writes the points' CSV (report.csv, when set), then the JSON where outputs.json says.
Written write_outputs(const ConsequenceReport& report, const Outputs& outputs);

}  // namespace dynpos::analysis
