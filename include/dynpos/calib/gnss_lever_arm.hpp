#pragma once
/// \file
/// GNSS antenna lever arms from vessel motion (thesis 4.2): m ≥ 1 antennas at BODY arms lₖ from
/// the point P₀ whose velocity ν is logged, P_GNSSk(t) = P₀(t) + R(Θ(t))·lₖ (4.2), with
/// Ṗ₀ = R(t)·ν(t) (4.6). Three estimators:
///  - kLuenberger: the observer (4.26) on the LTV system (4.8)–(4.12), x = [P₀; l₁ … l_m],
///    gain W = diag(W₁, W₂, …, W₂) as in (4.85);
///  - kAdaptive: the adaptive observer (4.42) with the update law (4.48), gains L and Γ;
///  - kLsq: batch least squares over the whole maneuver. P₀ is eliminated by differencing each
///    antenna's fixes `lag_epochs` apart against the integrated velocity,
///    ΔPₖ − ∫R·ν dτ = ΔR·lₖ (from (4.2) and (4.6)), so no velocity error accumulates beyond one
///    lag; with m ≥ 2 the antenna differences Pₖ − P₁ = R·(lₖ − l₁) are added. Rows are weighted
///    by the residual variance of their group (difference type × NED axis). A fix enters
///    several rows, so the 1σ of each arm component propagates the fix noise (half the time
///    differences' residual variance per axis) through the solution, N⁻¹·(Σ σ²·h·hᵀ)·N⁻¹,
///    not σ²·(AᵀWA)⁻¹ (which treats the rows as independent).
/// GNSS and motion may run at different rates: the motion (attitude, rates, velocity) is
/// interpolated to each fix epoch and its velocity integrated between epochs. A time offset δ
/// of the GNSS stamps (a fix stamped t holds the antenna position at t − δ) is applied, or
/// estimated by minimising the least-squares residual over δ.

#include <Eigen/Core>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "dynpos/calib/arm_estimate.hpp"
#include "dynpos/calib/excitation.hpp"
#include "dynpos/calib/motion_series.hpp"
#include "dynpos/core/log.hpp"
#include "dynpos/core/status.hpp"

