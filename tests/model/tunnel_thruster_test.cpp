#include "dynpos/model/tunnel_thruster.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "dynpos/core/error.hpp"

namespace dynpos::model {
namespace {

constexpr double kKnot = 1852.0 / 3600.0;

TEST(TunnelThruster, EffectivenessFallsMonotonicallyWithSpeed) {
  const TunnelThruster tunnel;
  EXPECT_DOUBLE_EQ(tunnel.speed_factor(0.0), 1.0);
  double previous = 1.0;
  for (int k = 1; k <= 100; ++k) {
    const double u = 0.1 * k;
    const double eta = tunnel.speed_factor(u);
    // Strictly decreasing where exp(−(u/u₀)²) is resolvable next to η_min in double precision
    // (u ≤ 5 m/s ≈ 10 kn); beyond that it has converged to η_min and must not rise.
    if (u <= 5.0) {
      EXPECT_LT(eta, previous) << "u = " << u;
    } else {
      EXPECT_LE(eta, previous) << "u = " << u;
    }
    EXPECT_DOUBLE_EQ(tunnel.speed_factor(-u), eta);
    previous = eta;
  }
  // Reasoned target: 0.3–0.5 of bollard at 3–4 kn.
  EXPECT_GE(tunnel.speed_factor(3.0 * kKnot), 0.3);
  EXPECT_LE(tunnel.speed_factor(3.0 * kKnot), 0.51);
  EXPECT_GE(tunnel.speed_factor(4.0 * kKnot), 0.3);
  EXPECT_LE(tunnel.speed_factor(4.0 * kKnot), 0.5);
}

TEST(TunnelThruster, ThrustMapIsSignDependentAndGunnerusSized) {
  const TunnelThruster tunnel;
  const TunnelThrusterParams& p = tunnel.params();
  const double d4 = std::pow(p.diameter, 4);
  // (2.25) closed form; rounding only.
  EXPECT_NEAR(tunnel.thrust(3.0), p.rho * p.kt_starboard * d4 * 9.0, 1e-9);
  EXPECT_NEAR(tunnel.thrust(-3.0), -p.rho * p.kt_port * d4 * 9.0, 1e-9);
  EXPECT_GT(tunnel.max_thrust_starboard(), 20e3);
  EXPECT_LT(tunnel.max_thrust_starboard(), 30e3);
  EXPECT_LT(tunnel.max_thrust_port(), tunnel.max_thrust_starboard());
  const TunnelThrusterOutput full = tunnel.outputs(p.max_shaft_speed, 0.0);
  EXPECT_NEAR(full.power, 200e3, 10e3);  // ≈ 200 kW rated
  EXPECT_NEAR(tunnel.outputs(2.0, 2.0).thrust, tunnel.thrust(2.0) * tunnel.speed_factor(2.0), 1e-9);
}

TEST(TunnelThruster, InverseMapRoundTripsIncludingSpeedFactor) {
  const TunnelThruster tunnel;
  for (double u : {0.0, 1.0, 2.0}) {
    for (double t : {-8e3, 0.0, 5e3}) {
      // sqrt/square round trip; 1e-9 N.
      EXPECT_NEAR(tunnel.thrust(tunnel.shaft_speed_for_thrust(t, u), u), t, 1e-9);
    }
  }
}

TEST(TunnelThruster, RateLimitAndSmallStepClosedForm) {
  const TunnelThruster tunnel;
  const TunnelThrusterParams& p = tunnel.params();
  EXPECT_DOUBLE_EQ(tunnel.shaft_acceleration(-5.0, 5.0), p.rate_limit);
  EXPECT_DOUBLE_EQ(tunnel.shaft_acceleration(0.0, 100.0), p.rate_limit);
  // A small step never hits the rate limit: pure FOPDT with T = T_n, δ = dead time. The
  // residual is RK4 error and 10 ms sampling/interpolation of the crossing times: ≤ 0.01 s.
  const FopdtTruth small = tunnel_step_truth(tunnel, 0.0, 0.5);
  EXPECT_NEAR(small.time_constant, p.time_constant, 0.01);
  EXPECT_NEAR(small.dead_time, p.dead_time, 0.01);
  // A full-range step is rate limited and therefore slower.
  EXPECT_GT(tunnel_step_truth(tunnel, 0.0, p.max_shaft_speed).time_constant, 1.5);
}

TEST(TunnelThruster, ValidateNamesTheField) {
  TunnelThrusterParams p;
  p.speed_factor_min = 1.5;
  EXPECT_THAT([&] { p.validate(); }, testing::ThrowsMessage<core::InputError>(
                                         testing::HasSubstr("tunnel.speed_factor_min")));
  p = TunnelThrusterParams{};
  p.time_constant = 0.0;
  EXPECT_THROW(TunnelThruster{p}, core::InputError);
}

}  // namespace
}  // namespace dynpos::model
