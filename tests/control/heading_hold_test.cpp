#include "dynpos/control/heading_hold.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace dynpos::control {
namespace {

HeadingHoldParams params() {
  HeadingHoldParams p;
  p.inertia_kgm2 = 4.0e6;
  p.yaw_damping_Nms = 1.0e5;
  p.omega_rad_s = 0.2;
  p.zeta = 0.8;
  p.max_yaw_Nm = 1.0e6;
  p.rate_hz = 10.0;
  p.heading_rad = 0.5;
  return p;
}

// The yaw mode I·ψ̈ + N_r·ψ̇ = N_max·(demand) + N_dist under the controller at its rate, by
// explicit Euler on a 1 ms grid (the controller's 0.1 s hold dominates the error). Returns ψ at
// the end.
double simulate(HeadingHold& hold, const HeadingHoldParams& p, double psi0, double disturbance_Nm,
                double duration_s) {
  const double h = 1e-3;
  const int per_update = static_cast<int>(std::lround(1.0 / (p.rate_hz * h)));
  double psi = psi0, r = 0.0, demand = 0.0;
  const int steps = static_cast<int>(std::lround(duration_s / h));
  for (int k = 0; k < steps; ++k) {
    if (k % per_update == 0) demand = hold.update(0.0, psi, r);
    const double r_dot =
        (p.max_yaw_Nm * demand + disturbance_Nm - p.yaw_damping_Nms * r) / p.inertia_kgm2;
    psi += h * r;
    r += h * r_dot;
  }
  return psi;
}

TEST(HeadingHold, GainsPlaceTheYawModeAtOmegaAndZeta) {
  const HeadingHoldParams p = params();
  const HeadingHold hold(p);
  EXPECT_DOUBLE_EQ(hold.kp(), 4.0e6 * 0.04);                     // I·ω²
  EXPECT_DOUBLE_EQ(hold.kd(), 2.0 * 0.8 * 0.2 * 4.0e6 - 1.0e5);  // 2ζωI − N_r
  EXPECT_DOUBLE_EQ(hold.ki(), hold.kp() * 0.2 / 10.0);           // integral time 10/ω
  // A hull whose own damping exceeds 2ζωI gets no derivative gain, never a negative one.
  HeadingHoldParams damped = p;
  damped.yaw_damping_Nms = 1.0e7;
  EXPECT_EQ(HeadingHold(damped).kd(), 0.0);
}

TEST(HeadingHold, ProportionalAndDerivativeTermsOfOneUpdate) {
  const HeadingHoldParams p = params();
  HeadingHold hold(p);
  // 0.01 rad to starboard of the held heading, turning further at 0.002 rad/s: the moment
  // −k_p·ψ̃ − k_d·r is added to the operator's 10 %.
  const double fraction = hold.update(0.1, 0.51, 0.002);
  const double expected = 0.1 + (-hold.kp() * 0.01 - hold.kd() * 0.002) / p.max_yaw_Nm;
  EXPECT_NEAR(fraction, expected, 1e-15);
  // The integral grows by k_i·ψ̃/rate after the update (its effect starts at the next one).
  EXPECT_NEAR(hold.integral_Nm(), hold.ki() * 0.01 / 10.0, 1e-12);
}

TEST(HeadingHold, HeadingErrorIsWrappedAcrossNorth) {
  HeadingHoldParams p = params();
  p.heading_rad = 0.01;
  HeadingHold hold(p);
  // 2π − 0.01 is 0.02 rad to port of 0.01: the moment turns to starboard (positive).
  EXPECT_GT(hold.update(0.0, 2.0 * M_PI - 0.01, 0.0), 0.0);
  EXPECT_NEAR(hold.integral_Nm(), hold.ki() * -0.02 / 10.0, 1e-9);
}

TEST(HeadingHold, IntegralStopsWhileTheDemandIsClamped) {
  const HeadingHoldParams p = params();
  HeadingHold hold(p);
  // 1 rad off with the operator at full starboard yaw: the sum is far beyond −1 … 1.
  EXPECT_EQ(hold.update(-1.0, 1.5, 0.0), -1.0);
  EXPECT_EQ(hold.update(-1.0, 1.5, 0.0), -1.0);
  EXPECT_EQ(hold.integral_Nm(), 0.0);
  // Off the clamp it integrates again.
  (void)hold.update(0.0, 0.51, 0.0);
  EXPECT_GT(hold.integral_Nm(), 0.0);
}

TEST(HeadingHold, HoldsTheHeadingAgainstAConstantMoment) {
  const HeadingHoldParams p = params();
  HeadingHold hold(p);
  // 20 % of the largest moment pushes the bow to starboard; the integral removes the offset.
  // The slowest mode of the loop decays at about k_i/k_p = ω/10 (50 s): after 600 s, twelve of
  // them, the error is far inside 1e-3 rad, where a PD law would leave 0.2·N_max/k_p = 1.25 rad.
  const double psi = simulate(hold, p, 0.5, 0.2 * p.max_yaw_Nm, 600.0);
  EXPECT_NEAR(psi, 0.5, 1e-3);
  EXPECT_NEAR(hold.integral_Nm(), 0.2 * p.max_yaw_Nm, 0.01 * p.max_yaw_Nm);
}

TEST(HeadingHold, RejectsBadParameters) {
  HeadingHoldParams p = params();
  p.omega_rad_s = 0.0;
  EXPECT_THROW(HeadingHold{p}, std::invalid_argument);
  p = params();
  p.max_yaw_Nm = -1.0;
  EXPECT_THROW(HeadingHold{p}, std::invalid_argument);
  p = params();
  p.yaw_damping_Nms = -1.0;
  EXPECT_THROW(HeadingHold{p}, std::invalid_argument);
}

}  // namespace
}  // namespace dynpos::control
