#pragma once
/// \file
/// The DP vessel with the backstepping controller of section 5.2.3 and hybrid integral action,
/// as a hybrid system H = (C, f, D, g).
///
/// Plant (5.32)–(5.34) and controller (5.35)–(5.38) as in control/dp_controller.hpp, for a
/// constant set point η_d:
///
///     η̇ = R(ψ)ν,   Mν̇ = −Dν + R(ψ)ᵀb + τ,   ḃ = 0,   b̂̇ = K_i R(ψ) x₂
///
/// with x₁ = R(ψ)ᵀ(η − η_d) (BODY), x₂ = ν − μ (BODY), x₃ = b − b̂ (NED), and the closed loop
/// (5.43)–(5.45). V = ½x₁ᵀx₁ + ½x₂ᵀMx₂ + ½x₃ᵀK_i⁻¹x₃ (5.48), V̇ = −x₁ᵀK_p x₁ − x₂ᵀK_d x₂ (5.57).
///
/// Frames of the jump map. The thesis writes x₃⁺ = x₃ − Λx₂ (5.47), but x₃ = b − b̂ is a NED
/// vector and x₂ a BODY vector. dynpos moves the integral state along the same direction the
/// continuous integral action uses, the NED velocity error w = R(ψ)x₂ of (5.36):
///
///     b̂⁺ = b̂ + λ R(ψ) x₂,   i.e.   x₃⁺ = x₃ − Λ R(ψ) x₂,   Λ = λI                  (5.47)
///
/// With it, V(g) − V = −λ wᵀK_i⁻¹x₃ + ½λ² wᵀK_i⁻¹w, and the jump set (5.54)–(5.55) reads, with
/// w in place of x₂ in its last condition,
///
///     D = {|x₁| ≥ ε₁,  |x₂| ≥ ε₂,  wᵀK_i⁻¹x₃ ≥ (λ/2) wᵀK_i⁻¹w + σ/(2λ)(|x₁|² + |x₂|² + |x₃|²)}
///
/// on which V(g) − V ≤ −(σ/2)|x|² ≤ 0. (The thesis' (5.61) drops the ½ of (5.48), which
/// halves the margin but not the sign.) At ψ = 0 this is the thesis' rule; at other headings
/// the literal rule adds a BODY vector to a NED one: its jump set then asks x₂ᵀK_i⁻¹x₃ ≥ …,
/// which for a bias across the heading (ψ = 90°) or opposite (ψ = 180°) is rarely or never true,
/// so the literal rule stops helping. JumpFrame::kThesisLiteral keeps it for comparison.
///
/// The practical jump set (5.64)–(5.67) replaces the unknown x₃ by the closed loop (5.44):
/// x̂₃ = R(ψ)(M ẋ₂ + x₁ + K_d x₂), with ẋ₂ from a sampled, noisy finite difference, and
/// evaluates the ideal set at x̂₃.
///
/// State vector (size 13): η = (N, E, ψ) [m, m, rad], ν = (u, v, r) BODY [m/s, m/s, rad/s],
/// b̂ NED [N, N, N·m], b NED [N, N, N·m] (the true bias, constant in flow; scenario events step
/// it), and t_J, the time of the last jump (initially the start time). Held input (size 4): the
/// sampled ẋ₂ estimate (BODY) and the time of the older sample it was built from (NaN: none).

#include <Eigen/Core>

#include "dynpos/control/dp_controller.hpp"
#include "dynpos/hybrid/jump_set.hpp"
#include "dynpos/hybrid/stability_check.hpp"
#include "dynpos/sim/hybrid_system.hpp"

namespace dynpos::hybrid {

/// Which vector the jump adds to the integral state (see the file comment).
enum class JumpFrame {
  kNed,            ///< b̂⁺ = b̂ + λR(ψ)x₂: the NED velocity error (dynpos' choice)
  kThesisLiteral,  ///< b̂⁺ = b̂ + λx₂: (5.47) as printed, mixing BODY into NED
};

/// The controller of the DP case study, section 5.3.2: M = diag(450, 450, 100) (5.84),
/// K_p = diag(100, 100, 50) (5.85), K_i = diag(10, 10, 5) (5.86), K_d = diag(500, 500, 200)
/// (5.87). The thesis gives no D: the control law cancels Dν exactly, so D does not enter the
/// closed loop (5.43)–(5.45); D = M·0.1 s⁻¹ is used only because the plant needs one. The
/// anti-windup bound of the controller is not used here (the integral state is integrated in
/// the flow).
control::DpControllerParams case_study_dp_controller();

/// Parameters of the DP system with hybrid integral action; defaults are section 5.3.2.
struct DpHybridParams {
  control::DpControllerParams controller = case_study_dp_controller();
  double lambda = 25.0;    ///< jump gain λ [N·s/m; N·m·s/rad in yaw], > 0 (5.88)
  double epsilon1 = 1e-4;  ///< no jumps while |x₁| < ε₁ [m, m, rad mixed], > 0 (5.89)
  double epsilon2 = 0.01;  ///< no jumps while |x₂| < ε₂ [m/s, rad/s mixed], > 0 (5.90)
  double sigma = 0.0;      ///< decrease margin σ ≥ 0 of (5.53); 0 as in the thesis
  Eigen::Vector3d eta_d = Eigen::Vector3d::Zero();  ///< set point (N, E, ψ) [m, m, rad]
  JumpSet jump_set = JumpSet::kIdeal;
  JumpFrame jump_frame = JumpFrame::kNed;

