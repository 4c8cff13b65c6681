#pragma once
/// \file
/// `leverarm gnss`: GNSS antenna lever arms from vessel motion (thesis 4.2, case studies 4.4.1)
/// as one request → report, with its JSON, text, figures and demo section.

#include <Eigen/Core>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/analysis/log_source.hpp"
#include "dynpos/calib/gnss_lever_arm.hpp"
#include "dynpos/calib/ins_arms.hpp"
#include "dynpos/calib/mru_observer.hpp"
#include "dynpos/report/table.hpp"

namespace dynpos::analysis {

/// The options of `leverarm gnss`; each field's name is its request key. Vectors are given as
/// text "X,Y,Z", antennas by their role prefix gnssK, per-antenna inputs as "gnssK=VALUE", as on
/// the command line.
struct LeverarmGnssRequest {
  /// Motion and any gnssK.* fixes: for ins an MRU (mruK.roll, .pitch, .p, .q, .r, .ax, .ay,
  /// .az) and heading; for the thesis' methods roll, pitch, heading, p, q, r, u, v, w.
  LogSource source;
  /// auto, ins, luenberger, adaptive or lsq. auto: ins when the log has an MRU with
  /// accelerations and the heading (no velocity needed), else lsq.
  std::string method = "auto";
  std::string imu;      ///< ins: the MRU of the fusion, mruK; empty: the first with every role
  std::string imu_arm;  ///< ins: X,Y,Z of that MRU from CO [m]; given: arms from CO
  std::string accel = "kinematic";    ///< ins: the MRUs' accelerations, kinematic|specific-force
  std::vector<std::string> antennas;  ///< gnssK to estimate; empty: every one found
  std::vector<std::string> gnss_log;  ///< gnssK=FILE.csv: fixes in a CSV of their own
  std::vector<std::string> nmea;      ///< gnssK=FILE.nmea: fixes from NMEA 0183 (GGA)
  /// UTC of the log's t = 0, HH:MM:SS[.sss] or YYYY-MM-DDTHH:MM:SS[.sss]Z; empty: the NMEA
  /// times must overlap the log's.
  std::string utc_at_zero;
  std::vector<std::string> init;  ///< gnssK=X,Y,Z: an observer's initial arm [m]
  std::string w1;                 ///< Luenberger W₁ on P₀ [1/s], > 0; empty: the default
  std::string w2;                 ///< Luenberger W₂ on each arm [1/s], > 0; empty: the default
  std::string gamma;              ///< adaptive Γ, > 0; empty: from adaptive_rate
  std::string L;                  ///< adaptive L [1/s], > 0; empty: the default
  std::string init_p0;            ///< N,E,D: Luenberger's initial P₀ [m]; empty: from the fixes
  double adaptive_rate = 0.1;     ///< [1/s], > 0: sets Γ when gamma is empty
  int lag = 10;                   ///< lsq: epochs between differenced fixes, ≥ 1
  std::optional<double> time_offset;  ///< GNSS time offset [s], finite
  bool estimate_time_offset = false;  ///< excludes time_offset
  double max_time_offset = 1.0;       ///< search range of the offset [s], ≥ 0.05
  double converged_from = 0.5;        ///< observers: averaged from this fraction on, [0, 1)
  double pe_window = 60.0;            ///< PE window T of (4.51) [s], > 0
  double gnss_std = 0.01;             ///< GNSS noise per axis for the predicted σ [m], > 0

  /// Throws analysis::option_error naming the first bad option (with the file for a missing
  /// gnss_log or nmea file).
  void validate() const;
};

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
  std::filesystem::path log;             ///< the motion log as given
  io::InputReport input;                 ///< the files read, their formats and skipped lines
  double pe_window_s = 60.0;             ///< the PE window used [s]
  double gnss_rate_hz = 1.0;             ///< from the median fix spacing of the first antenna
  std::string method;                    ///< the method run (auto resolved)
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

}  // namespace dynpos::analysis
