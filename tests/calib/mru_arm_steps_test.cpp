// The steps of estimate_mru_arms() on their own: the span used, the residual correlation and the
// excitation G(t) (4.77).

#include "mru_arm_steps.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace dynpos::calib::detail {
namespace {

TEST(MruArmSteps, UsedSpanDropsTheFilterEdges) {
  std::vector<double> t;
  for (int i = 0; i <= 100; ++i) t.push_back(0.1 * i);  // 0 … 10 s
  const SampleSpan s = used_span(t, 2.0);
  // Samples at 2.0 s … 8.0 s are kept (≥ 2 s from each end, up to the rounding of 0.1·i).
  EXPECT_NEAR(t[s.begin], 2.0, 0.1 + 1e-9);
  EXPECT_NEAR(t[s.end - 1], 8.0, 0.1 + 1e-9);
  EXPECT_GE(t[s.begin] - t.front(), 2.0);
  EXPECT_GE(t.back() - t[s.end - 1], 2.0);
  EXPECT_EQ(used_span(t, 0.0).size(), t.size());
  EXPECT_EQ(used_span(t, 6.0).size(), 0U);  // the edges overlap
}

TEST(MruArmSteps, VarianceInflationOfAnAr1Noise) {
  // White noise: ρ ≈ 0, no inflation (±0.05 for 20 000 samples: ρ's 1σ is 1/√(3·20 000)).
  std::mt19937 rng(7);
  std::normal_distribution<double> nd(0.0, 1.0);
  std::vector<Eigen::Vector3d> white(20000);
  for (auto& e : white) e = {nd(rng), nd(rng), nd(rng)};
  EXPECT_NEAR(variance_inflation(white), 1.0, 0.05);
  // AR(1) with φ = 0.5: (1 + φ)/(1 − φ) = 3 (±0.2, the same 1σ of ρ through d/dρ = 8).
  std::vector<Eigen::Vector3d> ar(20000, Eigen::Vector3d::Zero());
  for (std::size_t i = 1; i < ar.size(); ++i) {
    ar[i] = 0.5 * ar[i - 1] + Eigen::Vector3d(nd(rng), nd(rng), nd(rng));
  }
  EXPECT_NEAR(variance_inflation(ar), 3.0, 0.2);
  // Alternating residuals have ρ < 0, clamped to 0; constant ones are capped at ρ = 0.999.
  std::vector<Eigen::Vector3d> alt(100);
  for (std::size_t i = 0; i < alt.size(); ++i) alt[i].setConstant(i % 2 == 0 ? 1.0 : -1.0);
  EXPECT_DOUBLE_EQ(variance_inflation(alt), 1.0);
  const std::vector<Eigen::Vector3d> flat(100, Eigen::Vector3d::Ones());
  EXPECT_NEAR(variance_inflation(flat), 1.999 / 0.001, 1e-6);
  EXPECT_DOUBLE_EQ(variance_inflation({}), 1.0);
}

MruSignals rotating(const Eigen::Vector3d& omega, const Eigen::Vector3d& omega_dot, std::size_t n) {
  MruSignals s;
  for (std::size_t i = 0; i < n; ++i) {
    s.t_s.push_back(0.01 * static_cast<double>(i));
    s.omega_b_rps.push_back(omega);
    s.omega_dot_b.push_back(omega_dot);
    s.omega_ddot_b.push_back(Eigen::Vector3d::Zero());
  }
  return s;
}

TEST(MruArmSteps, GExcitationOfASteadyTurnIsRankDeficient) {
  // A steady turn about z: G = S(ω)³ has rank 2 (Proposition 3 fails: nothing determined).
  MruExcitation steady;
  const MruSignals turn = rotating({0, 0, 0.05}, Eigen::Vector3d::Zero(), 100);
  EXPECT_EQ(g_excitation(turn, {0, 100}, 10, steady), 0);
  EXPECT_EQ(steady.t_s.size(), 10U);
  EXPECT_DOUBLE_EQ(steady.rank3_fraction, 0.0);
  EXPECT_EQ(steady.g_rank.front(), 2);
  // Turning while rolling, with a roll acceleration: G has full rank (its determinant is
  // 1.2e-5 1/s⁹ here).
  MruExcitation rolling;
  const MruSignals roll = rotating({0.1, 0, 0.05}, {0.2, 0, 0}, 100);
  EXPECT_EQ(g_excitation(roll, {0, 100}, 10, rolling), 10);
  EXPECT_DOUBLE_EQ(rolling.rank3_fraction, 1.0);
  EXPECT_GT(rolling.g_min_sv_median, 0.0);
  EXPECT_GE(rolling.g_condition_median, 1.0);
}

}  // namespace
}  // namespace dynpos::calib::detail
