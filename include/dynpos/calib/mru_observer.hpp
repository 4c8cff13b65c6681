#pragma once
/// \file
/// MRU lever arms (thesis 4.3): the kinematic acceleration a_i measured by MRU i at lever arm
/// l_i relates to the acceleration of the control origin by (4.65),
///   A_i = A₀ + R(Θ)(S(ω)² + S(ω̇))·l_i,
/// or in BODY, a_i − a₀ = M(t)·l_i with M = S(ω)² + S(ω̇). Two estimators share one signal
/// preparation: the Luenberger observer (4.71)–(4.76), (4.80) on the NED state
/// x = [A₀; l_1; …; l_m], and batch least squares on the BODY equation, which is linear in l_i.
///
/// Signal preparation. Every channel is interpolated onto the time grid of the first MRU. ω̇ and
/// ν̇ come from a Savitzky–Golay smoother F (quadratic, window `smooth_window_s`) followed by a
/// central difference, and every other term of the equation (a_i, S(ω)², ω × ν) is smoothed by
/// the same F. The filtered equation F(a_i) − F(a₀) = F(M)·l_i then holds exactly for noise-free
/// data (F is linear and commutes with d/dt up to the central difference's O((ω·dt)²) error), so
/// the filter removes noise without biasing the arms. a₀ = ν̇ + ω × ν is (4.69) in BODY; with
/// A₀ = R·a₀ that is (4.95) read the other way.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dynpos/calib/arm_estimate.hpp"
#include "dynpos/core/log.hpp"
#include "dynpos/core/status.hpp"

