#include "dynpos/hybrid/stability_check.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "dynpos/sim/random.hpp"

namespace dynpos::hybrid {
namespace {

using ::testing::HasSubstr;

const Eigen::Matrix2d kThesisP = (Eigen::Matrix2d() << 1.0, -0.1, -0.1, 1.0).finished();  // (5.75)

TEST(FirstOrderCheck, ThesisNumbers) {
  // Section 5.3.1: a′ = 10, k_i = 1, P of (5.75), λ = 3 give β = 6 and γ = 9.6 (text after
  // (5.77)). The arithmetic is a handful of products of short decimals: 1e-12 is rounding.
  const FirstOrderCheck c = check_first_order_conditions(10.0, 1.0, 3.0, kThesisP, 0.3, 0.0);
  ASSERT_TRUE(c.ok()) << c.reason;
  EXPECT_EQ(to_string(c.status), std::string("satisfied"));
  EXPECT_NEAR(c.beta, 6.0, 1e-12);
  EXPECT_NEAR(c.gamma, 9.6, 1e-12);
  // PA + AᵀP = [−19.8, 1; 1, −0.2]: eigenvalues −10 ∓ √(100 − 2.96).
  const double root = std::sqrt(100.0 - 2.96);
  EXPECT_NEAR(c.flow_eigenvalues(0), -10.0 - root, 1e-12);
  EXPECT_NEAR(c.flow_eigenvalues(1), -10.0 + root, 1e-12);
  EXPECT_NEAR(c.P_eigenvalues(0), 0.9, 1e-12);
  EXPECT_NEAR(c.P_eigenvalues(1), 1.1, 1e-12);
  EXPECT_TRUE(c.reason.empty());
  ASSERT_EQ(c.notes.size(), 1u);  // σ = 0
  EXPECT_THAT(c.notes[0], HasSubstr("sigma = 0"));
}

TEST(FirstOrderCheck, RefusesAPThatDoesNotDecreaseInFlow) {
  // k_i = 30 with the thesis P: PA + AᵀP = [−14, −28; −28, −0.2] is indefinite.
  const FirstOrderCheck c = check_first_order_conditions(10.0, 30.0, 3.0, kThesisP, 0.3, 0.0);
  EXPECT_FALSE(c.ok());
  EXPECT_EQ(to_string(c.status), std::string("violated"));
  EXPECT_THAT(c.reason, HasSubstr("(5.24)"));
  EXPECT_GT(c.flow_eigenvalues(1), 0.0);
}

TEST(FirstOrderCheck, RefusesBadParameters) {
  EXPECT_THAT(check_first_order_conditions(0.0, 1.0, 3.0, kThesisP, 0.3, 0.0).reason,
              HasSubstr("a'"));
  EXPECT_THAT(check_first_order_conditions(10.0, -1.0, 3.0, kThesisP, 0.3, 0.0).reason,
              HasSubstr("k_i"));
  EXPECT_THAT(check_first_order_conditions(10.0, 1.0, 0.0, kThesisP, 0.3, 0.0).reason,
              HasSubstr("lambda"));
  Eigen::Matrix2d asym = kThesisP;
  asym(0, 1) = 0.2;
  EXPECT_THAT(check_first_order_conditions(10.0, 1.0, 3.0, asym, 0.3, 0.0).reason,
              HasSubstr("symmetric"));
  const Eigen::Matrix2d indefinite = (Eigen::Matrix2d() << 1.0, 2.0, 2.0, 1.0).finished();
  EXPECT_THAT(check_first_order_conditions(10.0, 1.0, 3.0, indefinite, 0.3, 0.0).reason,
              HasSubstr("(5.14)"));
  EXPECT_THAT(check_first_order_conditions(10.0, 1.0, 3.0, kThesisP, 0.0, 0.0).reason,
              HasSubstr("(5.18)"));
  EXPECT_THAT(check_first_order_conditions(10.0, 1.0, 3.0, kThesisP, 0.3, -1.0).reason,
              HasSubstr("(5.19)"));
  const FirstOrderCheck strict = check_first_order_conditions(10.0, 1.0, 3.0, kThesisP, 0.3, 0.1);
  EXPECT_TRUE(strict.ok());
  EXPECT_TRUE(strict.notes.empty());
}

TEST(SolveLyapunov, FirstOrderClosedForm) {
  // For A = [−a′, 1; −k_i, 0] and Q = I the equation gives, by hand, p₂ = −½,
  // p₁ = (1 + k_i)/(2a′), p₃ = (p₁ − a′p₂)/k_i: (0.1, −0.5, 5.1) for a′ = 10, k_i = 1.
  const auto P = solve_lyapunov(first_order_flow_matrix(10.0, 1.0), Eigen::Matrix2d::Identity());
  ASSERT_TRUE(P.has_value());
  EXPECT_NEAR((*P)(0, 0), 0.1, 1e-12);
  EXPECT_NEAR((*P)(0, 1), -0.5, 1e-12);
  EXPECT_NEAR((*P)(1, 0), -0.5, 1e-12);
  EXPECT_NEAR((*P)(1, 1), 5.1, 1e-12);
  // That P passes the theorem's conditions (with Q = I, PA + AᵀP = −I).
  const FirstOrderCheck c = check_first_order_conditions(10.0, 1.0, 3.0, *P, 0.3, 0.0);
  ASSERT_TRUE(c.ok()) << c.reason;
  EXPECT_NEAR(c.flow_eigenvalues(0), -1.0, 1e-12);
  EXPECT_NEAR(c.flow_eigenvalues(1), -1.0, 1e-12);
  // … and rescues k_i = 30, which the thesis P cannot take.
  const auto P30 = solve_lyapunov(first_order_flow_matrix(10.0, 30.0), Eigen::Matrix2d::Identity());
  ASSERT_TRUE(P30.has_value());
  EXPECT_TRUE(check_first_order_conditions(10.0, 30.0, 3.0, *P30, 0.3, 0.0).ok());
}

TEST(SolveLyapunov, ResidualOnRandomHurwitzMatrices) {
  sim::Rng rng(42);
  for (int trial = 0; trial < 50; ++trial) {
    Eigen::Matrix3d B;
    for (int i = 0; i < 9; ++i) B.data()[i] = rng.uniform(-1.0, 1.0);
    // Shift the spectrum left of −0.5: A = B − (ρ(B) + 0.5)·I is Hurwitz.
    const double radius = B.eigenvalues().cwiseAbs().maxCoeff();
    const Eigen::Matrix3d A = B - (radius + 0.5) * Eigen::Matrix3d::Identity();
    Eigen::Matrix3d L;
    for (int i = 0; i < 9; ++i) L.data()[i] = rng.uniform(-1.0, 1.0);
    const Eigen::Matrix3d Q = L * L.transpose() + 0.1 * Eigen::Matrix3d::Identity();
    const auto P = solve_lyapunov(A, Q);
    ASSERT_TRUE(P.has_value());
    // The LU solve of a 9×9 system with condition number ≲ 1e3 leaves a residual of a few
    // hundred ulp of the entries; 1e-10 relative to |Q| is a generous bound.
    const Eigen::MatrixXd residual = A.transpose() * *P + *P * A + Q;
    EXPECT_LT(residual.cwiseAbs().maxCoeff(), 1e-10 * Q.cwiseAbs().maxCoeff()) << "trial " << trial;
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(*P).eigenvalues()(0), 0.0);
  }
}

TEST(SolveLyapunov, NoUniqueSolution) {
  // Eigenvalues 1 and −1 sum to zero: the Kronecker matrix is singular.
  const Eigen::Matrix2d A = Eigen::Vector2d(1.0, -1.0).asDiagonal();
  EXPECT_FALSE(solve_lyapunov(A, Eigen::Matrix2d::Identity()).has_value());
  EXPECT_FALSE(
      solve_lyapunov(Eigen::Matrix3d::Identity(), Eigen::Matrix2d::Identity()).has_value());
  EXPECT_FALSE(solve_lyapunov(Eigen::MatrixXd(0, 0), Eigen::MatrixXd(0, 0)).has_value());
}

TEST(DpCheck, ThesisGains) {
  const Eigen::Matrix3d M = Eigen::Vector3d(450, 450, 100).asDiagonal();
  const Eigen::Matrix3d Kp = Eigen::Vector3d(100, 100, 50).asDiagonal();
  const Eigen::Matrix3d Kd = Eigen::Vector3d(500, 500, 200).asDiagonal();
  const Eigen::Matrix3d Ki = Eigen::Vector3d(10, 10, 5).asDiagonal();
  const DpCheck c = check_dp_conditions(M, Kp, Kd, Ki, 25.0, 1e-4, 0.01, 0.0);
  ASSERT_TRUE(c.ok()) << c.reason;
  EXPECT_DOUBLE_EQ(c.min_eig_M, 100.0);
  EXPECT_DOUBLE_EQ(c.min_eig_Kp, 50.0);
  EXPECT_DOUBLE_EQ(c.min_eig_Kd, 200.0);
  EXPECT_DOUBLE_EQ(c.min_eig_Ki, 5.0);
  EXPECT_DOUBLE_EQ(c.beta_min, 2.5);     // λ/max K_i = 25/10
  EXPECT_DOUBLE_EQ(c.gamma_min, 31.25);  // ½λ²/max K_i = 312.5/10

  Eigen::Matrix3d bad = Kd;
  bad(2, 2) = -1.0;
  EXPECT_THAT(check_dp_conditions(M, Kp, bad, Ki, 25.0, 1e-4, 0.01, 0.0).reason,
              HasSubstr("K_d must be positive definite"));
  bad = Ki;
  bad(0, 1) = 1.0;
  EXPECT_THAT(check_dp_conditions(M, Kp, Kd, bad, 25.0, 1e-4, 0.01, 0.0).reason,
              HasSubstr("K_i must be symmetric"));
  EXPECT_THAT(check_dp_conditions(M, Kp, Kd, Ki, 0.0, 1e-4, 0.01, 0.0).reason, HasSubstr("lambda"));
  EXPECT_THAT(check_dp_conditions(M, Kp, Kd, Ki, 25.0, 0.0, 0.01, 0.0).reason, HasSubstr("(5.51)"));
  EXPECT_THAT(check_dp_conditions(M, Kp, Kd, Ki, 25.0, 1e-4, -0.01, 0.0).reason,
              HasSubstr("(5.52)"));
  EXPECT_THAT(check_dp_conditions(-M, Kp, Kd, Ki, 25.0, 1e-4, 0.01, 0.0).reason,
              HasSubstr("M must be positive definite"));
}

}  // namespace
}  // namespace dynpos::hybrid
