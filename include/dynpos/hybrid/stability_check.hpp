#pragma once
/// \file
/// The conditions of the stability theorems of the hybrid integral action, checked for given
/// gains, so that a configuration the theorems do not cover is refused with the reason.
///
/// First order (Theorem 6): for the flow matrix A of (5.11) and the Lyapunov matrix P of
/// (5.13)–(5.14), the flow decreases V = xᵀPx when PA + AᵀP < 0 (5.24), and a jump
/// x₂⁺ = x₂ − λx₁ (5.12) inside the jump set (5.20) decreases V when
///
///     β := 2λp₃ > 0   (5.16),     γ := λ²p₃ − 2λp₂ > 0   (5.17),     ε > 0 (5.18),  σ ≥ 0.
///
/// (5.19) asks σ > 0, which makes the decrease at a jump strict, V(g) − V ≤ −σ|x|² (5.21). The
/// thesis simulations use σ = 0 (5.78): V then does not increase at a jump, V(g) ≤ V, and the
/// dwell time keeps jumps apart so the flow, where V strictly decreases, does the rest. σ = 0
/// is accepted with a note.
///
/// DP (Theorem 7): with V of (5.48) the flow gives V̇ = −x₁ᵀK_p x₁ − x₂ᵀK_d x₂ (5.57), so K_p and
/// K_d must be positive definite (their symmetric parts), M = Mᵀ > 0 and K_i = K_iᵀ > 0 for V to
/// be a Lyapunov function; with V's x₃-block P₃ = ½K_i⁻¹ and no cross term (P₂ = 0), (5.49) and
/// (5.50) read β = λK_i⁻¹ > 0 and Γ = ½λ²K_i⁻¹ > 0, which hold for λ > 0; ε₁, ε₂ > 0 (5.51)–(5.52)
/// and σ ≥ 0 as above.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace dynpos::hybrid {

/// Whether the conditions of a theorem hold.
enum class CheckStatus {
  kSatisfied,  ///< every condition holds
  kViolated,   ///< a condition fails; `reason` says which and how to fix it
};

/// "satisfied" or "violated".
const char* to_string(CheckStatus status) noexcept;

/// The solution P of the Lyapunov equation AᵀP + PA = −Q for square A and Q of one size,
/// found from the Kronecker form (I ⊗ Aᵀ + Aᵀ ⊗ I)·vec(P) = −vec(Q) by a full-pivot LU
/// solve, then symmetrised. Absent when the equation has no unique solution (A has two
/// eigenvalues with λᵢ + λⱼ = 0) or the sizes do not match. For a Hurwitz A and Q = Qᵀ > 0,
/// P = Pᵀ > 0.
std::optional<Eigen::MatrixXd> solve_lyapunov(const Eigen::MatrixXd& A, const Eigen::MatrixXd& Q);

/// The closed-loop flow matrix of the first-order system, (5.11): A = [−a′, 1; −k_i, 0].
Eigen::Matrix2d first_order_flow_matrix(double a_prime, double ki);

/// The outcome of check_first_order_conditions().
struct FirstOrderCheck {
  CheckStatus status = CheckStatus::kViolated;
  std::string reason;              ///< empty when satisfied; else the failed condition and a fix
  std::vector<std::string> notes;  ///< remarks that do not refuse the configuration
  Eigen::Matrix2d A = Eigen::Matrix2d::Zero();                 ///< (5.11)
  Eigen::Matrix2d P = Eigen::Matrix2d::Zero();                 ///< as given (5.14)
  Eigen::Vector2d P_eigenvalues = Eigen::Vector2d::Zero();     ///< increasing; > 0 required
  Eigen::Vector2d flow_eigenvalues = Eigen::Vector2d::Zero();  ///< of PA + AᵀP, increasing; < 0
  double beta = 0.0;                                           ///< β = 2λp₃, (5.16)
  double gamma = 0.0;  ///< γ = λ²p₃ − 2λp₂, (5.17)

  bool ok() const noexcept { return status == CheckStatus::kSatisfied; }
};

/// Checks Theorem 6 for a′ = a + k_p, k_i, λ, P, ε and σ (see the file comment).
FirstOrderCheck check_first_order_conditions(double a_prime, double ki, double lambda,
                                             const Eigen::Matrix2d& P, double epsilon,
                                             double sigma);

/// The outcome of check_dp_conditions().
struct DpCheck {
  CheckStatus status = CheckStatus::kViolated;
  std::string reason;              ///< empty when satisfied; else the failed condition and a fix
  std::vector<std::string> notes;  ///< remarks that do not refuse the configuration
  double min_eig_M = 0.0;          ///< smallest eigenvalue of M (symmetric part); > 0 required
  double min_eig_Kp = 0.0;         ///< of (K_p + K_pᵀ)/2; > 0 required
  double min_eig_Kd = 0.0;         ///< of (K_d + K_dᵀ)/2; > 0 required
  double min_eig_Ki = 0.0;         ///< of K_i; > 0 required (and K_i = K_iᵀ)
  double beta_min = 0.0;           ///< smallest eigenvalue of β = λK_i⁻¹, (5.49)
  double gamma_min = 0.0;          ///< smallest eigenvalue of Γ = ½λ²K_i⁻¹, (5.50)

  bool ok() const noexcept { return status == CheckStatus::kSatisfied; }
};

/// Checks Theorem 7 for M, K_p, K_d, K_i, λ, ε₁, ε₂ and σ (see the file comment).
DpCheck check_dp_conditions(const Eigen::Matrix3d& M, const Eigen::Matrix3d& Kp,
                            const Eigen::Matrix3d& Kd, const Eigen::Matrix3d& Ki, double lambda,
                            double epsilon1, double epsilon2, double sigma);

}  // namespace dynpos::hybrid
