#include "dynpos/hybrid/first_order_system.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "dynpos/sim/random.hpp"
#include "dynpos/sim/simulator.hpp"

namespace dynpos::hybrid {
namespace {

using ::testing::HasSubstr;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// e^{At} for a 2×2 A with distinct real eigenvalues r₁, r₂ (Sylvester's formula):
// e^{At} = (A − r₂I)e^{r₁t}/(r₁ − r₂) + (A − r₁I)e^{r₂t}/(r₂ − r₁).
Eigen::Matrix2d expm(const Eigen::Matrix2d& A, double t) {
  const double tr = A.trace();
  const double det = A.determinant();
  const double disc = std::sqrt(tr * tr / 4.0 - det);
  const double r1 = tr / 2.0 + disc;
  const double r2 = tr / 2.0 - disc;
  const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
  return (A - r2 * I) * std::exp(r1 * t) / (r1 - r2) + (A - r1 * I) * std::exp(r2 * t) / (r2 - r1);
}

// A state with errors (x1, x2), set point z_d, and d̂ = 2 (so d = x2 + 2).
Eigen::VectorXd state(const FirstOrderSystem& s, double x1, double x2, double t_jump = 0.0) {
  Eigen::VectorXd x(FirstOrderSystem::kStateSize);
  x << s.params().z_d + x1, 2.0, x2 + 2.0, t_jump;
  return x;
}

TEST(FirstOrderSystem, FlowIsTheLinearClosedLoop) {
  FirstOrderParams p;
  p.z_d = 1.5;
  const FirstOrderSystem s(p);
  sim::Rng rng(3);
  Eigen::VectorXd dxdt(FirstOrderSystem::kStateSize);
  const Eigen::VectorXd u = Eigen::VectorXd::Zero(FirstOrderSystem::kInputSize);
  for (int i = 0; i < 100; ++i) {
    const Eigen::Vector2d e(rng.uniform(-10, 10), rng.uniform(-100, 100));
    const Eigen::VectorXd x = state(s, e(0), e(1));
    s.flow(0.0, x, u, dxdt);
    const Eigen::Vector2d e_dot(dxdt(FirstOrderSystem::kZ),
                                dxdt(FirstOrderSystem::kD) - dxdt(FirstOrderSystem::kDHat));
    // ẋ = Ax (5.11); a few roundings of numbers ≤ 100: 1e-12 absolute.
    EXPECT_LT((e_dot - p.A() * e).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_EQ(dxdt(FirstOrderSystem::kD), 0.0);
    EXPECT_EQ(dxdt(FirstOrderSystem::kLastJump), 0.0);
  }
}

TEST(FirstOrderSystem, NoJumpResponseMatchesClosedForm) {
  FirstOrderParams p;
  p.jump_set = JumpSet::kNone;
  const FirstOrderSystem s(p);
  sim::SimulatorOptions o;
  o.dt = 1e-3;
  o.end_time = 10.0;
  sim::Simulator sim(s, o);
  const Eigen::Vector2d e0(0.0, 100.0);  // just after a disturbance step of 100
  const sim::SimResult r = sim.run(state(s, e0(0), e0(1)));
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_TRUE(r.jump_times.empty());
  const Eigen::Vector2d expected = expm(p.A(), 10.0) * e0;
  // RK4 with h·|λ_max| = 1e-3·9.9 ≈ 0.01 has a relative global error ~1e-10 over 10⁴ steps;
  // 1e-7 of the step size (100) leaves room for rounding and still catches any model error.
  EXPECT_NEAR(s.errors(r.final_state)(0), expected(0), 1e-5);
  EXPECT_NEAR(s.errors(r.final_state)(1), expected(1), 1e-5);
}

TEST(FirstOrderSystem, JumpMapIsOmega) {
  const FirstOrderSystem s(FirstOrderParams{});
  const Eigen::VectorXd x = state(s, 2.0, 50.0, 0.0);
  Eigen::VectorXd x_plus(FirstOrderSystem::kStateSize);
  s.jump(7.5, x, Eigen::VectorXd::Zero(2), x_plus);
  // (5.12): x₁⁺ = x₁, x₂⁺ = x₂ − λx₁ = 50 − 3·2.
  EXPECT_DOUBLE_EQ(s.errors(x_plus)(0), 2.0);
  EXPECT_DOUBLE_EQ(s.errors(x_plus)(1), 44.0);
  EXPECT_DOUBLE_EQ(x_plus(FirstOrderSystem::kD), x(FirstOrderSystem::kD));  // d is not touched
  EXPECT_DOUBLE_EQ(x_plus(FirstOrderSystem::kLastJump), 7.5);
}

TEST(FirstOrderSystem, JumpsInTheIdealSetDecreaseV) {
  // (5.21): V(g(x)) − V(x) ≤ −σ|x|² on D, here with σ = 0.5, over random states.
  FirstOrderParams p;
  p.sigma = 0.5;
  const FirstOrderSystem s(p);
  sim::Rng rng(11);
  int in_d = 0;
  Eigen::VectorXd x_plus(FirstOrderSystem::kStateSize);
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Vector2d e(rng.uniform(-20, 20), rng.uniform(-200, 200));
    if (!s.in_ideal_jump_set(e)) continue;
    ++in_d;
    s.jump(0.0, state(s, e(0), e(1)), Eigen::VectorXd::Zero(2), x_plus);
    const Eigen::Vector2d e_plus = s.errors(x_plus);
    // V is ≤ ~4e4 here; differences of such numbers are exact to ~1e-11.
    EXPECT_LE(s.lyapunov(e_plus) - s.lyapunov(e), -p.sigma * e.squaredNorm() + 1e-9)
        << "x = (" << e(0) << ", " << e(1) << ")";
  }
  EXPECT_GT(in_d, 2000);  // the property was exercised on many states
}

TEST(FirstOrderSystem, IdealSetIsExactlyWhereAJumpDoesNotRaiseV) {
  // With σ = 0, (5.20) is {|x₁| ≥ ε, γx₁² − βx₁x₂ ≤ 0} = {|x₁| ≥ ε, ΔV ≤ 0} (5.28): the set is
  // not merely safe but the largest safe set of its form.
  const FirstOrderSystem s(FirstOrderParams{});
  sim::Rng rng(12);
  Eigen::VectorXd x_plus(FirstOrderSystem::kStateSize);
  int in_d = 0, out_d = 0;
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Vector2d e(rng.uniform(-20, 20), rng.uniform(-200, 200));
    if (std::abs(e(0)) < s.params().epsilon) continue;
    s.jump(0.0, state(s, e(0), e(1)), Eigen::VectorXd::Zero(2), x_plus);
    const double dv = s.lyapunov(s.errors(x_plus)) - s.lyapunov(e);
    if (std::abs(dv) < 1e-8) continue;  // on the boundary up to rounding
    EXPECT_EQ(s.in_ideal_jump_set(e), dv < 0.0) << "x = (" << e(0) << ", " << e(1) << ")";
    (dv < 0.0 ? in_d : out_d)++;
  }
  EXPECT_GT(in_d, 1000);
  EXPECT_GT(out_d, 1000);
}

TEST(FirstOrderSystem, SampledSetWithTheExactDerivativeIsTheIdealSet) {
  FirstOrderParams p;
  p.jump_set = JumpSet::kSampled;
  p.sigma = 0.01;  // exercises the σx₂² term with x̂₂ in place of x₂
  const FirstOrderSystem s(p);
  sim::Rng rng(13);
  Eigen::VectorXd u(FirstOrderSystem::kInputSize);
  int agree = 0;
  for (int i = 0; i < 5000; ++i) {
    const Eigen::Vector2d e(rng.uniform(-20, 20), rng.uniform(-200, 200));
    const double x1_dot = (p.A() * e)(0);  // ẋ₁ = −a′x₁ + x₂
    // Skip states within rounding of the boundary, where the two evaluations may round apart.
    const double margin =
        e(0) * e(1) -
        ((s.check().gamma + p.sigma) * e(0) * e(0) + p.sigma * e(1) * e(1)) / s.check().beta;
    if (std::abs(margin) < 1e-9) continue;
    u << x1_dot, 0.0;
    EXPECT_EQ(s.in_jump_set(0.0, state(s, e(0), e(1), 0.0), u), s.in_ideal_jump_set(e));
    ++agree;
  }
  EXPECT_GT(agree, 4000);
}

TEST(FirstOrderSystem, SampledSetNeedsAnEstimateNewerThanTheLastJump) {
  FirstOrderParams p;
  p.jump_set = JumpSet::kSampled;
  const FirstOrderSystem s(p);
  const Eigen::Vector2d e(2.0, 50.0);  // deep inside D
  const double x1_dot = (p.A() * e)(0);
  Eigen::VectorXd u(FirstOrderSystem::kInputSize);
  u << x1_dot, 4.0;
  EXPECT_TRUE(s.in_jump_set(5.0, state(s, e(0), e(1), 4.0), u));    // sample at the jump: ok
  EXPECT_FALSE(s.in_jump_set(5.0, state(s, e(0), e(1), 4.01), u));  // straddles the jump
  u(FirstOrderSystem::kOlderSampleTime) = kNaN;                     // no estimate yet
  EXPECT_FALSE(s.in_jump_set(5.0, state(s, e(0), e(1), 0.0), u));
}

TEST(FirstOrderSystem, ConventionalNeverJumps) {
  FirstOrderParams p;
  p.jump_set = JumpSet::kNone;
  const FirstOrderSystem s(p);
  EXPECT_FALSE(s.in_jump_set(0.0, state(s, 2.0, 50.0), Eigen::VectorXd::Zero(2)));
  EXPECT_TRUE(s.in_ideal_jump_set({2.0, 50.0}));
}

TEST(FirstOrderSystem, RefusesConfigurationsOutsideTheorem6) {
  FirstOrderParams p;
  p.ki = 30.0;  // the thesis P no longer decreases in flow
  EXPECT_THROW(
      {
        try {
          FirstOrderSystem s(p);
        } catch (const std::invalid_argument& e) {
          EXPECT_THAT(e.what(), HasSubstr("(5.24)"));
          throw;
        }
      },
      std::invalid_argument);
  p = FirstOrderParams{};
  p.a = -1.0;
  EXPECT_THROW(FirstOrderSystem{p}, std::invalid_argument);
  p = FirstOrderParams{};
  p.lambda = 0.0;
  EXPECT_THROW(FirstOrderSystem{p}, std::invalid_argument);
}

TEST(FirstOrderSystem, InitialStateIsAtRest) {
  const FirstOrderSystem s(FirstOrderParams{});
  const Eigen::VectorXd x = s.initial_state(5.0, 1.0);
  EXPECT_EQ(s.errors(x), Eigen::Vector2d::Zero());
  EXPECT_EQ(x(FirstOrderSystem::kD), 5.0);
  EXPECT_EQ(x(FirstOrderSystem::kLastJump), 1.0);
}

}  // namespace
}  // namespace dynpos::hybrid
