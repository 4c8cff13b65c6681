#pragma once
/// \file
/// From sea trial to vessel file: `identify vessel` fits the low-speed hull model of a vessel
/// file (added mass, linear and quadratic damping in surge, sway and yaw, the sway–yaw coupling;
/// the wind coefficients when the logs hold wind) to logged step tests, zig-zags, turning
/// circles, 4-corner and station-keeping runs by an output-error fit of the simulator's own
/// model (scenario/hull_drive.hpp) driven by the logged thrust feedback, with σ from the
/// Jacobian and a cross-validation score; the model's units' dead times, tunnel time constant
/// and thrust maps, or a [[thruster]] layout's units' dead times, shaft time constants and
/// azimuth slew rates, from the step and thrust-map analyses of each log; `compare-trial`
/// re-simulates one logged test with a vessel file. docs/theory.md, "Vessel identification".

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/analysis/log_source.hpp"
#include "dynpos/analysis/outputs.hpp"
#include "dynpos/io/input_report.hpp"

namespace dynpos::analysis {

/// What `identify vessel` identifies; request keys in parentheses.
struct VesselIdRequest {
  /// One log per test (log options shared: map, columns, units). Roles: time, heading, u, v,
  /// r (or mruK.r), thrust.NAME and rudder.NAME/azimuth.NAME of every unit of the vessel,
  /// optionally wind_speed and wind_dir.
  std::vector<LogSource> logs;
  /// The starting vessel file (vessel); empty: the built-in Gunnerus. Its values start the fit,
  /// the values the data do not determine are kept, and its text is the output's.
  std::filesystem::path vessel_file;
  /// The test held out of the fit and scored (holdout): a LOG as given; empty: the last of two
  /// or more; "none": no cross-validation.
  std::string holdout;
  /// The largest σ/|value| of a determined value (max_rel_sigma), in (0, 1].
  double max_rel_sigma = 0.033;
  /// The largest σ/|value| of a value that is fitted at all (max_rel_sigma_fitted), in
  /// [max_rel_sigma, 1]: one between the two is weakly determined — fitted with the others (a
  /// wrong starting value held would pull them) and written, but not counted as determined.
  double max_rel_sigma_fitted = 0.25;
  /// Step of the re-simulation [s] (step), in [0.01, 1]; the log's rows are thinned to it.
  double step_s = 0.2;
  /// Spacing of the residuals [s] (sample), ≥ step_s: u, v and r at most this often.
  double sample_s = 1.0;
  /// Length of the stretches a log is cut into [s] (stretch), ≥ 30: each is re-simulated from
  /// its own start velocity in its own current (with a linear drift), as the sea's current
  /// changes over a trial.
  double stretch_s = 300.0;
  unsigned jobs = 0;  ///< threads; 0 = every core

