#pragma once
/// \file
/// `leverarm gnss`: GNSS antenna lever arms from vessel motion (thesis 4.2, case studies 4.4.1)
/// as one request → report, with its JSON, text, figures and demo section.

#include <Eigen/Core>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/analysis/log_source.hpp"
#include "dynpos/analysis/outputs.hpp"
#include "dynpos/calib/gnss_lever_arm.hpp"
#include "dynpos/calib/ins_arms.hpp"
#include "dynpos/calib/mru_observer.hpp"
#include "dynpos/report/table.hpp"

namespace dynpos::analysis {

/// The method of `leverarm gnss`: auto (ins when the log has an MRU with accelerations and the
/// heading, else lsq), the logger-only GNSS/INS fusion, or one of the thesis' estimators.
enum class LeverarmGnssMethod { kAuto, kIns, kLuenberger, kAdaptive, kLsq };

/// Every method, in the order the help lists them.
inline constexpr LeverarmGnssMethod kLeverarmGnssMethods[] = {
    LeverarmGnssMethod::kAuto, LeverarmGnssMethod::kIns, LeverarmGnssMethod::kLuenberger,
    LeverarmGnssMethod::kAdaptive, LeverarmGnssMethod::kLsq};

/// "auto", "ins", "luenberger", "adaptive" or "lsq".
std::string_view to_string(LeverarmGnssMethod m);

/// The method of that name, in any case; option_error("method") for another name.
LeverarmGnssMethod gnss_method_from_name(const std::string& name);

/// The options of `leverarm gnss`; each field's name is its request key. Antennas are named by
/// their role prefix gnssK; the thesis' gains left unset take calib::GnssArmOptions' defaults.
struct LeverarmGnssRequest {
  /// Motion and any gnssK.* fixes: for ins an MRU (mruK.roll, .pitch, .p, .q, .r, .ax, .ay,
  /// .az) and heading; for the thesis' methods roll, pitch, heading, p, q, r, u, v, w.
  LogSource source;
  LeverarmGnssMethod method = LeverarmGnssMethod::kAuto;
  std::string imu;  ///< ins: the MRU of the fusion, mruK; empty: the first with every role
  std::optional<Eigen::Vector3d> imu_arm;  ///< ins: that MRU from CO [m]; given: arms from CO
  calib::MruAccel accel = calib::MruAccel::kKinematic;  ///< ins: the MRUs' accelerations
  std::vector<std::string> antennas;  ///< gnssK to estimate; empty: every one found
  /// gnssK → FILE.csv: an antenna's fixes in a CSV of their own.
  std::map<std::string, std::filesystem::path> gnss_log;
  /// gnssK → FILE.nmea: an antenna's fixes from NMEA 0183 (GGA).
  std::map<std::string, std::filesystem::path> nmea;
  /// UTC of the log's t = 0 as seconds of the day [0, 86400) (parse_utc_at_zero reads
  /// HH:MM:SS[.sss] or YYYY-MM-DDTHH:MM:SS[.sss]Z; the date is not used); unset: the NMEA
  /// times must overlap the log's.
  std::optional<double> utc_at_zero;
  std::map<std::string, Eigen::Vector3d> init;  ///< gnssK → an observer's initial arm [m]
  std::optional<Eigen::Vector3d> w1;            ///< Luenberger W₁ on P₀ [1/s], > 0
  std::optional<Eigen::Vector3d> w2;            ///< Luenberger W₂ on each arm [1/s], > 0
  std::optional<Eigen::Vector3d> gamma;         ///< adaptive Γ, > 0; unset: from adaptive_rate
  std::optional<Eigen::Vector3d> L;             ///< adaptive L [1/s], > 0
  std::optional<Eigen::Vector3d> init_p0;  ///< N,E,D: Luenberger's initial P₀ [m]; unset: fixes
  double adaptive_rate = 0.1;              ///< [1/s], > 0: sets Γ when gamma is unset
  int lag = 10;                            ///< lsq: epochs between differenced fixes, ≥ 1
  std::optional<double> time_offset;       ///< GNSS time offset [s], finite
  bool estimate_time_offset = false;       ///< excludes time_offset
  double max_time_offset = 1.0;            ///< search range of the offset [s], ≥ 0.05
  double converged_from = 0.5;             ///< observers: averaged from this fraction on, [0, 1)
  double pe_window = 60.0;                 ///< PE window T of (4.51) [s], > 0
  double gnss_std = 0.01;                  ///< GNSS noise per axis for the predicted σ [m], > 0

  /// Throws analysis::option_error naming the first bad option (with the file for a missing
  /// gnss_log or nmea file).
  void validate() const;
};

/// The text of utc_at_zero as seconds of the UTC day; option_error("utc_at_zero") when it is
/// not a UTC time.
double parse_utc_at_zero(const std::string& text);

/// The logger-only estimate (method ins): the antennas by GNSS/INS fusion, further MRUs from
/// the IMU's accelerations (calib/imu_mru_arms.hpp); every arm from the same reference.
struct LeverarmInsResult {
  std::string imu;                     ///< the MRU of the fusion
  calib::InsArmResult gnss;            ///< antennas, time offset, biases, noise
  calib::MruEstimateResult mrus;       ///< further MRUs (no arms when there are none)
  std::vector<std::string> mru_names;  ///< of mrus.arms
};

/// The estimate and the resolved inputs its outputs need.
struct LeverarmGnssReport {
  std::filesystem::path log;  ///< the motion log as given
  io::InputReport input;      ///< the files read, their formats and skipped lines
  double pe_window_s = 60.0;  ///< the PE window used [s]
  double gnss_rate_hz = 1.0;  ///< from the median fix spacing of the first antenna
  LeverarmGnssMethod method = LeverarmGnssMethod::kLsq;  ///< the method run (auto resolved)
  calib::GnssArmResult result;           ///< the thesis' methods: status kOk (failures throw)
  std::optional<LeverarmInsResult> ins;  ///< method ins
  std::vector<std::string> input_notes;  ///< about the inputs: motion, NMEA sentences
};

/// Validates, reads the motion and the fixes (NMEA placed on the log's clock by utc_at_zero, or
/// as UTC seconds of day when they overlap the log's times), resolves the GNSS rate from the fix
/// spacing and estimates the arms. core::InputError (naming the file) when the inputs do not
/// give an estimate.
LeverarmGnssReport run_leverarm_gnss(const LeverarmGnssRequest& request);

/// The `--json` document.
nlohmann::json to_json(const LeverarmGnssReport& report);

/// Mean and std of each coordinate over the converged interval, thesis tables 4.2–4.5.
report::Table arm_table(const LeverarmGnssReport& report);

/// What `leverarm gnss` prints: the table, time offset, residual, excitation, verdicts, notes.
std::string to_text(const LeverarmGnssReport& report);

/// Figures 4.2–4.9 into `dir` (created): arm-gnssK.svg per antenna (with the true arms
/// [m, BODY] where given), p0-ne.svg and excitation.svg. Returns the paths written.
std::vector<std::filesystem::path> write_figures(
    const LeverarmGnssReport& report, const std::filesystem::path& dir,
    const std::map<std::string, Eigen::Vector3d>& true_arms_b_m = {});

/// The figures into the folder outputs.figures (write_figures), then the JSON.
Written write_outputs(const LeverarmGnssReport& report, const Outputs& outputs);

}  // namespace dynpos::analysis
