#include "dynpos/hybrid/stability_check.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>
#include <cstdio>
#include <string>

namespace dynpos::hybrid {
namespace {

// Relative tolerance of the symmetry tests: P and K_i are user numbers, typed or computed; a
// difference of 1e-12 of the largest entry is rounding, anything larger a real asymmetry.
constexpr double kSymmetryTolerance = 1e-12;

bool symmetric(const Eigen::MatrixXd& m) {
  const double scale = std::max(m.cwiseAbs().maxCoeff(), 1e-300);
  return (m - m.transpose()).cwiseAbs().maxCoeff() <= kSymmetryTolerance * scale;
}

template <int N>
Eigen::Matrix<double, N, 1> sym_eigenvalues(const Eigen::Matrix<double, N, N>& m) {
  const Eigen::Matrix<double, N, N> s = 0.5 * (m + m.transpose());
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>>(s, Eigen::EigenvaluesOnly)
      .eigenvalues();
}

bool finite(double v) { return std::isfinite(v); }

// A number with six significant digits, for messages.
std::string num(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", v);
  return buffer;
}

}  // namespace

const char* to_string(CheckStatus status) noexcept {
  return status == CheckStatus::kSatisfied ? "satisfied" : "violated";
}

std::optional<Eigen::MatrixXd> solve_lyapunov(const Eigen::MatrixXd& A, const Eigen::MatrixXd& Q) {
  const Eigen::Index n = A.rows();
  if (n == 0 || A.cols() != n || Q.rows() != n || Q.cols() != n) return std::nullopt;
  if (!A.allFinite() || !Q.allFinite()) return std::nullopt;
  // vec(AᵀP) = (I ⊗ Aᵀ)·vec(P) and vec(PA) = (Aᵀ ⊗ I)·vec(P) with column-major vec.
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n, n);
  const Eigen::MatrixXd At = A.transpose();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n * n, n * n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) {
      K.block(i * n, j * n, n, n) += I(i, j) * At;  // I ⊗ Aᵀ
      K.block(i * n, j * n, n, n) += At(i, j) * I;  // Aᵀ ⊗ I
    }
  }
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(K);
  if (!lu.isInvertible()) return std::nullopt;
  const Eigen::VectorXd q = Eigen::Map<const Eigen::VectorXd>(Q.data(), n * n);
  const Eigen::VectorXd p = lu.solve(-q);
  Eigen::MatrixXd P = Eigen::Map<const Eigen::MatrixXd>(p.data(), n, n);
  P = 0.5 * (P + P.transpose()).eval();
  return P;
}

Eigen::Matrix2d first_order_flow_matrix(double a_prime, double ki) {
  Eigen::Matrix2d A;
  A << -a_prime, 1.0, -ki, 0.0;  // (5.11)
  return A;
}

FirstOrderCheck check_first_order_conditions(double a_prime, double ki, double lambda,
                                             const Eigen::Matrix2d& P, double epsilon,
                                             double sigma) {
  FirstOrderCheck c;
  c.A = first_order_flow_matrix(a_prime, ki);
  c.P = P;
  const auto violated = [&c](std::string reason) {
    c.status = CheckStatus::kViolated;
    c.reason = std::move(reason);
    return c;
  };
  if (!(finite(a_prime) && a_prime > 0.0)) {
    return violated(std::string("a' = a + k_p = ") + num(a_prime) +
                    " must be > 0 (Theorem 6); raise k_p");
  }
  if (!(finite(ki) && ki > 0.0)) {
    return violated(std::string("k_i = ") + num(ki) + " must be > 0 (Theorem 6)");
  }
  if (!(finite(lambda) && lambda > 0.0)) {
    return violated(std::string("lambda = ") + num(lambda) + " must be > 0 (Theorem 6)");
  }
  if (!P.allFinite() || !symmetric(P)) {
    return violated("P must be finite and symmetric, P = P^T (5.14)");
  }
  c.P_eigenvalues = sym_eigenvalues<2>(P);
  c.beta = 2.0 * lambda * P(1, 1);                               // (5.16)
  c.gamma = lambda * lambda * P(1, 1) - 2.0 * lambda * P(0, 1);  // (5.17)
  const Eigen::Matrix2d flow = P * c.A + c.A.transpose() * P;    // (5.23)
  c.flow_eigenvalues = sym_eigenvalues<2>(flow);
  if (!(c.P_eigenvalues(0) > 0.0)) {
    return violated(std::string("P must be positive definite (5.14); its eigenvalues are ") +
                    num(c.P_eigenvalues(0)) + " and " + num(c.P_eigenvalues(1)));
  }
  if (!(c.flow_eigenvalues(1) < 0.0)) {
    return violated(
        std::string("PA + A^T P must be negative definite (5.24) so that V decreases in flow; its "
                    "eigenvalues are ") +
        num(c.flow_eigenvalues(0)) + " and " + num(c.flow_eigenvalues(1)) +
        ". Choose P from the Lyapunov equation A^T P + PA = -Q with Q > 0, or change the gains");
  }
  if (!(c.beta > 0.0)) {
    return violated(std::string("beta = 2 lambda p3 = ") + num(c.beta) + " must be > 0 (5.16)");
  }
  if (!(c.gamma > 0.0)) {
    return violated(
        std::string("gamma = lambda^2 p3 - 2 lambda p2 = ") + num(c.gamma) +
        " must be > 0 (5.17); raise lambda above 2 p2 / p3 = " + num(2.0 * P(0, 1) / P(1, 1)));
  }
  if (!(finite(epsilon) && epsilon > 0.0)) {
    return violated(std::string("epsilon = ") + num(epsilon) + " must be > 0 (5.18)");
  }
  if (!(finite(sigma) && sigma >= 0.0)) {
    return violated(std::string("sigma = ") + num(sigma) + " must be >= 0 (5.19)");
  }
  if (sigma == 0.0) {
    c.notes.push_back(
        "sigma = 0 as in the thesis simulations (5.78): V does not increase at a jump; (5.19) "
        "with sigma > 0 would make the decrease strict");
  }
  c.status = CheckStatus::kSatisfied;
  return c;
}

