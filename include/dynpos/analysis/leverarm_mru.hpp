#pragma once
/// \file
/// `leverarm mru`: MRU lever arms from MRU accelerations and vessel motion (thesis 4.3, case
/// study 4.4.2) as one request → report, with its JSON, text, figures and demo section
/// (leverarm_mru.cpp, leverarm_mru_report.cpp, leverarm_mru_demo.cpp).

#include <Eigen/Core>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/analysis/log_source.hpp"
#include "dynpos/analysis/outputs.hpp"
#include "dynpos/calib/mru_observer.hpp"
#include "dynpos/report/table.hpp"

namespace dynpos::analysis {

/// The options of `leverarm mru`; each field's name is its request key.
struct LeverarmMruRequest {
  /// Motion (time, roll, pitch, heading, p, q, r, u, v, w) and any mruK.ax/ay/az.
  LogSource source;
  /// NAME → FILE: an MRU's accelerations NAME.ax/ay/az in a file of their own, read with the
  /// source's map, columns and units.
  std::map<std::string, std::filesystem::path> mru_log;
  /// An MRU of the log ("mru1") the other MRUs' arms are measured from, with its roll, pitch,
  /// rates and accelerations and the heading: its accelerations stand in for a₀, so no velocity
  /// is read (the logger alone; calib/imu_mru_arms.hpp). Empty: arms from the control origin,
  /// a₀ from the velocity (4.69).
  std::string reference;
  calib::MruAccel accel = calib::MruAccel::kKinematic;  ///< what the acceleration channels hold
  calib::MruMethod method = calib::MruMethod::kLsq;     ///< batch least squares or observer
  double window_s = 1.0;  ///< Savitzky–Golay window of the smoother [s], > 0
  double tau_s = 5.0;     ///< observer convergence time constant [s], > 0
  double w1 = 0.01;       ///< observer gain W₁ on A₀ [1/s] (4.80)

  /// Throws analysis::option_error naming the first bad option.
  void validate() const;
};

/// The acceleration convention of that name ("kinematic", "specific-force"), in any case;
/// option_error("accel") for another name. `leverarm gnss` takes it too.
calib::MruAccel accel_from_name(const std::string& name);

/// The method of that name ("lsq", "observer"), in any case; option_error("method") otherwise.
calib::MruMethod mru_method_from_name(const std::string& name);

/// The estimate and the resolved inputs its outputs need.
struct LeverarmMruReport {
  std::filesystem::path log;        ///< the motion log as given
  std::string reference;            ///< the MRU the arms are from; empty: the control origin
  io::InputReport input;            ///< the files read, their formats and skipped lines
  calib::MruEstimateResult result;  ///< status kOk (failures throw)
  std::vector<std::string> notes;   ///< assumptions made preparing the signals
};

/// Validates, reads the motion and the MRU channels (every NAME of mru_log, then each mruK of
/// the log not given there), prepares the signals and estimates the arms. With a reference,
/// the arms of the log's other MRUs from it. core::InputError (naming
/// the file) when the inputs do not give an estimate.
LeverarmMruReport run_leverarm_mru(const LeverarmMruRequest& request);

/// The `--json` document.
nlohmann::json to_json(const LeverarmMruReport& report);

/// Thesis tables 4.2–4.5 style: mean and std per coordinate and the interval; with true arms
/// [m, BODY], the true arm and the error too.
report::Table arm_table(const LeverarmMruReport& report,
                        const std::map<std::string, Eigen::Vector3d>& true_arms_b_m = {});

/// What `leverarm mru` prints: the table, excitation, verdicts, advice and notes.
std::string to_text(const LeverarmMruReport& report);

/// Figure 4.13 into `dir` (created): mruK.svg per MRU (with the true arms where given) and
/// mru-excitation.svg. Returns the paths written.
std::vector<std::filesystem::path> write_figures(
    const LeverarmMruReport& report, const std::filesystem::path& dir,
    const std::map<std::string, Eigen::Vector3d>& true_arms_b_m = {});

/// The figures into the folder outputs.figures (write_figures), then the JSON.
Written write_outputs(const LeverarmMruReport& report, const Outputs& outputs);

}  // namespace dynpos::analysis
