#include "dynpos/hybrid/case_study.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace dynpos::hybrid {
namespace {

using ::testing::HasSubstr;

// e^{At} for a 2×2 A with distinct real eigenvalues (Sylvester's formula).
Eigen::Matrix2d expm(const Eigen::Matrix2d& A, double t) {
  const double tr = A.trace();
  const double disc = std::sqrt(tr * tr / 4.0 - A.determinant());
  const double r1 = tr / 2.0 + disc;
  const double r2 = tr / 2.0 - disc;
  const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
  return (A - r2 * I) * std::exp(r1 * t) / (r1 - r2) + (A - r1 * I) * std::exp(r2 * t) / (r2 - r1);
}

FirstOrderCaseOptions first_order(JumpSet jump_set) {
  FirstOrderCaseOptions o;
  o.params.jump_set = jump_set;
  return o;
}

DpCaseOptions dp(JumpSet jump_set) {
  DpCaseOptions o;
  o.params.jump_set = jump_set;
  return o;
}

// The case studies are deterministic and take tens of milliseconds; run each once.
const CaseResult& fo_conventional() {
  static const CaseResult r = run_first_order_case(first_order(JumpSet::kNone));
  return r;
}
const CaseResult& fo_hybrid() {
  static const CaseResult r = run_first_order_case(first_order(JumpSet::kIdeal));
  return r;
}
const CaseResult& dp_conventional() {
  static const CaseResult r = run_dp_case(dp(JumpSet::kNone));
  return r;
}
const CaseResult& dp_hybrid() {
  static const CaseResult r = run_dp_case(dp(JumpSet::kIdeal));
  return r;
}
const CaseResult& dp_sampled() {
  static const CaseResult r = run_dp_case(dp(JumpSet::kSampled));
  return r;
}

TEST(FirstOrderCase, ConventionalMatchesTheClosedFormLinearResponse) {
  const CaseResult& r = fo_conventional();
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.metrics.jumps, 0);
  EXPECT_FALSE(r.metrics.v_increase_at_jumps.has_value());
  const Eigen::Matrix2d A = FirstOrderParams{}.A();
  const std::vector<double>& x1 = r.trace.values("x1");
  const std::vector<double>& x2 = r.trace.values("x2");
  // Superposition of the two steps: x(t) = Σ e^{A(t − tᵢ)}(0, Δᵢ) for tᵢ ≤ t. At a step the
  // trace has two rows at the same instant: the first is the state just before the step.
  double worst = 0.0;
  int before_rows = 0;
  for (std::size_t i = 0; i < r.trace.size(); ++i) {
    const double t = r.trace.t[i];
    const bool before = i + 1 < r.trace.size() && r.trace.t[i + 1] == t;
    before_rows += before;
    const auto stepped = [&](double ts) { return before ? t > ts : t >= ts; };
    Eigen::Vector2d expected = Eigen::Vector2d::Zero();
    if (stepped(5.0)) expected += expm(A, t - 5.0) * Eigen::Vector2d(0.0, 100.0);
    if (stepped(30.0)) expected += expm(A, t - 30.0) * Eigen::Vector2d(0.0, -50.0);
    worst = std::max(worst, std::abs(x1[i] - expected(0)));
    worst = std::max(worst, std::abs(x2[i] - expected(1)));
  }
  // RK4 at h·|λ_max| ≈ 0.01 over 6·10⁴ steps: relative error ~1e-10 of the step size 100;
  // 1e-6 absolute still fails for any error in the model or in the event timing.
  EXPECT_LT(worst, 1e-6);
  EXPECT_EQ(before_rows, 2);  // one pair of rows per step, none for jumps (there are none)
}