  /// Throws option_error naming the key of the first bad field.
  void validate() const;
};

/// Adds one log per path of `logs` to request.logs, each with the log options of `shared` (map,
/// columns, units, formats) and its own path, and takes request.jobs from `shared`.
void add_logs(VesselIdRequest& request, const LogSource& shared,
              const std::vector<std::string>& logs);

/// One value of the vessel file.
struct VesselParameter {
  std::string key;          ///< "hull.x_u_Ns_m": the vessel file's table.key
  std::string unit;         ///< the key's unit
  double start = 0.0;       ///< the starting file's value [unit]
  double value = 0.0;       ///< identified, or the start when not determined [unit]
  double sigma = 0.0;       ///< 1σ [unit]; NaN when not fitted
  bool determined = false;  ///< σ/|value| ≤ max_rel_sigma
  bool fitted = false;      ///< σ/|value| ≤ max_rel_sigma_fitted: the value is the fit's
  /// Fitted: the tests it came from. Not determined: why, and the excitation a trial would
  /// need to determine it.
  std::string note;
};

/// One unit's order → shaft speed dynamics and thrust map as the logs show them (NaN: not
/// measured), and the starting file's model at the same order steps.
struct UnitIdentification {
  std::string unit;       ///< "port", "stb", "tunnel" or a layout unit's name
  std::size_t steps = 0;  ///< order steps with a FOPDT fit (3.7) of the shaft speed
  /// The steps' FOPDT time constant and dead time, combined over the steps and logs, with 1σ.
  double time_constant_s = 0.0, time_constant_sigma_s = 0.0;
  double dead_time_s = 0.0, dead_time_sigma_s = 0.0;
  /// The same fits of the starting file's model's response to the same steps.
  double model_time_constant_s = 0.0, model_dead_time_s = 0.0;
  /// Thrust map (3.17) c₊, c₋ [N/rps²] with 1σ, combined over the logs.
  double c_forward = 0.0, c_forward_sigma = 0.0, c_reverse = 0.0, c_reverse_sigma = 0.0;
  /// A layout's azimuth: its slew rate [deg/s] with 1σ from the rate-limited stretches of its
  /// turns, combined; NaN for another unit or without such a turn.
  double slew_rate_deg_per_s = 0.0, slew_rate_sigma_deg_per_s = 0.0;
  std::size_t turns = 0;  ///< the rate-limited stretches fitted
};

/// A test's measured and re-simulated motion.
struct TestResponse {
  std::string name;       ///< the log as given
  bool held_out = false;  ///< the cross-validation's test (scored with the parameters fitted
                          ///< without it; only its start velocity and current fitted)
  std::vector<double> time_s;
  /// Per channel u [m/s], v [m/s], r [rad/s]: measured (NaN where not sampled) and simulated.
  std::array<std::vector<double>, 3> measured, simulated;
  std::array<double, 3> nrmse{};  ///< RMSE / (max − min of the measured); NaN: none
  /// Fitted current (N, E) [m/s], the mean over the stretches' starts.
  Eigen::Vector2d current_n = Eigen::Vector2d::Zero();
  /// Track: logged and re-simulated position (N, E) [m] and its NRMSE; empty/NaN without a
  /// logged position.
  std::vector<double> north_m, east_m, sim_north_m, sim_east_m;
  double track_nrmse = 0.0;
};

struct VesselIdReport {
  std::filesystem::path vessel_file;  ///< the starting file read
  std::string vessel_text;            ///< its text, for the output file
  std::vector<io::InputReport> inputs;
  std::vector<VesselParameter> parameters;  ///< the hull's and wind's, then the units'
  std::vector<UnitIdentification> units;    ///< the model's units, or the layout's
  std::vector<TestResponse> tests;          ///< each fitted test, then the held-out one
  std::string held_out;                     ///< the held-out test; empty: none
  int iterations = 0;
  std::string solver_message;  ///< empty when the fit converged
  double run_time_s = 0.0;
};

/// Reads the logs and the starting vessel, fits, cross-validates. Throws core::InputError on bad
/// input (a log without a role the fit needs, naming it).
VesselIdReport run_vessel_id(const VesselIdRequest& request);

/// The starting vessel file's text with each fitted value replaced and commented with its σ and
/// the tests it came from (line by line: keys, comments and layout kept; a key the file lacks is
/// added to its table). Keys "table.key" edit [table]; "thruster.NAME.key" the [[thruster]]
/// table whose name is NAME. Throws std::invalid_argument for a unit the text does not name
/// (the parameters are the file's own).
std::string identified_vessel_text(const VesselIdReport& report);

nlohmann::json to_json(const VesselIdReport& report);
std::string to_text(const VesselIdReport& report);

/// Writes the report folder: index.html (the parameter and NRMSE tables) and one SVG per test
/// (measured and re-simulated u, v, r).
void write_report(const VesselIdReport& report, const std::filesystem::path& dir);

/// The outputs of `identify vessel`: the vessel file `vessel_out` (empty: none), outputs.figures
/// the report folder, then the JSON.
Written write_outputs(const VesselIdReport& report, const std::filesystem::path& vessel_out,
                      const Outputs& outputs);

/// What `compare-trial` re-simulates.
struct CompareTrialRequest {
  LogSource source;
  std::filesystem::path vessel_file;  ///< empty: the built-in Gunnerus
  double step_s = 0.2;
  double sample_s = 1.0;
  double stretch_s = 300.0;
  unsigned jobs = 0;
};

struct CompareTrialReport {
  std::filesystem::path vessel_file;
  io::InputReport input;
  TestResponse test;
};

/// The logged test re-simulated with its logged feedback (its start velocity and current
/// fitted, the vessel as the file has it).
CompareTrialReport run_compare_trial(const CompareTrialRequest& request);
nlohmann::json to_json(const CompareTrialReport& report);
std::string to_text(const CompareTrialReport& report);
/// outputs.figures: the SVG of measured and re-simulated u, v, r and track; then the JSON.
Written write_outputs(const CompareTrialReport& report, const Outputs& outputs);

}  // namespace dynpos::analysis
