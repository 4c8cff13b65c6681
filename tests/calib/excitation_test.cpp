#include "dynpos/calib/excitation.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dynpos/core/rotation.hpp"

namespace dynpos::calib {
namespace {

// Constant yaw rate r with optional roll oscillation of amplitude a [rad] at 2π/6 rad/s.
MotionSeries turning(double r, double roll_amp, double duration_s = 200.0) {
  MotionSeries m;
  for (double t = 0; t <= duration_s + 1e-9; t += 0.1) {
    const double w = 2 * M_PI / 6.0;
    const Eigen::Vector3d th(roll_amp * std::sin(w * t), 0.0, r * t);
    const Eigen::Vector3d thd(roll_amp * w * std::cos(w * t), 0.0, r);
    m.t_s.push_back(t);
    m.theta_rad.push_back(th);
    m.omega_b_rps.push_back(core::euler_rate_matrix_inverse(th(0), th(1)) * thd);
    m.v_b_mps.emplace_back(3.0, 0.0, 0.0);
  }
  return m;
}

TEST(Excitation, VerdictFromStd) {
  EXPECT_EQ(determinacy_from_std(0.005), Determinacy::kWell);
  EXPECT_EQ(determinacy_from_std(0.1), Determinacy::kWeakly);
  EXPECT_EQ(determinacy_from_std(1.0), Determinacy::kNot);
  EXPECT_EQ(determinacy_from_std(NAN), Determinacy::kNot);
  EXPECT_EQ(worse(Determinacy::kWell, Determinacy::kWeakly), Determinacy::kWeakly);
  EXPECT_EQ(determinacy_advice(2, Determinacy::kWeakly),
            "z is weakly determined: more roll or pitch needed");
  EXPECT_TRUE(determinacy_advice(0, Determinacy::kWell).empty());
  VerdictThresholds bad;
  bad.weak_std_m = bad.well_std_m;
  EXPECT_THROW(bad.validate(), std::invalid_argument);
}

TEST(Excitation, PureYawIsNotObservableInZ) {
  // r constant, p = q = 0: S² + Ṡ = S² has rank 2 (Example 1 without ṗ), and SᵀS (4.54) has
  // λ_min = 0 (no p or q): z is not seen. x and y are seen through the rotating heading.
  const ExcitationDiagnostics d = excitation_diagnostics(turning(0.05, 0.0));
  EXPECT_EQ(d.rank3_fraction, 0.0);
  EXPECT_NEAR(d.pe_min_eig_min_rad2ps, 0.0, 1e-12);
  EXPECT_EQ(d.verdict[2], Determinacy::kNot);
  EXPECT_EQ(d.verdict[0], Determinacy::kWell);
  EXPECT_EQ(d.verdict[1], Determinacy::kWell);
  ASSERT_EQ(d.advice.size(), 1U);
  EXPECT_NE(d.advice[0].find("roll or pitch"), std::string::npos);
}

TEST(Excitation, YawWithRollIsObservable) {
  const ExcitationDiagnostics d = excitation_diagnostics(turning(0.05, 0.05));
  // Roll rate amplitude 0.05·2π/6 ≈ 0.052 rad/s: ṗ ≈ 0.055 rad/s² gives S² + Ṡ full rank
  // (Example 1) except near the zero crossings of ṗ.
  EXPECT_GT(d.rank3_fraction, 0.5);
  // (4.55) over 60 s: the p² + r² terms ≈ 60·(0.05²/2·(2π/6)² + ...) > 0; λ_min is the z one,
  // ∫(p² + q²) ≈ 60·0.5·0.052² ≈ 0.08 rad²/s.
  EXPECT_NEAR(d.pe_min_eig_min_rad2ps, 0.08, 0.02);
  EXPECT_TRUE(std::isfinite(d.gramian_condition));
  EXPECT_LT(d.predicted_arm_std_m(2), 0.25);
}

TEST(Excitation, NoRotationAtAllIsNotDetermined) {
  const ExcitationDiagnostics d = excitation_diagnostics(turning(0.0, 0.0, 50.0));
  for (int k = 0; k < 3; ++k) EXPECT_EQ(d.verdict[static_cast<std::size_t>(k)], Determinacy::kNot);
  EXPECT_FALSE(std::isfinite(d.gramian_condition));
  EXPECT_EQ(d.advice.size(), 3U);
}

TEST(Excitation, BadInputThrows) {
  MotionSeries m = turning(0.05, 0.0, 1.0);
  m.omega_b_rps.clear();
  EXPECT_THROW(excitation_diagnostics(m), std::invalid_argument);
  ExcitationOptions o;
  o.window_s = 0.0;
  EXPECT_THROW(o.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace dynpos::calib