TEST(FirstOrderCase, HybridSettlesMuchFasterThanConventional) {
  const CaseResult& h = fo_hybrid();
  const CaseResult& c = fo_conventional();
  ASSERT_TRUE(h.ok()) << h.message;
  ASSERT_EQ(h.metrics.settle_s.size(), 2u);
  ASSERT_EQ(c.metrics.settle_s.size(), 2u);
  // Conventional: the slow closed-loop pole is −0.101 1/s, so 5 % takes ln(20)/0.101 ≈ 30 s,
  // longer than the 25 s before the second step.
  EXPECT_FALSE(c.metrics.settle_s[0].has_value());
  EXPECT_GT(c.metrics.residual[0], 0.05);
  for (int i = 0; i < 2; ++i) {
    ASSERT_TRUE(h.metrics.settle_s[i].has_value());
    EXPECT_LT(*h.metrics.settle_s[i], 2.0) << "step " << i;
    const double conventional = c.metrics.settle_s[i].value_or(25.0);  // window length if none
    EXPECT_LT(*h.metrics.settle_s[i], 0.1 * conventional) << "step " << i;
  }
  EXPECT_LT(h.metrics.iae, 0.1 * c.metrics.iae);
  EXPECT_LT(h.metrics.peak_error, c.metrics.peak_error);
  EXPECT_GT(h.metrics.jumps, 2);
  EXPECT_TRUE(std::isnan(h.metrics.heading_iae));
}

TEST(FirstOrderCase, IdealJumpsNeverRaiseVAndRespectTheDwellTime) {
  const CaseResult& h = fo_hybrid();
  ASSERT_TRUE(h.metrics.v_increase_at_jumps.has_value());
  // Theorem 6 with σ = 0: V(g) ≤ V. Rounding of V ≤ 1e4 is ~1e-12.
  EXPECT_LE(*h.metrics.v_increase_at_jumps, 1e-9);
  for (std::size_t i = 1; i < h.jump_times.size(); ++i) {
    EXPECT_GE(h.jump_times[i] - h.jump_times[i - 1], 0.1 - 1e-9);
  }
  // Each jump adds two rows at its instant: before and after.
  int pairs = 0;
  for (std::size_t i = 1; i < h.trace.size(); ++i) pairs += h.trace.t[i] == h.trace.t[i - 1];
  EXPECT_GE(pairs, h.metrics.jumps);
}

TEST(FirstOrderCase, SampledWithHeavyNoiseDiffersAndStaysDeterministic) {
  FirstOrderCaseOptions o = first_order(JumpSet::kSampled);
  o.timing.noise_power = 100.0;  // σ ≈ 58 on ẋ₁: of the order of a′x₁ itself
  o.timing.seed = 7;
  const CaseResult a = run_first_order_case(o);
  const CaseResult b = run_first_order_case(o);
  o.timing.seed = 8;
  const CaseResult c = run_first_order_case(o);
  EXPECT_EQ(a.jump_times, b.jump_times);
  EXPECT_EQ(a.trace.values("x2"), b.trace.values("x2"));  // bit-identical
  EXPECT_NE(a.jump_times, c.jump_times);
  EXPECT_NE(a.jump_times, fo_hybrid().jump_times);
}

TEST(FirstOrderCase, ThesisSampledCaseIsCloseToIdeal) {
  // With the thesis noise (power 0.1) the sampled jump set loses little (section 5.4).
  const CaseResult s = run_first_order_case(first_order(JumpSet::kSampled));
  ASSERT_TRUE(s.ok());
  for (int i = 0; i < 2; ++i) {
    ASSERT_TRUE(s.metrics.settle_s[i].has_value());
    EXPECT_LT(*s.metrics.settle_s[i], 2.0 * *fo_hybrid().metrics.settle_s[i] + 0.1);
  }
}

TEST(DpCase, HybridSettlesMuchFasterThanConventional) {
  const CaseResult& h = dp_hybrid();
  const CaseResult& c = dp_conventional();
  ASSERT_TRUE(h.ok()) << h.message;
  ASSERT_TRUE(c.ok()) << c.message;
  EXPECT_EQ(c.metrics.jumps, 0);
  // Conventional: x₃ decays with the slow rate K_i/(K_d + 1/K_p) ≈ 0.02 1/s (time constant
  // ~50 s), so 50 s after the step about e^{-1} ≈ 37 % is left.
  EXPECT_FALSE(c.metrics.settle_s[0].has_value());
  EXPECT_GT(c.metrics.residual[0], 0.2);
  ASSERT_TRUE(h.metrics.settle_s[0].has_value());
  EXPECT_LT(*h.metrics.settle_s[0], 10.0);
  EXPECT_LT(h.metrics.residual[0], 0.01);
  EXPECT_LT(h.metrics.iae, 0.2 * c.metrics.iae);
  EXPECT_GT(h.metrics.jumps, 10);
  EXPECT_EQ(h.error_unit, "m");
}

