#include "dynpos/ident/thrust_map.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dynpos/core/error.hpp"
#include "synthetic.hpp"

namespace dynpos::ident {
namespace {

using core::InputError;

// Thesis table 3.2, back-calculated: c₊ = 8.13 kN/rps², c₋ = −5.8 kN/rps².
const ThrustMap kTable32{8130.0, -5800.0};

// Shaft speeds spread over ±3 rps (seeded), thrust from the map plus noise σ [N].
void make_log(double sigma, std::vector<double>& n, std::vector<double>& thrust) {
  testing::Normal rng(17);
  n.resize(2000);
  thrust.resize(2000);
  for (std::size_t i = 0; i < n.size(); ++i) {
    n[i] = 6.0 * rng.uniform() - 3.0;
    thrust[i] = kTable32.thrust(n[i]) + sigma * rng();
  }
}

TEST(ThrustMap, AppliesEachSignsCoefficient) {
  EXPECT_DOUBLE_EQ(kTable32.thrust(2.0), 4.0 * 8130.0);
  EXPECT_DOUBLE_EQ(kTable32.thrust(-2.0), -4.0 * 5800.0);  // reverse thrust is negative
  EXPECT_EQ(kTable32.thrust(0.0), 0.0);
  EXPECT_TRUE(std::isnan(kTable32.thrust(std::nan(""))));
  const std::vector<double> n{1.0, -1.0, std::nan("")};
  const std::vector<double> t = kTable32.thrust(n);
  EXPECT_DOUBLE_EQ(t[0], 8130.0);
  EXPECT_DOUBLE_EQ(t[1], -5800.0);
  EXPECT_TRUE(std::isnan(t[2]));
}

TEST(ThrustMap, MeanCoefficientOf318) {
  // (3.18): (8.13 + 5.8)/2 = 6.965 kN/rps² (printed rounded as 6.97).
  EXPECT_DOUBLE_EQ(kTable32.mean_coefficient(), 6965.0);
  const std::vector<double> n_abs{2.0, std::nan("")};
  const std::vector<double> t = thrust_from_abs_speed(kTable32.mean_coefficient(), n_abs);
  EXPECT_DOUBLE_EQ(t[0], 4.0 * 6965.0);
  EXPECT_TRUE(std::isnan(t[1]));
}

TEST(ThrustMapFit, RecoversTable32FromNoiseFreeLog) {
  std::vector<double> n;
  std::vector<double> thrust;
  make_log(0.0, n, thrust);
  const ThrustMapFitResult r = fit_thrust_map(n, thrust);
  ASSERT_EQ(r.status, FitStatus::kOk);
  // Exact data: only round-off in the sums of ~1000 terms, ~1e-13 relative.
  EXPECT_NEAR(r.c_forward->value, 8130.0, 8130.0 * 1e-12);
  EXPECT_NEAR(r.c_reverse->value, -5800.0, 5800.0 * 1e-12);
  EXPECT_GT(*r.r_squared, 1.0 - 1e-12);
  EXPECT_TRUE(r.warnings.empty());
}

TEST(ThrustMapFit, RecoversTable32WithinThreeSigmaFromNoisyLog) {
  // Thrust noise 2 kN (about 3 % of full thrust): each coefficient within its 3σ, and σ
  // itself small (< 0.5 % of c) for 1000 samples per sign.
  std::vector<double> n;
  std::vector<double> thrust;
  make_log(2000.0, n, thrust);
  const ThrustMapFitResult r = fit_thrust_map(n, thrust);
  ASSERT_EQ(r.status, FitStatus::kOk);
  EXPECT_NEAR(r.c_forward->value, 8130.0, 3.0 * *r.c_forward->sigma);
  EXPECT_NEAR(r.c_reverse->value, -5800.0, 3.0 * *r.c_reverse->sigma);
  EXPECT_LT(*r.c_forward->sigma, 0.005 * 8130.0);
  EXPECT_LT(*r.c_reverse->sigma, 0.005 * 5800.0);
  // The RMS residual estimates the noise: within 5 % for ~1900 samples (std error 1.6 %).
  EXPECT_NEAR(*r.rms_residual, 2000.0, 100.0);
  EXPECT_EQ(
      r.samples_forward + r.samples_reverse, 2000u - [&] {
        std::size_t slow = 0;
        for (double v : n) slow += std::abs(v) < 0.05 ? 1 : 0;
        return slow;
      }());
}

TEST(ThrustMapFit, OneSignOnlyAndNoData) {
  const std::vector<double> n{1.0, 2.0, 3.0, std::nan("")};
  const std::vector<double> thrust{8130.0, 4 * 8130.0, 9 * 8130.0, 1.0};
  const ThrustMapFitResult r = fit_thrust_map(n, thrust);
  ASSERT_EQ(r.status, FitStatus::kOk);
  EXPECT_DOUBLE_EQ(r.c_forward->value, 8130.0);
  EXPECT_FALSE(r.c_reverse.has_value());  // missing, not zero
  EXPECT_TRUE(has_warning(r.warnings, WarningCode::kNoSamplesForSign));

  const std::vector<double> idle{0.0, 0.01, -0.02};
  const ThrustMapFitResult none = fit_thrust_map(idle, std::vector<double>{1.0, 2.0, 3.0});
  EXPECT_EQ(none.status, FitStatus::kFailed);
  EXPECT_FALSE(none.map().has_value());
  EXPECT_THROW_MATCHING(fit_thrust_map(n, std::vector<double>{1.0}), InputError,
                        R"(\(thrust\): has 1 samples but the time axis has 4)");
  ThrustMapFitOptions bad;
  bad.min_abs_shaft_speed_rps = -1.0;
  EXPECT_THROW_MATCHING(fit_thrust_map(n, thrust, bad), InputError, "minimum shaft speed");
}

}  // namespace
}  // namespace dynpos::ident
