#include "dynpos/hybrid/sampled_integral_jump.hpp"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

#include "dynpos/control/dp_controller.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/sim/sim_time.hpp"

namespace dynpos::hybrid {
namespace {

// A state with a large integral error along north at ψ = 0, x₂ constant (ẋ₂ = 0): x̂₃ =
// x₁ + K_d·x₂ = (1 + 8e4·0.1) N ≈ 8 kN north, well inside the jump set of the defaults
// (K_i⁻¹Δ·x̂₃ = 6·8001 ≥ ½·K_i⁻¹Δ·Δ = 18000 with Δ = Λx₂ = 6 kN).
const Eigen::Vector3d kX1(1.0, 0.0, 0.0);
const Eigen::Vector3d kX2(0.1, 0.0, 0.0);

TEST(SampledIntegralJump, NoJumpBeforeTheSecondSample) {
  SampledIntegralJump rule(IntegralJumpParams{}, control::DpControllerParams{}, 0.1);
  EXPECT_FALSE(rule.step(0.0, kX1, kX2, 0.0).has_value());
  const std::optional<Eigen::Vector3d> jump = rule.step(0.1, kX1, kX2, 0.0);
  ASSERT_TRUE(jump.has_value());
  EXPECT_EQ(*jump, integral_jump(IntegralJumpParams{}, kX2, 0.0));
  EXPECT_NEAR(jump->x(), 6.0e3, 1e-9);
  ASSERT_EQ(rule.jump_times().size(), 1u);
  EXPECT_EQ(rule.jump_times()[0], 0.1);
}

TEST(SampledIntegralJump, JumpsAreADwellTimeApart) {
  IntegralJumpParams p;
  p.dwell_s = 2.0;
  SampledIntegralJump rule(p, control::DpControllerParams{}, 0.1);
  // Control steps on a 0.01 s tick grid, every 10 ticks, the state held in the jump set.
  const sim::TimeGrid grid(0.01);
  for (sim::Tick k = 0; k <= 1000; k += 10) (void)rule.step(grid.time(k), kX1, kX2, 0.0);
  // First at 0.1 s, then every 2 s, compared exactly: where t_k − t_J rounds below 2 s the
  // jump waits for the next control step.
  const std::vector<double>& jumps = rule.jump_times();
  ASSERT_GE(jumps.size(), 4u);
  EXPECT_EQ(jumps[0], grid.time(10));
  for (std::size_t i = 1; i < jumps.size(); ++i) {
    EXPECT_GE(jumps[i] - jumps[i - 1], 2.0) << i;
    EXPECT_LT(jumps[i] - jumps[i - 1], 2.0 + 0.1 + 1e-9) << i;
  }
}

TEST(SampledIntegralJump, TheEstimateOfTheIntegralErrorDecides) {
  // Same x₁ and x₂ now, but x₂ fell fast since the last step: ẋ₂ = −0.2/0.1 = −2 m/s² in
  // surge, so M·ẋ₂ (−9.7e5 N) dominates x̂₃ and points against the jump: no jump.
  SampledIntegralJump falling(IntegralJumpParams{}, control::DpControllerParams{}, 0.1);
  (void)falling.step(0.0, kX1, kX2 + Eigen::Vector3d(0.2, 0.0, 0.0), 0.0);
  EXPECT_FALSE(falling.step(0.1, kX1, kX2, 0.0).has_value());
  // With x₂ rising as fast, x̂₃ points along the jump: a jump.
  SampledIntegralJump rising(IntegralJumpParams{}, control::DpControllerParams{}, 0.1);
  (void)rising.step(0.0, kX1, kX2 - Eigen::Vector3d(0.2, 0.0, 0.0), 0.0);
  EXPECT_TRUE(rising.step(0.1, kX1, kX2, 0.0).has_value());
}

TEST(SampledIntegralJump, JumpIsAlongTheNedVelocityError) {
  // At ψ = 90° a surge error x₂ is a velocity error towards east: Δb̂ = Λ·R(ψ)x₂ points east.
  SampledIntegralJump rule(IntegralJumpParams{}, control::DpControllerParams{}, 0.1);
  const double psi = M_PI / 2;
  const Eigen::Vector3d x1(0.0, -1.0, 0.0);  // BODY offset of 1 m north at this heading
  (void)rule.step(0.0, x1, kX2, psi);
  const std::optional<Eigen::Vector3d> jump = rule.step(0.1, x1, kX2, psi);
  ASSERT_TRUE(jump.has_value());
  EXPECT_NEAR(jump->x(), 0.0, 1e-9);
  EXPECT_NEAR(jump->y(), IntegralJumpParams{}.lambda.y() * 0.1, 1e-9);
}

// The rule step by step as the formulas write it: ẋ₂ by the difference of the last two
// samples over their time difference, x̂₃ by (5.64), the set (5.54)–(5.55), the dwell time.
// Over random states the class takes exactly the same jumps, to the bit.
TEST(SampledIntegralJump, SameJumpsAsTheFormulasOverRandomStates) {
  const IntegralJumpParams p;
  const control::DpControllerParams c;
  SampledIntegralJump rule(p, c, 0.1);
  const sim::TimeGrid grid(0.01);
  std::mt19937_64 engine(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Eigen::Vector3d prev_x2 = Eigen::Vector3d::Zero();
  std::optional<double> prev_t, last_jump;
  int jumps = 0;
  for (sim::Tick k = 0; k <= 20000; k += 10) {
    const double t = grid.time(k);
    const Eigen::Vector3d x1(unit(engine), unit(engine), 0.1 * unit(engine));
    const Eigen::Vector3d x2(0.2 * unit(engine), 0.2 * unit(engine), 0.01 * unit(engine));
    const double psi = M_PI * unit(engine);
    std::optional<Eigen::Vector3d> expected;
    if (prev_t && (!last_jump || (*prev_t >= *last_jump && t - *last_jump >= p.dwell_s))) {
      const Eigen::Vector3d x2_dot = (x2 - prev_x2) / (t - *prev_t);
      const Eigen::Vector3d x3_hat = estimate_integral_error(c.M, c.Kd, x1, x2, x2_dot, psi);
      if (in_integral_jump_set(p, c.Ki, x1, x2, x3_hat, psi)) {
        expected = integral_jump(p, x2, psi);
        last_jump = t;
      }
    }
    prev_x2 = x2;
    prev_t = t;
    const std::optional<Eigen::Vector3d> got = rule.step(t, x1, x2, psi);
    ASSERT_EQ(got.has_value(), expected.has_value()) << "t = " << t;
    if (got) {
      EXPECT_EQ(*got, *expected);
      ++jumps;
    }
  }
  EXPECT_GT(jumps, 10);  // the comparison covers jumps, not only their absence
}

TEST(SampledIntegralJump, RejectsBadParameters) {
  IntegralJumpParams p;
  p.dwell_s = 0.0;
  // The [hybrid] section is user input: InputError naming the key (core/error.hpp).
  EXPECT_THROW(SampledIntegralJump(p, control::DpControllerParams{}, 0.1), core::InputError);
  EXPECT_THROW(SampledIntegralJump(IntegralJumpParams{}, control::DpControllerParams{}, 0.0),
               std::invalid_argument);
}

}  // namespace
}  // namespace dynpos::hybrid