TEST(DpCase, IdealJumpsNeverRaiseV) {
  const CaseResult& h = dp_hybrid();
  ASSERT_TRUE(h.metrics.v_increase_at_jumps.has_value());
  // Theorem 7 with σ = 0: V(g) ≤ V; V ≤ 1e6 rounds at ~1e-10.
  EXPECT_LE(*h.metrics.v_increase_at_jumps, 1e-12 * h.metrics.v_max + 1e-9);
}

TEST(DpCase, SampledIsCloseToIdealAndDeterministic) {
  const CaseResult& s = dp_sampled();
  ASSERT_TRUE(s.ok()) << s.message;
  ASSERT_TRUE(s.metrics.settle_s[0].has_value());
  EXPECT_LT(*s.metrics.settle_s[0], 2.0 * *dp_hybrid().metrics.settle_s[0]);
  const CaseResult again = run_dp_case(dp(JumpSet::kSampled));
  EXPECT_EQ(again.jump_times, s.jump_times);
  EXPECT_EQ(again.trace.values("x3.north"), s.trace.values("x3.north"));
  DpCaseOptions other = dp(JumpSet::kSampled);
  other.timing.seed = 2;
  EXPECT_NE(run_dp_case(other).jump_times, s.jump_times);
}

TEST(DpCase, JumpFrameDecidesWhetherHeadingMatters) {
  // At ψ_d = 180° the NED rule behaves as at 0°; the literal (5.47) never jumps, because
  // x₂ (BODY) and x₃ (NED) point in opposite directions there.
  DpCaseOptions o = dp(JumpSet::kIdeal);
  o.params.eta_d.z() = std::numbers::pi;
  const CaseResult ned = run_dp_case(o);
  ASSERT_TRUE(ned.metrics.settle_s[0].has_value());
  EXPECT_NEAR(*ned.metrics.settle_s[0], *dp_hybrid().metrics.settle_s[0], 0.05);
  o.params.jump_frame = JumpFrame::kThesisLiteral;
  const CaseResult literal = run_dp_case(o);
  EXPECT_EQ(literal.metrics.jumps, 0);
  EXPECT_FALSE(literal.metrics.settle_s[0].has_value());
}

TEST(CaseOptions, RejectsBadOptions) {
  FirstOrderCaseOptions o;
  o.steps = {{70.0, 1.0}};  // after the end
  EXPECT_THROW(run_first_order_case(o), std::invalid_argument);
  o = FirstOrderCaseOptions{};
  o.steps = {{5.0005, 1.0}};  // off the 1 ms grid
  EXPECT_THROW(run_first_order_case(o), std::invalid_argument);
  o = FirstOrderCaseOptions{};
  o.steps = {{30.0, 1.0}, {5.0, 1.0}};  // out of order
  EXPECT_THROW(run_first_order_case(o), std::invalid_argument);
  o = FirstOrderCaseOptions{};
  o.timing.sample_period_s = 0.0305;
  EXPECT_THROW(run_first_order_case(o), std::invalid_argument);
  o = FirstOrderCaseOptions{};
  o.params.ki = 30.0;  // Theorem 6 fails with the thesis P
  try {
    run_first_order_case(o);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("(5.24)"));
  }
  DpCaseOptions d;
  d.steps = {{10.0, Eigen::Vector3d::Zero()}};
  EXPECT_THROW(run_dp_case(d), std::invalid_argument);
  d = DpCaseOptions{};
  d.timing.settle_band = 1.5;
  EXPECT_THROW(run_dp_case(d), std::invalid_argument);
}

}  // namespace
}  // namespace dynpos::hybrid