namespace dynpos::calib {

/// The fixes of one antenna in the local NED frame.
struct GnssSeries {
  std::string name;                    ///< role prefix, e.g. "gnss1"
  std::vector<double> t_s;             ///< strictly increasing [s], on the motion's clock
  std::vector<Eigen::Vector3d> p_n_m;  ///< NED position [m]; all finite
};

enum class GnssArmMethod { kLuenberger, kAdaptive, kLsq };
std::string_view gnss_arm_method_name(GnssArmMethod m);  // "luenberger", "adaptive", "lsq"

/// Options of estimate_gnss_arms().
struct GnssArmOptions {
  GnssArmMethod method = GnssArmMethod::kLsq;
  /// Initial arm guesses [m] for the observers, one per antenna; empty: all zero.
  std::vector<Eigen::Vector3d> initial_arms_b_m;
  /// Luenberger: initial P̂₀ in the fixes' NED frame [m] when known (thesis case study 1 starts
  /// from the true P₀). Unset: the mean over the first epoch's antennas of Pₖ − R·l̂ₖ(0).
  std::optional<Eigen::Vector3d> initial_p0_n_m;
  /// Luenberger (4.26): W₁ on P₀ and W₂ on each arm (diagonals) [1/s]. Each fix is applied as
  /// the continuous correction held over the fix interval. P₀ is dead-reckoned from the
  /// velocity (4.6), so it needs little correction (W₁ ≪ W₂): the fix residual then goes to the
  /// arms, whose error decays at about W₂·|ỹ| while the P₀ error left over is W₁/W₂ of the arm
  /// error per unit time. W₁/W₂ = 1/30 000 reached 0.2 mm on the noise-free turning circle from
  /// a known P₀ (the thesis' case study 1); a larger W₁ follows a drifting velocity better.
  Eigen::Vector3d luenberger_w_p0 = Eigen::Vector3d::Constant(0.001);
  Eigen::Vector3d luenberger_w_arm = Eigen::Vector3d::Constant(30.0);
  /// Adaptive (4.42), (4.48): L on the antenna positions [1/s] and Γ on the arms (diagonals).
  /// The arm error decays at about Γ·E|ω|²/L, so when Γ is unset it is chosen from the data
  /// as Γ = adaptive_rate_per_s·L/E|ω|² (E|ω|² the mean squared angular rate of the motion):
  /// the same convergence rate on a calm or a rough maneuver.
  Eigen::Vector3d adaptive_l = Eigen::Vector3d::Constant(1.0);
  std::optional<Eigen::Vector3d> adaptive_gamma;
  double adaptive_rate_per_s = 0.1;
  /// Least squares: fixes differenced this many epochs apart, ≥ 1. The arm shows in a
  /// difference only through the rotation ΔR over the lag: at a turning rate of 0.03 rad/s
  /// and 1 Hz fixes, one epoch turns a 1 m arm by 3 cm, the order of the RTK noise of the
  /// difference. Ten epochs give ten times the signal while the integrated velocity of a good
  /// motion reference stays accurate (turning circle, 400 s: arm 1σ in x and y 3–5 mm at lag 1,
  /// 0.6–0.8 mm at lag 10; z, seen through roll and pitch, 9 mm at both). A poor velocity (a
  /// 1 Hz speed log) argues for a shorter lag.
  int lag_epochs = 10;
  /// GNSS time offset δ [s] applied to every fix (stamp t ↔ motion time t − δ).
  double time_offset_s = 0.0;
  /// Estimate δ in [−max, max] by the least-squares residual (then `time_offset_s` is ignored).
  bool estimate_time_offset = false;
  double max_time_offset_s = 1.0;    ///< search range [s], > 0
  double time_offset_step_s = 0.01;  ///< grid step of the search [s], refined by a parabola
  /// Start of the interval over which an observer's estimate is averaged (the thesis' tables
  /// 4.2–4.5) as a fraction of the log, [0, 1).
  double converged_from_fraction = 0.5;
  ExcitationOptions excitation;
  void validate() const;  ///< throws std::invalid_argument naming the bad field
};

/// The estimate and what came with it.
struct GnssArmResult {
  core::Status status = core::Status::kFailed;  ///< kOk, or kFailed with the reason in message
  std::string message;
  GnssArmMethod method = GnssArmMethod::kLsq;
  /// One per antenna. LSQ: final solution and its own 1σ. Observers: mean and standard
  /// deviation over the converged interval.
  std::vector<ArmEstimate> arms;
  /// Estimate history at the fix epochs (motion time): arms (LSQ: growing-window solution),
  /// P₀ in NED.
  std::vector<double> t_s;
  std::vector<std::vector<Eigen::Vector3d>> arm_history_b_m;  ///< [antenna][epoch]
  std::vector<Eigen::Vector3d> p0_n_m;
  std::vector<Eigen::Vector3d> p0_measured_n_m;  ///< mean over antennas of Pₖ − R·l̂ₖ (final)
  double converged_from_s = 0.0;                 ///< the averaging interval [from, to] [s]
  double converged_to_s = 0.0;
  std::vector<Eigen::Vector3d> interval_mean_b_m;  ///< per antenna, over that interval
  std::vector<Eigen::Vector3d> interval_std_b_m;
  Eigen::Vector3d adaptive_gamma = Eigen::Vector3d::Constant(std::nan(""));  ///< Γ used (adaptive)
  double time_offset_s = 0.0;                                                ///< δ used
  bool time_offset_estimated = false;
  double time_offset_std_s = 0.0;  ///< from the residual's curvature; NaN if not estimated
  std::vector<double> offset_scan_s, offset_scan_cost;  ///< the δ search (empty if none)
  Eigen::Vector3d residual_rms_n_m =
      Eigen::Vector3d::Zero();  ///< of P_k − P̂₀ − R·l̂ₖ; observers: over the interval
  std::size_t epochs_used = 0;
  ExcitationDiagnostics excitation;
  std::vector<std::string> notes;
};

/// Estimates every antenna's arm. Problems of the data (no fixes inside the motion's time,
/// too few epochs) come back as status kFailed with a message; invalid options throw
/// std::invalid_argument. The motion needs attitude, angular rates and velocity.
GnssArmResult estimate_gnss_arms(const MotionSeries& motion,
                                 const std::vector<GnssSeries>& antennas,
                                 const GnssArmOptions& options = {});

/// The motion of a mixed-rate log on the time axis of its fastest attitude channel (rows
/// where `roll` is present): every other motion channel is interpolated linearly from its own
/// samples (heading unwrapped), rows outside any channel's samples are dropped; w is 0 when
/// not logged (noted). Throws core::InputError naming a missing role or too short a log.
MotionFromLog motion_from_mixed_log(const core::Log& log);

/// Where one antenna's fixes are: a log and the antenna's role prefix in it.
struct GnssSource {
  const core::Log* log = nullptr;
  std::string prefix;  ///< e.g. "gnss1"
  std::string file;    ///< for error messages; may be empty
};

/// The antennas' fixes in one local NED frame: roles PREFIX.north/east/down when every source
/// has them, else PREFIX.lat/lon/height [rad, rad, m] converted by core::LocalNedFrame
/// (GeographicLib) with its origin at the first fix of the first antenna (shared by all).
/// Rows with a component missing are skipped. Throws core::InputError if an antenna has
/// neither set, fewer than 3 fixes, or an infinite value.
std::vector<GnssSeries> gnss_from_logs(const std::vector<GnssSource>& sources);

/// The role prefixes gnssK present in a log (north or lat channels), in K order.
std::vector<std::string> gnss_prefixes(const core::Log& log);

}  // namespace dynpos::calib
