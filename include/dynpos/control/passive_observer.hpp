#pragma once
/// \file
/// The nonlinear passive observer of Fossen & Strand (1999) (Fossen 2011, sec. 11.4) on the
/// model of observer.hpp, with ỹ = y − ŷ and ŷ = η̂ + C_w ξ̂:
///
///     ξ̂̇ = A_w ξ̂ + K₁ ỹ
///     η̂̇ = R(ψ) ν̂ + K₂ ỹ
///     b̂̇ = −T⁻¹ b̂ + R(ψ) K₃ R(ψ)ᵀ ỹ
///     M ν̂̇ = −D ν̂ + R(ψ)ᵀ b̂ + τ + K₄ R(ψ)ᵀ ỹ
///
/// R is taken at the measured heading (the estimate's while the heading is missing), which makes
/// the error dynamics passive. K₃ and K₄ scale with M's diagonal, so they act in BODY: Fossen's
/// K₃ and K₄ (NED) are R K₃ Rᵀ and R K₄ Rᵀ here, his at ψ = 0 or with equal surge and sway
/// masses. The gains follow Fossen's tuning rules from the wave peak frequency ω₀: per DOF a
/// notch at ω₀ with damping ζ_n over the wave model's λ and a cut-off ω_c > ω₀,
///
///     K₁ = [diag(−2(ζ_n − λ) ω_c/ω₀); diag(2 ω₀ (ζ_n − λ))],   K₂ = diag(ω_c),
///
/// and K₃, K₄ from a slow pair at ω_b with damping ratio 1 (1/T ≪ K₃/K₄ < ω₀ < ω_c): per DOF
/// s² + K₄/(M K₂) s + K₃/(M K₂), so K₄ = 2 ω_b M K₂ and K₃ = ω_b² M K₂. That pair is the LF
/// loop M s³ + M K₂ s² + K₄ s + K₃ for ω_b ≪ ω_c with D and the wave model left out; the whole
/// error dynamics has instead one real slow pole per DOF at about ω_b/2 and the others beyond
/// 2 ω_b (on a supply vessel of T_p = 8 s: 0.48–0.65 ω_b and 2.8 ω_b; passive_observer_test).
///
/// A bias held against the decay −T⁻¹ b̂ of (2.22) settles short of the truth, per BODY axis at
/// b̂ = b / (1 + (D K₂ + K₄)/(T K₃)) ≈ b (1 − 2/(ω_b T)): 2.7–3.3 % short on that vessel with
/// T = 1000 s.
///
/// A lost measurement (a GNSS dropout: N and E NaN; a gyro fault: ψ NaN) leaves ỹ = 0 in it and
/// the observer coasts on its model, from the wave-period means of ν̂ and b̂ (coast_start.hpp).

#include <Eigen/Core>

#include "dynpos/control/coast_start.hpp"
#include "dynpos/control/observer.hpp"

namespace dynpos::control {

/// The tuning of the passive observer (see the file comment). passive_observer_gains() throws
/// std::invalid_argument unless ζ_n > λ (else no notch), ω_c/ω₀ > 1 and 0 < ω_b/ω₀ < 1.
struct PassiveObserverTuning {
  double notch_damping = 1.0;    ///< ζ_n [-]. Source: Fossen 2011 (ζ_n = 1.0).
  double cutoff_ratio = 1.2255;  ///< ω_c/ω₀ [-]. Source: Fossen 2011 (1.2255 ω₀).
  /// ω_b/ω₀ [-]. Source: calibrated on the virtual Gunnerus under DP in Hs 2.5 m, T_p 8 s at
  /// 45° to the waves (seed 3): a decade below the waves (0.1) left the observer's velocity so
  /// slow that the DP loop on it moved 1.8 times as much as on the true motion; 0.3 gave 1.06
  /// with the demand's wave-band power still 0.01–0.02 of the unfiltered loop's; from 0.5
  /// (with ω_c = 1.2255 ω₀) the error dynamics are unstable.
  double lf_bandwidth_ratio = 0.3;
};

/// The gains K₁…K₄ (see the file comment).
struct PassiveObserverGains {
  Eigen::Matrix<double, 6, 3> K1 = Eigen::Matrix<double, 6, 3>::Zero();
  Eigen::Matrix3d K2 = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d K3 = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d K4 = Eigen::Matrix3d::Zero();
};

/// The gains of `model` by the tuning rules. Throws std::invalid_argument on a bad model or
/// tuning.
PassiveObserverGains passive_observer_gains(const ObserverModel& model,
                                            const PassiveObserverTuning& tuning = {});

/// The observer (see the file comment).
class PassiveObserver {
 public:
  /// Starts at rest at η₀ (N, E, ψ) [m, m, rad] with no bias and no wave motion. Throws
  /// std::invalid_argument on a bad model.
  PassiveObserver(const ObserverModel& model, const PassiveObserverGains& gains,
                  const Eigen::Vector3d& eta0_n);

  /// Advances the estimate by dt [s] (one RK4 step with y and τ held) on the measurement
  /// y = (N, E, ψ) [m, m, rad] (a component NaN: missing; see the file comment for the step
  /// where it is lost) and the thrust τ (BODY) [N, N, N·m].
  void step(const Eigen::Vector3d& y_n, const Eigen::Vector3d& tau_b, double dt_s);

  const ObserverEstimate& estimate() const noexcept { return estimate_; }

 private:
  using State = Eigen::Matrix<double, 15, 1>;  // ξ (6), η (3), ν (3), b (3)
  State derivative(const State& x, const Eigen::Vector3d& y_n, const Eigen::Vector3d& tau_b) const;

  ObserverModel model_;
  PassiveObserverGains gains_;
  Eigen::Matrix3d M_inv_;
  State x_ = State::Zero();
  ObserverEstimate estimate_;
  CoastStart coast_;
};

}  // namespace dynpos::control
