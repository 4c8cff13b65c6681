#pragma once
/// \file
/// `dynpos estimate LOG`: a DP observer run over a logged DP run (control/observer_run.hpp),
/// giving the low-frequency motion and the bias b̂ — the environmental load the thrusters held
/// against, in NED — as a time series, and b̂'s mean and spread over the log.
///
/// The inputs, as the DP system had them: the control origin's position (north/east or lat/lon
/// moved by the antenna's lever arm, control_origin_track.hpp), the heading, and the thrust τ
/// (BODY) of each unit's feedback through the vessel's actuator models
/// (scenario/thrust_feedback.hpp). The observer's model: M and D of the vessel's DP controller and
/// the wave model at the peaks of the vessel's wave-frequency motion in a sea of the peak period
/// T_p the operator enters (scenario/dp_estimator.hpp observer_model). A GNSS gap longer than
/// max_hold_s is bridged on a logged MRU (inertial_bridge.hpp), as the DP system's inertial
/// bridge does in the loop.
///
/// estimate.cpp (request, validate, run); estimate_report.cpp (JSON, text, CSV, outputs).

#include <Eigen/Core>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/analysis/log_source.hpp"
#include "dynpos/analysis/outputs.hpp"
#include "dynpos/control/observer_run.hpp"
#include "dynpos/core/log.hpp"
#include "dynpos/scenario/thrust_feedback.hpp"

namespace dynpos::analysis {

/// The options of the analysis; request keys in parentheses (analysis/options.hpp).
struct EstimateRequest {
  /// time; north, east [m, any offset] or lat, lon; heading; roll, pitch (with an arm's
  /// height, and for the bridge); per unit of the vessel thrust.NAME and its angle rudder.NAME
  /// or azimuth.NAME; mruK.ax, ay, az (the bridge).
  LogSource source;
  std::filesystem::path vessel;  ///< vessel file (vessel); empty: the built-in Gunnerus
  /// Lever arm (x forward, y starboard, z down; BODY) [m] of the antenna whose position is
  /// logged (arm); absent: the logged position is the control origin's.
  std::optional<Eigen::Vector3d> arm_m;
  std::string observer = "ekf";  ///< "passive" or "ekf" (observer)
  /// The wave peak period T_p [s] the observer's wave model is set for (tp), 2–20 s. Source of
  /// 8 s: reasoned — the middle of DNV-ST-0111's Level 1 table (T_p 7.5–9 s for H_s 2–4 m); the
  /// operator enters the sea's.
  double tp_s = 8.0;
  double rate_hz = 10.0;  ///< the observer's step rate [Hz] (rate), 0.1–100
  /// Longest time [s] a sample stands for its input (max_hold), > 0 (observer_run.hpp).
  double max_hold_s = 5.0;
  /// The summary leaves out this long after the observer starts [s] (settle), ≥ 0: b̂ starts at
  /// zero (the EKF follows a change in about 30 s; the passive observer's slow pole has a time
  /// constant of 20–26 s on a T_p of 8 s, passive_observer.hpp).
  double settle_s = 120.0;
  /// The MRU a GNSS gap longer than max_hold_s is bridged on (mru; inertial_bridge.hpp):
  /// "auto" (the first of the vessel's MRUs whose mruK.ax/ay/az the log has, with roll and
  /// pitch mapped; none: no bridge), "none", or a vessel MRU's name (its channels, roll and
  /// pitch required). Its lever arm and noise are the vessel file's.
  std::string mru = "auto";
  /// Analyse from / up to this log time [s] (from, to): only these rows are read.
  std::optional<double> t_from_s;
  std::optional<double> t_to_s;
  /// The time series CSV (out); empty: none. The analysis' further output: write_outputs()
  /// writes it, next to Outputs' JSON.
  std::filesystem::path out;

  /// Throws option_error naming the key of the first bad field.
  void validate() const;
  /// The observer run's options, checked.
  control::ObserverRunOptions run_options() const;
};

/// The mean and the standard deviation of b̂ (NED) over the samples from `from_s` to `to_s`.
struct BiasSummary {
  double from_s = 0.0;
  double to_s = 0.0;
  std::size_t samples = 0;
  Eigen::Vector3d mean_n = Eigen::Vector3d::Zero();  ///< [N, N, N·m]
  Eigen::Vector3d std_n = Eigen::Vector3d::Zero();   ///< [N, N, N·m]
};

/// The run and what its outputs need to show it.
struct EstimateReport {
  std::filesystem::path log;  ///< the log as given
  io::InputReport input;      ///< the files read, their formats and skipped lines
  std::string vessel;         ///< the vessel's name
  std::string vessel_source;  ///< its file as given; empty for the built-in one
  std::vector<scenario::FeedbackChannel> units;  ///< the thrust's channels, in layout order
  std::string position;  ///< the roles of the position: "north/east" or "lat/lon"
  std::optional<Eigen::Vector3d> arm_m;
  bool attitude = false;  ///< the arm was applied with the logged roll and pitch
  control::ObserverKind observer = control::ObserverKind::kEkf;
  double tp_s = 8.0;
  Eigen::Vector3d wave_peak_frequency_rad_s = Eigen::Vector3d::Zero();  ///< ω₀ (N, E, ψ)
  control::ObserverRunOptions run;  ///< rate, hold and whether the measurement is held
  double settle_s = 120.0;
  /// The MRU GNSS gaps were bridged on (empty: none), its lever arm (BODY) [m], the rows given
  /// the bridge's position and the longest gap bridged [s].
  std::string bridge_mru;
  Eigen::Vector3d bridge_arm_m = Eigen::Vector3d::Zero();
  std::size_t bridged_rows = 0;
  double longest_gap_bridged_s = 0.0;
  control::ObserverTrack track;
  std::optional<BiasSummary> bias;  ///< none when the log ends within the settling time
  std::filesystem::path csv;        ///< where write_outputs() writes the series (the out)
};

/// Validates the request, reads the vessel and the log, and runs the observer. core::InputError
/// naming the log for a missing position, heading or unit feedback (naming the role), or no
/// time at which all are present; naming the option for a bad request.
EstimateReport run_estimate(const EstimateRequest& request);

/// The mean and standard deviation of b̂ over the track's samples from `from_s` on (t ≥ from_s);
/// none when there is no such sample.
std::optional<BiasSummary> summarise_bias(const control::ObserverTrack& track, double from_s);

// The report's adapters: estimate_report.cpp.

/// The time series the CSV holds: lf.north, lf.east [m], lf.heading [deg, 0–360), lf.u, lf.v
/// [m/s], lf.r [deg/s], bias.north, bias.east [kN] (NED), bias.yaw [kN*m], position.age [s]
/// (ObserverTrack::position_age_s).
core::Log estimate_log(const control::ObserverTrack& track);

/// The `estimate --json` document (docs/cli.md).
nlohmann::json to_json(const EstimateReport& report);

/// What `estimate` prints: the inputs, the observer and the mean bias.
std::string to_text(const EstimateReport& report);

/// Writes the series' CSV (report.csv, when set), then the JSON where outputs.json says.
Written write_outputs(const EstimateReport& report, const Outputs& outputs);

}  // namespace dynpos::analysis
