#pragma once
/// \file
/// The first-order system with hybrid integral action, thesis section 5.2.2, as a hybrid system
/// H = (C, f, D, g).
///
/// Plant and control law, (5.4)–(5.6), for a constant set point z_d:
///
///     ż = −a z + d + u,   ḋ = 0,   u = a z_d − k_p (z − z_d) − d̂,   d̂̇ = k_i (z − z_d)
///
/// In the errors x = (x₁, x₂) = (z − z_d, d − d̂) (5.9) the closed loop is the linear flow
/// ẋ = A x, A = [−a′, 1; −k_i, 0], a′ = a + k_p (5.7)–(5.11), on C = ℝ² (5.10). The jump map
/// moves the integral state by the position error, d̂⁺ = d̂ + λ x₁, that is
///
///     x₁⁺ = x₁,   x₂⁺ = x₂ − λ x₁                                                    (5.12)
///
/// With V = xᵀPx (5.13), a jump changes V by γx₁² − βx₁x₂ (5.28), β = 2λp₃, γ = λ²p₃ − 2λp₂,
/// and the ideal jump set is
///
///     D = {|x₁| ≥ ε,  x₁x₂ ≥ ((γ + σ)x₁² + σx₂²)/β}                                 (5.20)
///
/// where V(g(x)) − V(x) ≤ −σ|x|² (5.21). The practical jump set cannot use x₂ = d − d̂ (d is
/// unknown); by the flow map x₂ = a′x₁ + ẋ₁ (5.30), so it evaluates (5.20) at
/// x̂₂ = a′x₁ + ẋ₁ with ẋ₁ from a sampled, noisy finite difference (derivative_sampler.hpp).
/// This is (5.31) exactly (including its σx₂² term, with x̂₂ in place of x₂).
///
/// State vector (size 4): z, d̂, d, and t_J, the time of the last jump (initially the start
/// time). d is the true disturbance, constant in flow (5.5): scenario events step it. Held
/// input (size 2), written by the sampling task: the sampled ẋ₁ estimate and the time of the
/// older sample it was built from (NaN: no estimate yet). The sampled jump set accepts an
/// estimate only if that sample is not older than the last jump, since a jump changes the
/// slope ẋ₁ = −a′x₁ + x₂.

#include <Eigen/Core>

#include "dynpos/hybrid/jump_set.hpp"
#include "dynpos/hybrid/stability_check.hpp"
#include "dynpos/sim/hybrid_system.hpp"

namespace dynpos::hybrid {

/// Parameters of the first-order system; defaults are the case study of section 5.3.1.
struct FirstOrderParams {
  double a = 1.0;       ///< plant pole a [1/s] of (5.4), > 0 (5.68)
  double kp = 9.0;      ///< proportional gain k_p [1/s], ≥ 0; a′ = a + k_p = 10 (5.70)–(5.71)
  double ki = 1.0;      ///< integral gain k_i [1/s²], > 0 (5.72)
  double z_d = 0.0;     ///< set point z_d (constant), in the unit of z
  double lambda = 3.0;  ///< jump gain λ [1/s], > 0 (5.76)
  double epsilon = 0.3;  ///< no jumps while |x₁| < ε, in the unit of z, > 0 (5.77)
  double sigma = 0.0;    ///< decrease margin σ ≥ 0 of (5.19)–(5.21); 0 in the thesis (5.78)
  /// Lyapunov matrix P = Pᵀ > 0 with PA + AᵀP < 0; (5.75): [1, −0.1; −0.1, 1].
  Eigen::Matrix2d P = (Eigen::Matrix2d() << 1.0, -0.1, -0.1, 1.0).finished();
  JumpSet jump_set = JumpSet::kIdeal;  ///< which D to use

  /// a′ = a + k_p, (5.7).
  double a_prime() const noexcept { return a + kp; }
  /// A of (5.11).
  Eigen::Matrix2d A() const { return first_order_flow_matrix(a_prime(), ki); }
  /// Theorem 6's conditions for these parameters.
  FirstOrderCheck check() const;
  /// Throws std::invalid_argument when a parameter is out of range or the conditions of
  /// Theorem 6 fail, with check()'s reason.
  void validate() const;
};

/// The first-order system with hybrid integral action (see the file comment).
class FirstOrderSystem final : public sim::HybridSystem {
 public:
  /// Indices into the state vector.
  enum StateIndex : Eigen::Index { kZ = 0, kDHat = 1, kD = 2, kLastJump = 3, kStateSize = 4 };
  /// Indices into the held input.
  enum InputIndex : Eigen::Index { kX1DotHat = 0, kOlderSampleTime = 1, kInputSize = 2 };

  /// Throws std::invalid_argument if params.validate() does.
  explicit FirstOrderSystem(const FirstOrderParams& params);

  const FirstOrderParams& params() const noexcept { return params_; }
  /// β and γ of (5.16)–(5.17) and the rest of the check.
  const FirstOrderCheck& check() const noexcept { return check_; }

  Eigen::Index state_size() const override { return kStateSize; }
  Eigen::Index input_size() const override { return kInputSize; }

  /// The closed loop (5.4)–(5.8): ż = −a′(z − z_d) + d − d̂, d̂̇ = k_i(z − z_d), ḋ = 0, ṫ_J = 0.
  void flow(double t, const sim::ConstVectorRef& x, const sim::ConstVectorRef& u,
            sim::VectorRef dxdt) const override;

  /// The ideal (5.20) or sampled (5.31) jump set, or ∅ for JumpSet::kNone.
  bool in_jump_set(double t, const sim::ConstVectorRef& x,
                   const sim::ConstVectorRef& u) const override;

  /// d̂⁺ = d̂ + λx₁, i.e. x₂⁺ = x₂ − λx₁ (5.12); t_J⁺ = t.
  void jump(double t, const sim::ConstVectorRef& x, const sim::ConstVectorRef& u,
            sim::VectorRef x_plus) const override;

  /// The initial state at time t0 [s]: z = z_d, d̂ = d = d0.
  Eigen::VectorXd initial_state(double d0 = 0.0, double t0 = 0.0) const;

  /// The errors x = (x₁, x₂) = (z − z_d, d − d̂) of a state, (5.9).
  Eigen::Vector2d errors(const sim::ConstVectorRef& x) const;

  /// V = xᵀPx, (5.13), of the errors x.
  double lyapunov(const Eigen::Vector2d& e) const { return e.dot(params_.P * e); }

  /// x ∈ D of (5.20), for the errors x.
  bool in_ideal_jump_set(const Eigen::Vector2d& e) const;

  /// x̂₂ = a′x₁ + ẋ₁, (5.30): the integral error implied by a derivative estimate.
  double estimate_x2(double x1, double x1_dot) const { return params_.a_prime() * x1 + x1_dot; }

 private:
  FirstOrderParams params_;
  FirstOrderCheck check_;
};

}  // namespace dynpos::hybrid
