#include "dynpos/hybrid/dp_hybrid_system.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "dynpos/core/rotation.hpp"
#include "dynpos/sim/random.hpp"

namespace dynpos::hybrid {
namespace {

using ::testing::HasSubstr;
using Index = DpHybridSystem::StateIndex;

constexpr double kPi = std::numbers::pi;

// A random plant state: any heading (including near ±π), a heading error within ±2 rad of the
// set point (away from the wrap of (−π, π]), and moderate velocities and biases.
Eigen::VectorXd random_state(const DpHybridSystem& s, sim::Rng& rng) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(Index::kStateSize);
  const Eigen::Vector3d eta_d = s.params().eta_d;
  x(Index::kEta + 0) = eta_d(0) + rng.uniform(-5, 5);
  x(Index::kEta + 1) = eta_d(1) + rng.uniform(-5, 5);
  x(Index::kEta + 2) = eta_d(2) + rng.uniform(-2, 2);
  for (int i = 0; i < 3; ++i) {
    x(Index::kNu + i) = rng.uniform(-2, 2);
    x(Index::kBiasHat + i) = rng.uniform(-3000, 3000);
    x(Index::kBias + i) = rng.uniform(-3000, 3000);
  }
  return x;
}

// A state in which the integral error points roughly along the jump direction, so that many of
// them fall in D: x₃ = K_i·(c·w + noise) with w the jump direction.
Eigen::VectorXd aligned_state(const DpHybridSystem& s, sim::Rng& rng) {
  Eigen::VectorXd x = random_state(s, rng);
  const DpErrors e = s.errors(x);
  const Eigen::Vector3d w = s.jump_direction(e);
  Eigen::Vector3d noise(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
  const Eigen::Vector3d x3 =
      s.params().controller.Ki * (rng.uniform(0.0, 40.0) * w + 5.0 * noise.cwiseProduct(w));
  x.segment<3>(Index::kBias) = x.segment<3>(Index::kBiasHat) + x3;
  return x;
}

DpHybridParams params_at(double psi_d, JumpSet jump_set = JumpSet::kIdeal) {
  DpHybridParams p;
  p.eta_d = Eigen::Vector3d(10.0, -4.0, psi_d);
  p.jump_set = jump_set;
  return p;
}

double V(const DpHybridSystem& s, const Eigen::VectorXd& x) { return s.lyapunov(s.errors(x)); }

TEST(DpHybridSystem, CaseStudyController) {
  const control::DpControllerParams p = case_study_dp_controller();
  EXPECT_EQ(p.M.diagonal(), Eigen::Vector3d(450, 450, 100));   // (5.84)
  EXPECT_EQ(p.Kp.diagonal(), Eigen::Vector3d(100, 100, 50));   // (5.85)
  EXPECT_EQ(p.Ki.diagonal(), Eigen::Vector3d(10, 10, 5));      // (5.86)
  EXPECT_EQ(p.Kd.diagonal(), Eigen::Vector3d(500, 500, 200));  // (5.87)
}

TEST(DpHybridSystem, FlowDecreasesVAsTheorem7Says) {
  // Along the flow of plant + controller, V̇ = −x₁ᵀK_p x₁ − x₂ᵀK_d x₂ (5.57), at any heading.
  for (const double psi_d : {0.0, 1.0, kPi - 0.5, -kPi + 0.3}) {
    const DpHybridSystem s(params_at(psi_d));
    const Eigen::Matrix3d& Kp = s.params().controller.Kp;
    const Eigen::Matrix3d& Kd = s.params().controller.Kd;
    sim::Rng rng(21);
    Eigen::VectorXd f(Index::kStateSize);
    const Eigen::VectorXd u = Eigen::VectorXd::Zero(DpHybridSystem::kInputSize);
    for (int i = 0; i < 200; ++i) {
      const Eigen::VectorXd x = random_state(s, rng);
      s.flow(0.0, x, u, f);
      const DpErrors e = s.errors(x);
      const double expected = -e.x1.dot(Kp * e.x1) - e.x2.dot(Kd * e.x2);
      // Central difference of V along f with step h: truncation O(h²·V‴) and rounding
      // ~1e-16·V/h. V ≲ 2e6 and |V̇| ≲ 1e4 here; h = 1e-6 s keeps both below ~1e-3, so
      // 1e-6·|V̇| + 1e-3 is a tight bound that any modelling error (a wrong sign, a missing
      // rotation) exceeds by orders of magnitude.
      const double h = 1e-6;
      const double numeric = (V(s, x + h * f) - V(s, x - h * f)) / (2.0 * h);
      EXPECT_NEAR(numeric, expected, 1e-6 * std::abs(expected) + 1e-3) << "psi_d " << psi_d;
      EXPECT_LE(expected, 0.0);
    }
  }
}

TEST(DpHybridSystem, ClosedLoopIsTheThesisErrorDynamics) {
  // (5.44): M ẋ₂ = −x₁ − K_d x₂ + R(ψ)ᵀx₃ and (5.45): ẋ₃ = −K_i R(ψ) x₂, checked by central
  // differences of the errors along the flow.
  const DpHybridSystem s(params_at(0.7));
  const control::DpControllerParams& p = s.params().controller;
  sim::Rng rng(22);
  Eigen::VectorXd f(Index::kStateSize);
  const Eigen::VectorXd u = Eigen::VectorXd::Zero(DpHybridSystem::kInputSize);
  for (int i = 0; i < 200; ++i) {
    const Eigen::VectorXd x = random_state(s, rng);
    s.flow(0.0, x, u, f);
    const DpErrors e = s.errors(x);
    const double h = 1e-6;
    const DpErrors ep = s.errors(x + h * f);
    const DpErrors em = s.errors(x - h * f);
    const Eigen::Vector3d x2_dot = (ep.x2 - em.x2) / (2.0 * h);
    const Eigen::Vector3d x3_dot = (ep.x3 - em.x3) / (2.0 * h);
    const Eigen::Matrix3d R = core::R_yaw(e.psi);
    const Eigen::Vector3d lhs = p.M * x2_dot;
    const Eigen::Vector3d rhs = -e.x1 - p.Kd * e.x2 + R.transpose() * e.x3;
    // Forces up to ~5e3 N; central-difference rounding ~1e-16·3000/1e-6 ≈ 3e-7, times M ≤ 450.
    EXPECT_LT((lhs - rhs).cwiseAbs().maxCoeff(), 1e-3 + 1e-7 * rhs.norm());
    EXPECT_LT((x3_dot + p.Ki * R * e.x2).cwiseAbs().maxCoeff(), 1e-5);
  }
}

TEST(DpHybridSystem, JumpNeverIncreasesVInsideTheJumpSet) {
  // The property of Theorem 7 with dynpos' frame choice, over many random states in D of
  // every heading: V(g(x)) ≤ V(x), and with σ > 0, V(g(x)) − V(x) ≤ −(σ/2)|x|².
  for (const double sigma : {0.0, 1e-3}) {
    for (const double psi_d : {0.0, kPi / 2.0, kPi, -2.5}) {
      DpHybridParams p = params_at(psi_d);
      p.sigma = sigma;
      const DpHybridSystem s(p);
      sim::Rng rng(23);
      Eigen::VectorXd x_plus(Index::kStateSize);
      const Eigen::VectorXd u = Eigen::VectorXd::Zero(DpHybridSystem::kInputSize);
      int in_d = 0;
      for (int i = 0; i < 4000; ++i) {
        const Eigen::VectorXd x = (i % 2 == 0) ? aligned_state(s, rng) : random_state(s, rng);
        const DpErrors e = s.errors(x);
        if (!s.in_ideal_jump_set(e)) continue;
        ASSERT_TRUE(s.in_jump_set(0.0, x, u));
        ++in_d;
        s.jump(1.0, x, u, x_plus);
        const double v = V(s, x);
        const double dv = V(s, x_plus) - v;
        const double size2 = e.x1.squaredNorm() + e.x2.squaredNorm() + e.x3.squaredNorm();
        // V ≲ 1e6: its rounding is ≲ 1e-10; 1e-12·V + 1e-9 bounds the difference of two
        // such numbers.
        EXPECT_LE(dv, -0.5 * sigma * size2 + 1e-12 * v + 1e-9)
            << "psi_d " << psi_d << " sigma " << sigma;
        // x₁ and x₂ do not change at a jump; only b̂ and t_J do.
        EXPECT_EQ(x_plus.head<6>(), x.head<6>());
        EXPECT_EQ(x_plus.segment<3>(Index::kBias), x.segment<3>(Index::kBias));
        EXPECT_EQ(x_plus(Index::kLastJump), 1.0);
      }
      EXPECT_GT(in_d, 500) << "psi_d " << psi_d;
    }
  }
}

TEST(DpHybridSystem, JumpChangesVByTheClosedForm) {
  // V(g) − V = −λwᵀK_i⁻¹x₃ + ½λ²wᵀK_i⁻¹w for any state (in D or not).
  const DpHybridSystem s(params_at(2.0));
  const double lambda = s.params().lambda;
  const Eigen::Matrix3d Ki_inv = s.params().controller.Ki.inverse();
  sim::Rng rng(24);
  Eigen::VectorXd x_plus(Index::kStateSize);
  for (int i = 0; i < 200; ++i) {
    const Eigen::VectorXd x = random_state(s, rng);
    s.jump(0.0, x, Eigen::VectorXd::Zero(4), x_plus);
    const DpErrors e = s.errors(x);
    const Eigen::Vector3d w = core::R_yaw(e.psi) * e.x2;
    const double expected =
        -lambda * w.dot(Ki_inv * e.x3) + 0.5 * lambda * lambda * w.dot(Ki_inv * w);
    EXPECT_NEAR(V(s, x_plus) - V(s, x), expected, 1e-9 * V(s, x) + 1e-9);
  }
}

TEST(DpHybridSystem, IdealSetIsWhereAJumpDoesNotRaiseV) {
  // With σ = 0 and |x₁| ≥ ε₁, |x₂| ≥ ε₂, D is exactly {ΔV ≤ 0}, for both frame choices (each
  // is consistent with its own jump map).
  for (const JumpFrame frame : {JumpFrame::kNed, JumpFrame::kThesisLiteral}) {
    DpHybridParams p = params_at(1.2);
    p.jump_frame = frame;
    const DpHybridSystem s(p);
    sim::Rng rng(25);
    Eigen::VectorXd x_plus(Index::kStateSize);
    int in_d = 0, out_d = 0;
    for (int i = 0; i < 4000; ++i) {
      const Eigen::VectorXd x = (i % 2 == 0) ? aligned_state(s, rng) : random_state(s, rng);
      s.jump(0.0, x, Eigen::VectorXd::Zero(4), x_plus);
      const double dv = V(s, x_plus) - V(s, x);
      if (std::abs(dv) < 1e-6) continue;  // on the boundary up to rounding
      EXPECT_EQ(s.in_ideal_jump_set(s.errors(x)), dv < 0.0);
      (dv < 0.0 ? in_d : out_d)++;
    }
    EXPECT_GT(in_d, 500);
    EXPECT_GT(out_d, 500);
  }
}

TEST(DpHybridSystem, JumpMovesTheBiasEstimateInNed) {
  // Heading east (ψ = 90°), a pure surge velocity error: the vessel is pushed ahead, i.e. east,
  // so the bias estimate must grow eastwards. The literal (5.47) would move it north.
  for (const JumpFrame frame : {JumpFrame::kNed, JumpFrame::kThesisLiteral}) {
    DpHybridParams p = params_at(kPi / 2.0);
    p.jump_frame = frame;
    const DpHybridSystem s(p);
    Eigen::VectorXd x = s.initial_state();
    x(Index::kNu + 0) = 0.2;  // u = 0.2 m/s at the set point: x₁ = 0, μ = 0, x₂ = (0.2, 0, 0)
    Eigen::VectorXd x_plus(Index::kStateSize);
    s.jump(0.0, x, Eigen::VectorXd::Zero(4), x_plus);
    const Eigen::Vector3d step = x_plus.segment<3>(Index::kBiasHat) - x.segment<3>(Index::kBiasHat);
    const Eigen::Vector3d expected =
        frame == JumpFrame::kNed ? Eigen::Vector3d(0.0, 5.0, 0.0) : Eigen::Vector3d(5.0, 0.0, 0.0);
    // λ·0.2 = 5 N; cos(π/2) ≈ 6e-17 leaves a rounding of ~1e-15 in the other component.
    EXPECT_LT((step - expected).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(DpHybridSystem, SampledSetEstimatesTheIntegralError) {
  // (5.64): x̂₃ = R(ψ)(M ẋ₂ + x₁ + K_d x₂) recovers x₃ from the true ẋ₂ (here from central
  // differences along the flow), and the sampled set then agrees with the ideal one.
  const DpHybridSystem ideal(params_at(-1.0));
  const DpHybridSystem sampled(params_at(-1.0, JumpSet::kSampled));
  sim::Rng rng(26);
  Eigen::VectorXd f(Index::kStateSize);
  Eigen::VectorXd u(DpHybridSystem::kInputSize);
  int compared = 0;
  for (int i = 0; i < 2000; ++i) {
    const Eigen::VectorXd x = (i % 2 == 0) ? aligned_state(ideal, rng) : random_state(ideal, rng);
    ideal.flow(0.0, x, Eigen::VectorXd::Zero(4), f);
    const double h = 1e-6;
    const Eigen::Vector3d x2_dot =
        (ideal.errors(x + h * f).x2 - ideal.errors(x - h * f).x2) / (2.0 * h);
    const DpErrors e = ideal.errors(x);
    const Eigen::Vector3d x3_hat = ideal.estimate_x3(e, x2_dot);
    // |x₃| ≲ 6e3 N; the difference quotient carries ~3e-7 m/s² of rounding, times M = 450.
    EXPECT_LT((x3_hat - e.x3).cwiseAbs().maxCoeff(), 1e-3);
    // Away from the boundary the decisions agree.
    const Eigen::Vector3d w = ideal.jump_direction(e);
    const Eigen::Matrix3d Ki_inv = ideal.params().controller.Ki.inverse();
    const double margin = w.dot(Ki_inv * e.x3) - 0.5 * ideal.params().lambda * w.dot(Ki_inv * w);
    if (std::abs(margin) < 1e-3 * (1.0 + w.norm() * e.x3.norm())) continue;
    u << x2_dot, 0.0;
    EXPECT_EQ(sampled.in_jump_set(0.0, x, u), ideal.in_ideal_jump_set(e));
    ++compared;
  }
  EXPECT_GT(compared, 1500);
}

TEST(DpHybridSystem, SampledSetNeedsAFreshEstimate) {
  const DpHybridSystem s(params_at(0.0, JumpSet::kSampled));
  Eigen::VectorXd x = s.initial_state();
  x(Index::kNu + 0) = 0.2;
  x(Index::kEta + 0) += 0.01;
  x(Index::kBias + 0) = 3000.0;  // a large bias step not yet integrated
  x(Index::kLastJump) = 2.0;
  Eigen::VectorXd u(DpHybridSystem::kInputSize);
  // A derivative consistent with x₃ = (3000, 0, 0): M ẋ₂ = −x₁ − K_d x₂ + x₃.
  const DpErrors e = s.errors(x);
  const control::DpControllerParams& p = s.params().controller;
  const Eigen::Vector3d x2_dot = p.M.inverse() * (-e.x1 - p.Kd * e.x2 + e.x3);
  u << x2_dot, 2.0;
  EXPECT_TRUE(s.in_jump_set(3.0, x, u));
  u(DpHybridSystem::kOlderSampleTime) = 1.99;
  EXPECT_FALSE(s.in_jump_set(3.0, x, u));
  u(DpHybridSystem::kOlderSampleTime) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(s.in_jump_set(3.0, x, u));
}

TEST(DpHybridSystem, SmallErrorsBlockJumps) {
  // (5.54): no jump while |x₁| < ε₁ or |x₂| < ε₂, however large x₃.
  const DpHybridSystem s(params_at(0.0));
  Eigen::VectorXd x = s.initial_state();
  const double north_d = x(Index::kEta + 0);
  x(Index::kBias + 0) = 3000.0;
  x(Index::kNu + 0) = 0.5;  // at the set point: x₁ = 0 < ε₁, x₂ = (0.5, 0, 0)
  EXPECT_FALSE(s.in_ideal_jump_set(s.errors(x)));
  x(Index::kEta + 0) = north_d + 1e-3;  // x₁ = (1e-3, 0, 0) ≥ ε₁ …
  x(Index::kNu + 0) = -0.1;             // … and ν = μ = −K_p x₁, so x₂ = 0 < ε₂
  EXPECT_FALSE(s.in_ideal_jump_set(s.errors(x)));
  x(Index::kNu + 0) = 0.5;  // x₂ = (0.6, 0, 0): both large, x₃ along w
  EXPECT_TRUE(s.in_ideal_jump_set(s.errors(x)));
}

TEST(DpHybridSystem, RefusesConfigurationsOutsideTheorem7) {
  DpHybridParams p;
  p.lambda = -1.0;
  EXPECT_THROW(
      {
        try {
          DpHybridSystem s(p);
        } catch (const std::invalid_argument& e) {
          EXPECT_THAT(e.what(), HasSubstr("lambda"));
          throw;
        }
      },
      std::invalid_argument);
  p = DpHybridParams{};
  p.epsilon2 = 0.0;
  EXPECT_THROW(DpHybridSystem{p}, std::invalid_argument);
  p = DpHybridParams{};
  p.eta_d.x() = std::numeric_limits<double>::infinity();
  EXPECT_THROW(DpHybridSystem{p}, std::invalid_argument);
}

}  // namespace
}  // namespace dynpos::hybrid
