#pragma once
/// \file
/// Step-test identification on any CSV log (thesis 3.2): every step of the input (or of a
/// trigger, or the window given) found, and a FOPDT (3.7) or second-order model fitted to the
/// output after each.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/analysis/log_source.hpp"
#include "dynpos/analysis/outputs.hpp"
#include "dynpos/core/status.hpp"
#include "dynpos/ident/fit_status.hpp"
#include "dynpos/ident/step_detector.hpp"

namespace dynpos::analysis {

/// How a step's response is fitted.
enum class StepMethod {
  kLeastSquares,          ///< "lsq": FOPDT (3.7) by least squares with the dead time
  kSmith,                 ///< "smith": FOPDT by Smith's two-point method (3.8)-(3.9)
  kSmithSecondOrder,      ///< "smith2": Smith's second-order 20/60 %
  kRangaiahKrishnaswamy,  ///< "rk": Rangaiah-Krishnaswamy second-order 14/55/91 %
};

/// What is fitted instead of the role output.
enum class StepDerive {
  kNone,        ///< "": the role output
  kTotalSpeed,  ///< "total-speed": √(u² + v²) (3.19) from the roles u and v (sway tests)
};

/// The method's name in reports and options: "lsq", "smith", "smith2" or "rk".
std::string to_string(StepMethod method);
/// "" or "total-speed".
std::string to_string(StepDerive derive);

/// Every method and derived output by its name, for the front ends' option parsing.
const std::vector<std::pair<std::string, StepMethod>>& step_method_names();
const std::vector<std::pair<std::string, StepDerive>>& step_derive_names();
/// The method or derived output named `name` (any case); else option_error("method"/"derive").
StepMethod step_method_from_name(const std::string& name);
StepDerive step_derive_from_name(const std::string& name);

/// What to identify: the log's roles time, input (the command), output (the response) and
/// optionally trigger (e.g. power feedback, to time steps without a command); or u and v with
/// derive = kTotalSpeed.
struct StepRequest {
  LogSource source;
  StepMethod method = StepMethod::kLeastSquares;
  /// Window [s] (request keys "from", "to"; judged as "from/to" by LogSource::load): one step
  /// in the window; only the window is read, with its own step threshold.
  std::optional<double> from_s;
  std::optional<double> to_s;
  std::optional<double> step_at_s;  ///< step time [s], with or without a window
  StepDerive derive = StepDerive::kNone;
  /// Smallest input change counted as a step, in the input's SI unit; 0: adapted to the log
  /// (ident/step_detector.hpp: from its noise and its largest changes).
  double min_step = 0.0;
  /// Shortest time [s] the input holds a level to count as a step.
  double min_plateau_s = 3.0;
  /// Segment file (io/segments.hpp): only steps inside its named stretches are analysed; "" for
  /// the whole log.
  std::filesystem::path segments_file;

  /// Throws option_error naming the key of the first bad range (min_step, min_plateau, from,
  /// to, step_at).
  void validate() const;
};

/// How the step times were found.
enum class StepTimingSource {
  kCommand,  ///< from the input (the command)
  kTrigger,  ///< from a trigger signal that responds to the input
  kWindow,   ///< neither is logged: the window given
};

/// "command", "trigger" or "window".
std::string_view timing_name(StepTimingSource timing);

/// Extras of a first-order fit (methods lsq and smith).
struct FopdtFitDetails {
  std::optional<double> gain_sigma;             ///< 1σ of K; absent without K, or for Smith
  std::optional<double> time_constant_sigma_s;  ///< 1σ of T [s]
  std::optional<double> dead_time_sigma_s;      ///< 1σ of δ [s]
  std::optional<double> gain_from_levels;       ///< K = Δy/Δu from the mean levels, (3.4)
  std::optional<double> rms_residual;           ///< [output unit]
};

/// Extras of a second-order fit (methods smith2 and rk).
struct SecondOrderFitDetails {
  std::optional<double> time_constant_1_s;  ///< T₁ [s]
  std::optional<double> time_constant_2_s;  ///< T₂ [s]
  std::optional<double> damping_ratio;      ///< ζ [-]
};

/// One step and the model fitted to it. Values are SI: y in the output's unit, K in output unit
/// per input unit.
struct StepFit {
  ident::Step step;                       ///< step time, window end and input levels
  std::optional<double> y_before;         ///< y₀
  std::optional<double> y_after;          ///< y₀ + K·Δu
  std::optional<double> gain;             ///< K
  std::optional<double> time_constant_s;  ///< T (T₁ of a second-order fit) [s]
  std::optional<double> dead_time_s;      ///< δ [s]
  std::optional<double> r_squared;
  core::Status status = core::Status::kFailed;
  std::string message;  ///< how the fit went, or why the step could not be fitted
  std::vector<ident::FitWarning> warnings;
  std::string segment;  ///< name of the segment the step is in; "" without a segment file
  std::optional<FopdtFitDetails> fopdt;               ///< set for lsq and smith
  std::optional<SecondOrderFitDetails> second_order;  ///< set for smith2 and rk
};

/// The steps of one log and their fits.
struct StepReport {
  std::filesystem::path log;
  io::InputReport input;  ///< the files read, their formats and skipped lines
  StepMethod method = StepMethod::kLeastSquares;
  std::string output_unit;                ///< SI unit of the output; "" is dimensionless
  std::optional<std::string> input_unit;  ///< SI unit of the input; absent without one
  StepTimingSource timing = StepTimingSource::kCommand;
  /// Smallest input change counted as a step [input unit]; absent when the steps were not
  /// detected (a step time given, or no input or trigger).
  std::optional<double> step_threshold;
  bool threshold_from_min_step = false;     ///< true: --min-step; false: adapted to the log
  std::optional<double> input_noise_sigma;  ///< σ̂ of the input (or trigger) [input unit]
  std::filesystem::path segments_file;      ///< "" without one
  std::vector<StepFit> steps;               ///< sorted by step time
  std::vector<std::string> notes;           ///< e.g. why a segment has no step
};

/// Validates, reads the log, finds the steps and fits each by FOPDT (3.7):
/// y = y₀ + K·Δu·(1 − e^{−(t−t₀−δ)/T}), or by the second-order model of the method.
/// A step that cannot be fitted (too short, no response, a degenerate fit, ...) is a row with
/// status kFailed and the reason, never an error. Throws option_error("col:output") without an
/// output, option_error("col:input") without an input, a trigger or a window to find the steps
/// in, and InputError naming the log (or the segment file) for a bad file or window (an
/// empty window, or one without a row of the log: "from/to", LogSource::load).
StepReport run_step(const StepRequest& request);

// The report's adapters: step_report.cpp.

/// The `identify step --json` document: {log, method, output_unit, input_unit, timing,
/// step_threshold, step_threshold_source ("auto" or "min_step"), input_noise_sigma, segments?,
/// notes, steps: [{t_step, t_end, segment?, u_before, u_after, y_before, y_after, K, T, delay,
/// r_squared, status, message?, warnings, ...}]} with sigma, K_levels and rms_residual (first
/// order) or T1, T2 and damping_ratio (second order).
nlohmann::json to_json(const StepReport& report);

/// A header line and one table row per step, as `identify step` prints them.
std::string to_text(const StepReport& report);

/// Writes the JSON where outputs.json says (the step analysis draws no figure).
Written write_outputs(const StepReport& report, const Outputs& outputs);

}  // namespace dynpos::analysis
