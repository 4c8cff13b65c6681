#include "dynpos/sim/hybrid_system.hpp"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <vector>

#include "dynpos/sim/simulator.hpp"

namespace dynpos::sim {
namespace {

// Only the required members: the defaults must give C = ℝⁿ, D = ∅, g = identity, no guard.
class Decay final : public HybridSystem {
 public:
  Eigen::Index state_size() const override { return 3; }
  void flow(double, const ConstVectorRef& x, const ConstVectorRef&, VectorRef dxdt) const override {
    dxdt = -x;
  }
};

TEST(HybridSystem, DefaultsAreFlowEverywhereAndNeverJump) {
  const Decay system;
  const Eigen::VectorXd u(0);
  const Eigen::Vector3d cases[] = {Eigen::Vector3d::Zero(), Eigen::Vector3d(1e-300, 0, -1e-300),
                                   Eigen::Vector3d(1.0, -2.0, 3.0),
                                   Eigen::Vector3d::Constant(1e300)};
  for (const Eigen::Vector3d& x : cases) {
    EXPECT_TRUE(system.in_flow_set(0.0, x, u));
    EXPECT_FALSE(system.in_jump_set(0.0, x, u));
    Eigen::VectorXd x_plus = Eigen::VectorXd::Constant(3, -7.0);
    system.jump(0.0, x, u, x_plus);
    EXPECT_EQ(x_plus, Eigen::VectorXd(x));
    EXPECT_EQ(system.guard(0.0, x, u), std::numeric_limits<double>::infinity());
  }
  EXPECT_EQ(system.input_size(), 0);
  EXPECT_FALSE(system.has_guard());
}

// The thesis' first-order system with hybrid integral action, (5.9)–(5.12), case study values
// (5.73)–(5.78): x = (z̃, d̃), ẋ = A·x with A = [−a′ 1; −k_i 0], a′ = 10, k_i = 1; jump map
// x⁺ = Ω·x = (x₁, x₂ − λ·x₁), λ = 3; V = xᵀPx with P = [1 −0.1; −0.1 1]; jump set (5.78) with
// ε = 0.3 and σ = α₃ = 0: D = {|x₁| ≥ 0.3, x₁·x₂ ≥ (γ/β)·x₁²}, β = 2λp₃ = 6, γ = λ²p₃ − 2λp₂ = 9.6.
class HybridIntegralAction final : public HybridSystem {
 public:
  static constexpr double kAPrime = 10.0;
  static constexpr double kKi = 1.0;
  static constexpr double kLambda = 3.0;
  static constexpr double kEpsilon = 0.3;
  static constexpr double kBeta = 6.0;
  static constexpr double kGamma = 9.6;

  explicit HybridIntegralAction(bool jumps) : jumps_(jumps) {}

  Eigen::Index state_size() const override { return 2; }
  void flow(double, const ConstVectorRef& x, const ConstVectorRef&, VectorRef dxdt) const override {
    dxdt(0) = -kAPrime * x(0) + x(1);
    dxdt(1) = -kKi * x(0);
  }
  bool in_jump_set(double, const ConstVectorRef& x, const ConstVectorRef&) const override {
    return jumps_ && std::abs(x(0)) >= kEpsilon && x(0) * x(1) >= (kGamma / kBeta) * x(0) * x(0);
  }
  void jump(double, const ConstVectorRef& x, const ConstVectorRef&,
            VectorRef x_plus) const override {
    x_plus(0) = x(0);
    x_plus(1) = x(1) - kLambda * x(0);
  }

  static double lyapunov(const Eigen::Vector2d& x) {
    Eigen::Matrix2d p;
    p << 1.0, -0.1, -0.1, 1.0;
    return x.dot(p * x);
  }