DpCheck check_dp_conditions(const Eigen::Matrix3d& M, const Eigen::Matrix3d& Kp,
                            const Eigen::Matrix3d& Kd, const Eigen::Matrix3d& Ki, double lambda,
                            double epsilon1, double epsilon2, double sigma) {
  DpCheck c;
  const auto violated = [&c](std::string reason) {
    c.status = CheckStatus::kViolated;
    c.reason = std::move(reason);
    return c;
  };
  if (!M.allFinite() || !Kp.allFinite() || !Kd.allFinite() || !Ki.allFinite()) {
    return violated("M, K_p, K_d and K_i must be finite");
  }
  if (!symmetric(M)) return violated("M must be symmetric, M = M^T (Theorem 7)");
  if (!symmetric(Ki)) return violated("K_i must be symmetric, K_i = K_i^T (5.36)");
  c.min_eig_M = sym_eigenvalues<3>(M)(0);
  c.min_eig_Kp = sym_eigenvalues<3>(Kp)(0);
  c.min_eig_Kd = sym_eigenvalues<3>(Kd)(0);
  c.min_eig_Ki = sym_eigenvalues<3>(Ki)(0);
  if (!(c.min_eig_M > 0.0)) {
    return violated(std::string("M must be positive definite (5.33); smallest eigenvalue ") +
                    num(c.min_eig_M));
  }
  if (!(c.min_eig_Kp > 0.0)) {
    return violated(std::string("K_p must be positive definite so that V decreases in flow (5.57); "
                                "smallest eigenvalue ") +
                    num(c.min_eig_Kp));
  }
  if (!(c.min_eig_Kd > 0.0)) {
    return violated(std::string("K_d must be positive definite so that V decreases in flow (5.57); "
                                "smallest eigenvalue ") +
                    num(c.min_eig_Kd));
  }
  if (!(c.min_eig_Ki > 0.0)) {
    return violated(
        std::string("K_i must be positive definite for V of (5.48); smallest eigenvalue ") +
        num(c.min_eig_Ki));
  }
  if (!(finite(lambda) && lambda > 0.0)) {
    return violated(std::string("lambda = ") + num(lambda) + " must be > 0 (5.46)");
  }
  // Eigenvalues of K_i⁻¹ are the reciprocals of those of K_i; the smallest is 1/max.
  const double max_eig_Ki = sym_eigenvalues<3>(Ki)(2);
  c.beta_min = lambda / max_eig_Ki;                  // (5.49) with P₃ = ½K_i⁻¹
  c.gamma_min = 0.5 * lambda * lambda / max_eig_Ki;  // (5.50) with P₂ = 0
  if (!(finite(epsilon1) && epsilon1 > 0.0)) {
    return violated(std::string("epsilon1 = ") + num(epsilon1) + " must be > 0 (5.51)");
  }
  if (!(finite(epsilon2) && epsilon2 > 0.0)) {
    return violated(std::string("epsilon2 = ") + num(epsilon2) + " must be > 0 (5.52)");
  }
  if (!(finite(sigma) && sigma >= 0.0)) {
    return violated(std::string("sigma = ") + num(sigma) + " must be >= 0 (5.53)");
  }
  if (sigma == 0.0) {
    c.notes.push_back(
        "sigma = 0 as in the thesis simulations: V does not increase at a jump; (5.53) with "
        "sigma > 0 would make the decrease strict");
  }
  c.status = CheckStatus::kSatisfied;
  return c;
}

}  // namespace dynpos::hybrid