namespace dynpos::calib {

/// What the MRU acceleration channels hold.
enum class MruAccel {
  kKinematic,      ///< a = R(Θ)ᵀA, gravity removed (the default)
  kSpecificForce,  ///< f = R(Θ)ᵀ(A − g_n): g rotated into BODY is added back
};
std::string_view to_string(MruAccel a);                          // "kinematic" | "specific-force"
std::optional<MruAccel> parse_mru_accel(std::string_view text);  // nullopt if unknown

/// Standard gravity [m/s²], the one the sensor models use (sensors::kGravity_mps2).
inline constexpr double kMruGravity_mps2 = 9.80665;

/// One MRU's acceleration channels: roles NAME.ax, NAME.ay, NAME.az in `log`.
struct MruSource {
  std::string name;                ///< role prefix, "mru1"
  const core::Log* log = nullptr;  ///< the log holding its channels (may be the motion log)
  std::string file;                ///< for error messages
};

struct MruSignalOptions {
  MruAccel accel = MruAccel::kKinematic;
  double smooth_window_s = 1.0;  ///< Savitzky–Golay window of F [s], > 0
  double gravity_mps2 = kMruGravity_mps2;
};

/// The prepared, filtered signals on one uniform grid.
struct MruSignals {
  std::vector<double> t_s;
  std::vector<Eigen::Matrix3d> R_nb;                   ///< R(Θ) (2.4)
  std::vector<Eigen::Vector3d> omega_b_rps;            ///< F(ω)
  std::vector<Eigen::Vector3d> omega_dot_b;            ///< ω̇ [rad/s²]
  std::vector<Eigen::Vector3d> omega_ddot_b;           ///< ω̈ [rad/s³] (for G(t), (4.77))
  std::vector<Eigen::Matrix3d> M_b;                    ///< F(S(ω)²) + S(ω̇) [1/s²]
  std::vector<Eigen::Vector3d> a0_b_mps2;              ///< F(ν̇ + ω × ν), (4.69) in BODY
  std::vector<std::string> names;                      ///< one per MRU
  std::vector<std::vector<Eigen::Vector3d>> a_b_mps2;  ///< F(a_i), kinematic, per MRU
  std::vector<std::string> notes;                      ///< assumptions made on the way
  std::size_t size() const noexcept { return t_s.size(); }
};

/// Builds the signals from a motion log (roles time, roll, pitch, heading, p, q, r, u, v and
/// optionally w, any rates, blank cells allowed) and the MRU channels. Throws core::InputError
/// for a missing role, a non-finite value where one is needed (fewer than two valid samples), an
/// MRU time axis that is not increasing, or a log too short for the smoothing window.
MruSignals mru_signals_from_logs(const core::Log& motion, const std::vector<MruSource>& mrus,
                                 const MruSignalOptions& options = {});

/// Builds the signals from samples already on one uniform grid (SI; a_i in the convention of
/// options.accel). Used by mru_signals_from_logs and by tests.
struct MruRawSamples {
  std::vector<double> t_s;
  std::vector<Eigen::Vector3d> theta_rad, omega_b_rps, v_b_mps;
  std::vector<std::string> names;
  std::vector<std::vector<Eigen::Vector3d>> a_b_mps2;
};
MruSignals mru_signals_from_samples(const MruRawSamples& raw, const MruSignalOptions& options = {});

enum class MruMethod { kObserver, kLsq };
std::string_view to_string(MruMethod m);                           // "observer" | "lsq"
std::optional<MruMethod> parse_mru_method(std::string_view text);  // nullopt if unknown

struct MruEstimateOptions {
  MruMethod method = MruMethod::kLsq;
  /// Observer gains W = diag(W₁, W₂, …, W₂) of (4.80). W₁ = w1·I [1/s]. W₂ is scaled by the
  /// excitation so that the arm error decays with the time constant tau_s. A₀ is propagated
  /// exactly by its input (4.70), so a small W₁ (trusting it) converges the arms fastest.
  ///
  /// W₂ = I / (tau_s · mean eigenvalue of MᵀM) (the thesis tunes W₂ by trial, (4.98)).
  double w1_per_s = 0.01;
  double tau_s = 5.0;
  /// Initial arm estimate of the observer [m] (the thesis starts at 30 m, 4.4.2).
  Eigen::Vector3d l0_b_m = Eigen::Vector3d::Zero();
  /// Fraction of the log, from its start, the observer needs to converge; the statistics
  /// are over the rest (the "converged interval" of the thesis tables). In [0, 1).
  double converge_fraction = 0.5;
  /// Samples dropped at each end (filter edge effects) [s].
  double edge_s = 2.0;
  void validate() const;  ///< throws std::invalid_argument naming the bad field
};

/// The excitation of the maneuver (Proposition 3): G(t) = S³ + ṠS + 2SṠ + S̈ (4.77).
struct MruExcitation {
  double rank3_fraction = 0.0;      ///< share of samples where G has numerical rank 3
  double g_min_sv_median = 0.0;     ///< median smallest singular value of G [1/s³]
  double g_condition_median = 0.0;  ///< median σ_max/σ_min of G
  double info_min_eig = 0.0;        ///< λ_min of mean MᵀM [1/s⁴], the regression's excitation
  double info_condition = 0.0;      ///< λ_max/λ_min of mean MᵀM
  std::vector<double> t_s;          ///< decimated to ≤ 10 Hz for plots
  std::vector<double> g_min_sv;     ///< smallest singular value of G at t_s
  std::vector<int> g_rank;
  std::vector<std::string> advice;  ///< union over arms
};

struct MruEstimateResult {
  core::Status status = core::Status::kFailed;  ///< kOk, or kFailed with the reason in message
  std::string message;
  MruMethod method = MruMethod::kLsq;
  std::vector<ArmEstimate> arms;  ///< std: residual-based (lsq) or over the interval (observer)
  double interval_from_s = 0.0, interval_to_s = 0.0;  ///< the converged interval
  MruExcitation excitation;
  /// Estimates over time for plots (≤ 10 Hz): the observer's state, or the recursive
  /// least-squares solution on the data up to t.
  std::vector<double> history_t_s;
  std::vector<std::vector<Eigen::Vector3d>> history_l_b_m;  ///< [arm][sample]
};

/// Estimates every MRU's arm from the signals. Too few samples come back as status kFailed with
/// a message; invalid options throw std::invalid_argument.
MruEstimateResult estimate_mru_arms(const MruSignals& signals,
                                    const MruEstimateOptions& options = {});

/// G(t) of (4.77) from ω, ω̇, ω̈.
Eigen::Matrix3d mru_g_matrix(const Eigen::Vector3d& omega, const Eigen::Vector3d& omega_dot,
                             const Eigen::Vector3d& omega_ddot);

}  // namespace dynpos::calib
