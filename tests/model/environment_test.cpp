#include "dynpos/model/environment.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "dynpos/core/error.hpp"

namespace dynpos::model {
namespace {

WindParams steady_wind(double speed, double from) {
  WindParams p;
  p.speed_mps = speed;
  p.from_rad = from;
  p.gust_std_fraction = 0.0;
  p.dir_std_rad = 0.0;
  return p;
}

TEST(Wind, HeadWindPushesAsternWithoutSideForceOrMoment) {
  const Wind wind(steady_wind(10.0, 0.0), 1, 0.01);
  const Eigen::Vector3d f = wind.force_b(0.0, Eigen::Vector2d::Zero());
  const WindParams p = steady_wind(10.0, 0.0);
  // ½ρV²·c_x·A_F exactly, the head-wind value of the coefficient curve.
  EXPECT_NEAR(f.x(), -0.5 * p.rho_air * 100.0 * p.cx * p.frontal_area_m2, 1e-9);
  EXPECT_NEAR(f.y(), 0.0, 1e-9);
  EXPECT_NEAR(f.z(), 0.0, 1e-6);
}

TEST(Wind, BeamWindsAreMirrorImages) {
  const Wind from_stb(steady_wind(8.0, M_PI / 2), 1, 0.01);
  const Wind from_port(steady_wind(8.0, -M_PI / 2), 1, 0.01);
  const Eigen::Vector3d a = from_stb.force_b(0.0, Eigen::Vector2d::Zero());
  const Eigen::Vector3d b = from_port.force_b(0.0, Eigen::Vector2d::Zero());
  EXPECT_LT(a.y(), 0.0);  // wind from starboard pushes to port
  EXPECT_NEAR(a.y(), -b.y(), 1e-9 * std::abs(a.y()));
  // Moving with the wind at wind speed removes the force (relative wind zero).
  // (Only rounding of cos(π/2) ≈ 6e-17 is left: forces ∝ V² of order 1e-30 N.)
  EXPECT_NEAR(from_stb.force_b(0.0, Eigen::Vector2d(0.0, -8.0)).norm(), 0.0, 1e-20);
}

TEST(Wind, GustStatisticsMatchTheTurbulenceIntensity) {
  WindParams p = steady_wind(10.0, 0.0);
  p.gust_std_fraction = 0.1;
  Wind wind(p, 3, 0.1);
  double sum = 0.0, sum2 = 0.0;
  const int n = 200000;  // 20 000 s ≈ 2500 correlation times
  for (int k = 0; k < n; ++k) {
    wind.step();
    sum += wind.speed_mps();
    sum2 += wind.speed_mps() * wind.speed_mps();
  }
  const double mean = sum / n;
  const double std = std::sqrt(sum2 / n - mean * mean);
  // ≈ 2500 independent samples: the std estimate has ≈ 1.4 % relative error, mean ≈ 0.02 m/s;
  // bounds at ≈ 4 standard errors.
  EXPECT_NEAR(mean, 10.0, 0.08);
  EXPECT_NEAR(std, 1.0, 0.06);
}

TEST(Current, VelocityPointsWhereItFlows) {
  CurrentParams p;
  p.speed_mps = 0.5;
  p.to_rad = M_PI / 2;  // flowing east
  p.speed_std_mps = 0.0;
  p.dir_std_rad = 0.0;
  Current current(p, 1, 0.01);
  current.step();
  EXPECT_NEAR(current.velocity_n().x(), 0.0, 1e-12);
  EXPECT_NEAR(current.velocity_n().y(), 0.5, 1e-12);
}

TEST(Bias, SameSeedSameSequenceOtherSeedOther) {
  Bias a(BiasParams{}, 5, 0.01), b(BiasParams{}, 5, 0.01), c(BiasParams{}, 6, 0.01);
  for (int k = 0; k < 100; ++k) {
    a.step();
    b.step();
    c.step();
  }
  EXPECT_EQ(a.value_n(), b.value_n());
  EXPECT_NE(a.value_n(), c.value_n());
}

TEST(Bias, SeaStateFactorIsOneAtTheReferenceAndTheCalmFractionInCalmWater) {
  BiasParams p;  // H_ref = 2 m
  p.calm_fraction = 0.25;
  EXPECT_DOUBLE_EQ(p.sea_state_factor(2.0), 1.0);
  EXPECT_DOUBLE_EQ(p.sea_state_factor(0.0), 0.25);
  // k(1 m) = √(c² + (1 − c²)/16) by hand: √(0.0625 + 0.05859375) = 0.348010...
  EXPECT_NEAR(p.sea_state_factor(1.0), std::sqrt(0.0625 + 0.9375 / 16.0), 1e-15);
  // Far above the reference the wave part dominates: k → √(1 − c²)·(H_s/H_ref)², the drift
  // force law (at 4·H_ref the calm part adds 1.4·10⁻⁴ of it).
  EXPECT_NEAR(p.sea_state_factor(8.0) / 16.0, std::sqrt(0.9375), 1e-3);
  double previous = 0.0;
  for (double hs = 0.0; hs <= 6.0; hs += 0.25) {
    const double k = p.sea_state_factor(hs);
    EXPECT_GE(k, previous) << "Hs " << hs;
    previous = k;
  }
  p.calm_fraction = 1.0;  // scaling off
  EXPECT_DOUBLE_EQ(p.sea_state_factor(0.0), 1.0);
  EXPECT_DOUBLE_EQ(p.sea_state_factor(2.0), 1.0);
}

TEST(Bias, ScaledForTheSeaStateIsTheSameSequenceTimesTheFactor) {
  const BiasParams p;
  const BiasParams calm = bias_for_sea_state(p, 0.1);
  EXPECT_EQ(calm.time_constant_s, p.time_constant_s);
  Bias full(p, 9, 0.01), scaled(calm, 9, 0.01);
  const double k = p.sea_state_factor(0.1);
  for (int i = 0; i < 1000; ++i) {
    full.step();
    scaled.step();
  }
  // Same seed, same white noise: the Gauss–Markov state is linear in its std.
  EXPECT_LT((scaled.value_n() - k * full.value_n()).norm(), 1e-9 * full.value_n().norm());
  EXPECT_THROW(bias_for_sea_state(p, -1.0), core::InputError);
  BiasParams bad = p;
  bad.calm_fraction = 1.5;
  EXPECT_THROW(bias_for_sea_state(bad, 1.0), core::InputError);
}

TEST(StepLoads, SwitchOnAndOffAtTheirTimes) {
  std::vector<StepLoad> loads{{10.0, 20.0, {1e4, 0, 0}}, {15.0, 1e300, {0, -5e3, 1e5}}};
  EXPECT_EQ(step_loads_n(loads, 9.999), Eigen::Vector3d::Zero());
  EXPECT_EQ(step_loads_n(loads, 10.0), Eigen::Vector3d(1e4, 0, 0));
  EXPECT_EQ(step_loads_n(loads, 15.0), Eigen::Vector3d(1e4, -5e3, 1e5));
  EXPECT_EQ(step_loads_n(loads, 20.0), Eigen::Vector3d(0, -5e3, 1e5));  // the line snapped
}

}  // namespace
}  // namespace dynpos::model