 private:
  bool jumps_;
};

TEST(HybridSystem, ThesisJumpMapDecreasesLyapunovOnTheJumpSet) {
  // V(g(x)) − V(x) = γ·x₁² − β·x₁·x₂ (5.28), ≤ 0 on D (5.29). Cases: on D's boundary (equality),
  // generic, large, and with x₁ < 0.
  const HybridIntegralAction system(true);
  const Eigen::VectorXd u(0);
  const Eigen::Vector2d in_d[] = {{0.3, 0.48},  {0.3, 5.0}, {1.0, 10.0},
                                  {-1.0, -5.0}, {1e3, 1e5}, {-0.5, -0.8}};
  for (const Eigen::Vector2d& x : in_d) {
    ASSERT_TRUE(system.in_jump_set(0.0, x, u)) << x.transpose();
    Eigen::VectorXd x_plus(2);
    system.jump(0.0, x, u, x_plus);
    const double dv = HybridIntegralAction::lyapunov(x_plus) - HybridIntegralAction::lyapunov(x);
    const double expected =
        HybridIntegralAction::kGamma * x(0) * x(0) - HybridIntegralAction::kBeta * x(0) * x(1);
    // Both sides are sums of a few products of size ~V; rounding is ~1e-15·V.
    const double rounding = 1e-13 * (1.0 + HybridIntegralAction::lyapunov(x));
    EXPECT_NEAR(dv, expected, rounding) << x.transpose();
    EXPECT_LE(dv, rounding) << x.transpose();
  }
  const Eigen::Vector2d not_in_d[] = {{0.0, 0.0}, {0.29, 100.0}, {1.0, 1.0}, {-1.0, 1.0}};
  for (const Eigen::Vector2d& x : not_in_d) EXPECT_FALSE(system.in_jump_set(0.0, x, u));
}

TEST(HybridSystem, ThesisHybridIntegralActionBeatsPlainIntegralAction) {
  // Case study 5.3.1: a disturbance step of 100 gives d̃ = 100 at t = 0; dwell time 0.1 s.
  // The plain PI loop (no jumps) removes d̃ on its slow mode, s ≈ −0.1 (τ ≈ 10 s); the jumps
  // cut d̃ by ~30 % per dwell time while |x₁| ≥ ε, so by t = 5 s V must be far smaller.
  SimulatorOptions options;
  options.dt = 0.01;
  options.end_time = 5.0;
  options.dwell_time = 0.1;
  const Eigen::Vector2d x0(0.0, 100.0);

  const HybridIntegralAction hybrid(true);
  Simulator simulator(hybrid, options);
  int jumps = 0;
  simulator.set_jump_observer(
      [&](double, const Eigen::VectorXd& x_minus, const Eigen::VectorXd& x_plus) {
        ++jumps;
        // V(g(x)) ≤ V(x) on D (5.29), up to rounding ~1e-15·V.
        EXPECT_LE(HybridIntegralAction::lyapunov(x_plus),
                  HybridIntegralAction::lyapunov(x_minus) * (1.0 + 1e-13));
      });
  const SimResult with_jumps = simulator.run(x0);
  ASSERT_TRUE(with_jumps.ok()) << with_jumps.message;
  EXPECT_GT(jumps, 3);
  EXPECT_EQ(static_cast<std::size_t>(jumps), with_jumps.jump_times.size());
  for (std::size_t i = 1; i < with_jumps.jump_times.size(); ++i) {
    // Jumps happen at ticks here (no guard), so spacings are multiples of dt ≥ τ_D up to
    // rounding of k·dt (~1e-15 s).
    EXPECT_GE(with_jumps.jump_times[i] - with_jumps.jump_times[i - 1], 0.1 - 1e-12);
  }

  const HybridIntegralAction plain(false);
  const SimResult without_jumps = Simulator(plain, options).run(x0);
  ASSERT_TRUE(without_jumps.ok());
  EXPECT_TRUE(without_jumps.jump_times.empty());
  const double v_hybrid = HybridIntegralAction::lyapunov(with_jumps.final_state);
  const double v_plain = HybridIntegralAction::lyapunov(without_jumps.final_state);
  EXPECT_LT(v_hybrid, 0.01 * v_plain);
}

}  // namespace
}  // namespace dynpos::sim
