#pragma once
/// \file
/// What the DP observers share: the low-speed vessel model (2.20)–(2.22) extended by a linear
/// wave model, the measurement and the estimate (Fossen & Strand 1999; Fossen 2011, ch. 11;
/// Sørensen 2012). The measured position and heading are the low-frequency (LF) motion plus
/// the wave-frequency (WF) motion:
///
///     ξ̇ = A_w ξ,   A_w = [0  I; −Ω²  −2ΛΩ],   η_w = C_w ξ = ξ₂        (wave model, per DOF)
///     η̇ = R(ψ) ν                                                       (2.20)
///     M ν̇ = −D ν + R(ψ)ᵀ b + τ                                          (2.21)
///     ḃ = −T⁻¹ b                                                       (2.22)
///     y = η + η_w
///
/// with Ω = diag(ω₀ᵢ) at each DOF's wave peak frequency (the peak of its wave-frequency motion's
/// spectrum: near 2π/T_p in surge and sway, higher in yaw, which follows the wave slope) and
/// Λ = diag(λ). b is the
/// environmental load in NED (everything the thrusters hold against: mean wind, current, wave
/// drift, slowly varying loads).
///
/// A measurement component that is missing (a GNSS dropout, a gyro fault) is NaN; an observer
/// coasts on its model in that component.

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace dynpos::control {

/// Which estimate the DP controller runs on: the true LF motion (ideal), the passive observer,
/// the extended Kalman filter, or the raw measurements (no wave filtering; for comparison).
enum class ObserverKind { kIdeal, kPassive, kEkf, kRaw };

/// "ideal", "passive", "ekf", "raw".
std::string_view observer_name(ObserverKind kind) noexcept;
/// The kind named `name`, or nullopt.
std::optional<ObserverKind> parse_observer(std::string_view name) noexcept;

/// The EKF's wave model has this many second-order components per DOF, the n-th at
/// kWaveComponentRatio[n] times the DOF's ω₀ with its share of the WF variance
/// (ObserverModel::wave_variance_share): a broad response spectrum — the yaw's, which weighs
/// short waves by k² — is followed where one component at its peak leaves much of it to the LF
/// estimate. Fossen's one component where only the first has a share.
inline constexpr int kWaveComponents = 3;
inline constexpr std::array<double, kWaveComponents> kWaveComponentRatio{1.0, 1.5, 2.0};
/// Shares per DOF (rows N, E, ψ) and component (columns).
using WaveShares = Eigen::Matrix<double, 3, kWaveComponents>;

/// The model both observers use.
struct ObserverModel {
  Eigen::Matrix3d M = Eigen::Matrix3d::Identity();  ///< inertia with added mass, as (5.33)
  Eigen::Matrix3d D = Eigen::Matrix3d::Identity();  ///< linear damping, as (5.33)
  /// T of (2.22) per axis [s]. Source: reasoned — a slowly varying load, far slower than the
  /// DP loop (Fossen 2011 uses 1000 s).
  Eigen::Vector3d bias_time_constant_s{1000.0, 1000.0, 1000.0};
  /// ω₀ per DOF (N, E, ψ) [rad/s], > 0.
  Eigen::Vector3d wave_peak_frequency_rad_s{0.8, 0.8, 1.2};
  /// λ, relative damping of the wave model [-]. Source: Fossen 2011 (0.05–0.1).
  double wave_damping_ratio = 0.1;
  /// The share of each DOF's WF variance its wave-model components take (the EKF's; the passive
  /// observer's wave model is the first component alone), ≥ 0, each row summing to 1. Default:
  /// one component.
  WaveShares wave_variance_share = (WaveShares() << 1, 0, 0, 1, 0, 0, 1, 0, 0).finished();
  /// Throws std::invalid_argument unless M is symmetric positive definite, D positive
  /// semidefinite on its diagonal, T > 0, every ω₀ > 0, 0 < λ ≤ 1 and the shares are ≥ 0 with
  /// each row summing to 1.
  void validate() const;
};

/// What an observer gives the DP controller.
struct ObserverEstimate {
  Eigen::Vector3d eta_n = Eigen::Vector3d::Zero();   ///< LF (N, E, ψ) [m, m, rad], ψ unwrapped
  Eigen::Vector3d nu_b = Eigen::Vector3d::Zero();    ///< LF velocity (u, v, r) BODY [m/s, rad/s]
  Eigen::Vector3d bias_n = Eigen::Vector3d::Zero();  ///< b̂ (NED) [N, N, N·m]
  Eigen::Vector3d wave_n = Eigen::Vector3d::Zero();  ///< WF estimate η̂_w [m, m, rad]
};

/// ỹ = y − ŷ with the heading component wrapped to (−π, π] and a missing (NaN) component 0.
Eigen::Vector3d innovation(const Eigen::Vector3d& y_n, const Eigen::Vector3d& y_hat_n) noexcept;

}  // namespace dynpos::control
