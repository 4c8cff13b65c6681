#include "dynpos/hybrid/integral_jump.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <random>

#include "dynpos/control/dp_controller.hpp"
#include "dynpos/core/error.hpp"

namespace dynpos::hybrid {
namespace {

TEST(IntegralJump, LyapunovNeverIncreasesAtAJumpInsideTheSet) {
  // Random states at random headings with the vessel controller's K_i: every state the rule
  // lets jump (with the true x₃) has V(g) ≤ V, and the change agrees with V of (5.48).
  const control::DpControllerParams c;
  const control::DpController controller(c);
  const IntegralJumpParams p;
  std::mt19937_64 engine(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int inside = 0;
  for (int k = 0; k < 20000; ++k) {
    const Eigen::Vector3d x1(5 * unit(engine), 5 * unit(engine), 0.2 * unit(engine));
    const Eigen::Vector3d x2(0.3 * unit(engine), 0.3 * unit(engine), 0.01 * unit(engine));
    const Eigen::Vector3d x3(5e4 * unit(engine), 5e4 * unit(engine), 5e5 * unit(engine));
    const double psi = 3.14159 * unit(engine);
    const double dV = lyapunov_change_at_jump(p, c.Ki, x1, x2, x3, psi);
    const Eigen::Vector3d x3_plus = x3 - integral_jump(p, x2, psi);
    const double dV_direct = controller.lyapunov(x1, x2, x3_plus) - controller.lyapunov(x1, x2, x3);
    // Same quadratic form evaluated two ways: agreement to rounding of V (~1e6 here).
    EXPECT_NEAR(dV, dV_direct, 1e-9 * (std::abs(dV_direct) + 1.0));
    if (in_integral_jump_set(p, c.Ki, x1, x2, x3, psi)) {
      ++inside;
      EXPECT_LE(dV, 0.0) << "k = " << k;
    }
  }
  EXPECT_GT(inside, 1000);  // the test must exercise the set
}

TEST(IntegralJump, JumpMovesTheEstimateAlongTheNedVelocityError) {
  IntegralJumpParams p;
  p.lambda = {2.0, 3.0, 4.0};
  // Heading 90°: a BODY surge error is a NED east error.
  const Eigen::Vector3d d = integral_jump(p, {0.5, 0.0, 0.1}, M_PI / 2);
  EXPECT_NEAR(d.x(), 0.0, 1e-15);
  EXPECT_NEAR(d.y(), 1.5, 1e-15);
  EXPECT_NEAR(d.z(), 0.4, 1e-15);
}

TEST(IntegralJump, NoJumpInsideTheDeadZones) {
  const IntegralJumpParams p;
  const Eigen::Matrix3d Ki = Eigen::Vector3d(1e3, 1e3, 1e4).asDiagonal();
  const Eigen::Vector3d big_x3(1e5, 1e5, 1e6), x2(0.2, 0, 0);
  EXPECT_TRUE(in_integral_jump_set(p, Ki, {1, 0, 0}, x2, big_x3, 0.0));
  EXPECT_FALSE(in_integral_jump_set(p, Ki, {0.01, 0, 0}, x2, big_x3, 0.0));  // |x₁| < ε₁
  EXPECT_FALSE(in_integral_jump_set(p, Ki, {1, 0, 0}, {0.001, 0, 0}, big_x3, 0.0));  // |x₂| < ε₂
}

TEST(IntegralJump, EstimateRecoversTheIntegralErrorOfTheClosedLoop) {
  // Closed loop (5.44): M ẋ₂ = −x₁ − K_d x₂ + R(ψ)ᵀx₃, so (5.64) returns x₃ exactly.
  const control::DpControllerParams c;
  const Eigen::Vector3d x1(1, -2, 0.1), x2(0.1, 0.05, 0.002), x3(3e4, -1e4, 2e5);
  const double psi = 0.7;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(psi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d x2_dot = c.M.inverse() * (-x1 - c.Kd * x2 + R.transpose() * x3);
  EXPECT_LT((estimate_integral_error(c.M, c.Kd, x1, x2, x2_dot, psi) - x3).norm(), 1e-6);
}

TEST(IntegralJump, RejectsBadParameters) {
  IntegralJumpParams p;
  p.lambda.y() = 0.0;
  EXPECT_THROW(p.validate(), core::InputError);
  p = IntegralJumpParams{};
  p.dwell_s = 0.0;
  try {
    p.validate();
    ADD_FAILURE() << "no exception";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.where().column_name, "hybrid.dwell_s");  // the scenario file's key
  }
}

}  // namespace
}  // namespace dynpos::hybrid
