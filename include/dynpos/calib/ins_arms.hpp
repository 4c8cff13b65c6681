#pragma once
/// \file
/// GNSS antenna lever arms from what a vessel logs: GNSS fixes, one MRU (attitude, angular
/// rates, accelerations) and the gyro heading. No velocity reference is needed.
///
/// Model (GNSS/INS fusion with lever-arm states, solved as one batch over the maneuver). The
/// MRU point P (the INS) moves as P̈ = A(t) = R(Θ(t))·(a(t) − b) [+ g_n for specific force],
/// with a the logged acceleration at P in BODY, b a constant accelerometer bias and Θ the
/// attitude after smoothing against the gyros (attitude_smoother.hpp). Antenna k sits at
/// BODY arm d_k from P, so its fix stamped t is
///   z_k(t) = P(t − δ) + R(Θ(t − δ))·d_k + e_k,                        (cf. (4.2))
/// δ the GNSS time offset. The states are P and Ṗ at knots every fix interval, joined by the
/// integrated accelerations (exact for accelerations linear between samples) with the
/// accelerometer's white noise as process noise, plus d_k, b and δ: a sparse nonlinear least
/// squares (Ceres Solver). The noise levels are found from the data: the accelerometer's from
/// second differences, then each antenna's horizontal and vertical σ and the process noise by
/// variance component estimation (each group's residual sum over its redundancy, the
/// redundancy by a seeded stochastic trace of the hat matrix). The 1σ of each arm is from the
/// covariance (JᵀJ)⁻¹ at the solution, with those levels.
///
/// Observability: horizontal arm components are seen through the heading changing, vertical
/// ones through roll and pitch; what the maneuver does not turn shows as a large σ, and the
/// verdict per axis says so.

#include <Eigen/Core>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "dynpos/calib/arm_estimate.hpp"
#include "dynpos/calib/excitation.hpp"
#include "dynpos/calib/gnss_lever_arm.hpp"
#include "dynpos/calib/imu_series.hpp"
#include "dynpos/core/status.hpp"

namespace dynpos::calib {

struct InsArmOptions {
  /// The MRU's own arm from the vessel's control origin CO [m, BODY]; given: every arm is
  /// reported from CO ("co"), else from the MRU (its name).
  std::optional<Eigen::Vector3d> imu_arm_b_m;
  /// GNSS time offset δ [s]: the start value when estimated, else the value used.
  double time_offset_s = 0.0;
  bool estimate_time_offset = true;
  double max_time_offset_s = 1.0;  ///< bound on |δ| when estimated [s], > 0
  /// Smoothing window of the attitude [s], > 0: at least this, and at least 10 samples of the
  /// heading (10 s for a 1 Hz HDT), so that the gyros carry the yaw between its samples.
  double attitude_window_s = 1.0;
  /// Least spacing of the knots [s], > 0 (they are at least one fix interval apart). A fix
  /// between knots is reached by the integrated accelerations from the nearest one; their
  /// noise over half a second (0.2 mm at 0.01 m/s² and 100 Hz) is left out of its weight.
  double knot_spacing_s = 1.0;
  /// Starting GNSS noise [m] per horizontal and vertical axis; refined from the data.
  double gnss_horizontal_std_m = 0.01;
  double gnss_vertical_std_m = 0.02;
  /// Weak prior on each arm component, N(0, σ²) [m]: a maneuver that does not show an axis
  /// leaves it at a σ near this instead of a singular problem. ≫ any real arm.
  double arm_prior_std_m = 100.0;
  /// Prior on each accelerometer bias component, N(0, σ²) [m/s²]; infinity: free.
  double accel_bias_prior_std_mps2 = std::numeric_limits<double>::infinity();
  int variance_iterations = 1;  ///< variance-component passes, ≥ 0
  int trace_probes = 8;         ///< random probes per redundancy trace, ≥ 1
  VerdictThresholds verdict;    ///< σ thresholds of the per-axis verdict
  void validate() const;        ///< throws std::invalid_argument naming the bad field
};

/// The noise levels the estimate ends with.
struct InsNoise {
  Eigen::Vector3d accel_std_mps2 = Eigen::Vector3d::Zero();  ///< per sample, second differences
  double process_scale = 1.0;  ///< factor on that noise found by the variance components
  std::vector<double> gnss_horizontal_std_m, gnss_vertical_std_m;  ///< per antenna [m]
};

struct InsArmResult {
  core::Status status = core::Status::kFailed;  ///< kOk, or kFailed with the reason in message
  std::string message;
  std::string reference;          ///< "co" or the MRU's name
  std::vector<ArmEstimate> arms;  ///< one per antenna, from the reference point
  double time_offset_s = 0.0;
  double time_offset_std_s = std::numeric_limits<double>::quiet_NaN();  ///< NaN if not estimated
  bool time_offset_estimated = false;
  Eigen::Vector3d accel_bias_b_mps2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_bias_std_mps2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d euler_rate_bias_rps = Eigen::Vector3d::Zero();  ///< of the gyros (smoother)
  InsNoise noise;
  std::vector<Eigen::Vector3d> residual_rms_n_m;  ///< per antenna, NED [m]
  /// Each antenna's fix residuals z − ẑ over time (GNSS stamps) [s], NED [m], for plots.
  std::vector<std::vector<double>> residual_t_s;
  std::vector<std::vector<Eigen::Vector3d>> residual_n_m;
  std::size_t knots = 0, fixes = 0;
  int solver_iterations = 0;
  std::vector<std::string> advice;  ///< for axes not well determined
  std::vector<std::string> notes;
};

/// Estimates every antenna's arm. Data that give no estimate (too few fixes inside the MRU's
/// time, a solver failure) come back as status kFailed with a message; invalid options throw
/// std::invalid_argument.
InsArmResult estimate_ins_arms(const ImuSeries& imu, const std::vector<GnssSeries>& antennas,
                               const InsArmOptions& options = {});

}  // namespace dynpos::calib