  /// Theorem 7's conditions for these parameters.
  DpCheck check() const;
  /// Throws std::invalid_argument if the controller parameters are invalid, η_d is not finite
  /// or the conditions of Theorem 7 fail (with check()'s reason).
  void validate() const;
};

/// The errors of (5.35) at one state.
struct DpErrors {
  Eigen::Vector3d x1 = Eigen::Vector3d::Zero();  ///< R(ψ)ᵀ(η − η_d), BODY [m, m, rad]
  Eigen::Vector3d x2 = Eigen::Vector3d::Zero();  ///< ν − μ, BODY [m/s, m/s, rad/s]
  Eigen::Vector3d x3 = Eigen::Vector3d::Zero();  ///< b − b̂, NED [N, N, N·m]
  double psi = 0.0;                              ///< heading ψ [rad]
};

/// The DP system with hybrid integral action (see the file comment).
class DpHybridSystem final : public sim::HybridSystem {
 public:
  /// Indices into the state vector (first index of each 3-vector).
  enum StateIndex : Eigen::Index {
    kEta = 0,
    kNu = 3,
    kBiasHat = 6,
    kBias = 9,
    kLastJump = 12,
    kStateSize = 13
  };
  /// Indices into the held input.
  enum InputIndex : Eigen::Index { kX2DotHat = 0, kOlderSampleTime = 3, kInputSize = 4 };

  /// Throws std::invalid_argument if params.validate() does.
  explicit DpHybridSystem(const DpHybridParams& params);

  const DpHybridParams& params() const noexcept { return params_; }
  const control::DpController& controller() const noexcept { return controller_; }

  Eigen::Index state_size() const override { return kStateSize; }
  Eigen::Index input_size() const override { return kInputSize; }

  /// (5.32)–(5.34) with τ of (5.38) and b̂̇ = K_i R(ψ)x₂ (5.36); ḃ = 0, ṫ_J = 0.
  void flow(double t, const sim::ConstVectorRef& x, const sim::ConstVectorRef& u,
            sim::VectorRef dxdt) const override;

  /// The ideal (5.54)–(5.55) or sampled (5.65)–(5.67) jump set (with w = R(ψ)x₂ for
  /// JumpFrame::kNed), or ∅ for JumpSet::kNone.
  bool in_jump_set(double t, const sim::ConstVectorRef& x,
                   const sim::ConstVectorRef& u) const override;

  /// b̂⁺ = b̂ + λw (5.47 with the frame of the file comment), t_J⁺ = t.
  void jump(double t, const sim::ConstVectorRef& x, const sim::ConstVectorRef& u,
            sim::VectorRef x_plus) const override;

  /// The initial state at time t0 [s]: at the set point, at rest, b̂ = b = b0 (NED).
  Eigen::VectorXd initial_state(const Eigen::Vector3d& b0 = Eigen::Vector3d::Zero(),
                                double t0 = 0.0) const;

  /// x₁, x₂, x₃ and ψ of a state, (5.35).
  DpErrors errors(const sim::ConstVectorRef& x) const;

  /// V of (5.48).
  double lyapunov(const DpErrors& e) const { return controller_.lyapunov(e.x1, e.x2, e.x3); }

  /// The vector w the jump adds to b̂ (divided by λ): R(ψ)x₂ (kNed) or x₂ (kThesisLiteral).
  Eigen::Vector3d jump_direction(const DpErrors& e) const;

  /// x ∈ D of (5.54)–(5.55), with the integral error x3 (the true one, or an estimate).
  bool in_ideal_jump_set(const DpErrors& e) const;

  /// x̂₃ = R(ψ)(M ẋ₂ + x₁ + K_d x₂), (5.64), from a derivative estimate ẋ₂ (BODY).
  Eigen::Vector3d estimate_x3(const DpErrors& e, const Eigen::Vector3d& x2_dot) const;

 private:
  DpHybridParams params_;
  control::DpController controller_;
  control::DpReference reference_;
  Eigen::Matrix3d M_inv_;
  Eigen::Matrix3d Ki_inv_;
};

}  // namespace dynpos::hybrid
