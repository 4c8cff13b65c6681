#include "dynpos/model/hull.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dynpos/core/error.hpp"
#include "dynpos/sim/rk4.hpp"

namespace dynpos::model {
namespace {

using State = Hull::State;

State integrate(const Hull& hull, State x, const Eigen::Vector3d& tau, const Eigen::Vector2d& vc,
                double seconds, double dt = 0.05) {
  sim::Rk4<10> rk4;
  auto f = [&](double, const State& s, State& dxdt) { dxdt = hull.derivatives(s, tau, vc); };
  const int steps = static_cast<int>(std::lround(seconds / dt));
  for (int k = 0; k < steps; ++k) rk4.step(f, k * dt, dt, x);
  return x;
}

TEST(Hull, AtRestWithoutForcesStaysAtRest) {
  const Hull hull;
  State x = State::Zero();
  x[Hull::kYaw] = 1.0;
  const State after = integrate(hull, x, Eigen::Vector3d::Zero(), Eigen::Vector2d::Zero(), 100.0);
  // Exactly zero derivatives at rest: nothing may move, to the last bit.
  EXPECT_EQ(after, x);
}

TEST(Hull, SteadySurgeSpeedSolvesTheDampingBalance) {
  const Hull hull;
  for (const double force : {5.0e3, 40.0e3, 120.0e3, -30.0e3}) {
    const State x = integrate(hull, State::Zero(), {force, 0, 0}, Eigen::Vector2d::Zero(), 1500.0);
    const double u = hull.steady_surge_speed(force);
    // Closed form of (2.8) at rest: X_u·u + X_|u|u·u|u| = X.
    EXPECT_NEAR(hull.params().x_u_Ns_m * u + hull.params().x_uu_Ns2_m2 * u * std::abs(u), force,
                1e-6 * std::abs(force));
    // 1500 s is > 15 linearised time constants: the remaining transient is < 1e-6 of u.
    EXPECT_NEAR(x[Hull::kSurge], u, 1e-5 * std::abs(u) + 1e-9) << "force " << force;
    EXPECT_NEAR(x[Hull::kSway], 0.0, 1e-12);
  }
}

TEST(Hull, KineticEnergyNeverIncreasesWithoutForcing) {
  const Hull hull;
  State x = State::Zero();
  x[Hull::kSurge] = 3.0;
  x[Hull::kSway] = 0.8;
  x[Hull::kYawRate] = 0.05;
  const Eigen::Matrix3d& m = hull.mass_matrix();
  sim::Rk4<10> rk4;
  auto f = [&](double, const State& s, State& dxdt) {
    dxdt = hull.derivatives(s, Eigen::Vector3d::Zero(), Eigen::Vector2d::Zero());
  };
  auto energy = [&](const State& s) {
    const Eigen::Vector3d nu = s.segment<3>(Hull::kSurge);
    return 0.5 * nu.dot(m * nu);
  };
  const double initial = energy(x);
  double previous = initial;
  for (int k = 0; k < 4000; ++k) {
    rk4.step(f, k * 0.05, 0.05, x);
    const double e = energy(x);
    // Coriolis terms do no work (νᵀCν = 0) and damping dissipates: E non-increasing, up to
    // the RK4 truncation error relative to E (≈ 1e-12 at this step).
    EXPECT_LE(e, previous * (1.0 + 1e-10)) << "step " << k;
    previous = e;
  }
  // After 200 s (2–3 surge time constants at these speeds) most of the energy is gone.
  EXPECT_LT(previous, 0.2 * initial);
}

TEST(Hull, CoriolisTermsDoNoWork) {
  HullParams p;
  // Remove damping: then νᵀ(forces) = −νᵀ(C_RB + C_A)ν must vanish for ν_r = ν.
  p.x_u_Ns_m = 1e-3;
  p.x_uu_Ns2_m2 = p.y_uv_Ns2_m2 = p.y_vv_Ns2_m2 = p.y_ur_Ns2 = p.n_uv_Ns2 = 0.0;
  p.y_v_Ns_m = p.n_r_Nms = 1e-3;
  p.n_ur_Nms2 = p.n_rr_Nms2 = 0.0;
  const Hull hull(p);
  const Eigen::Vector3d nu(2.5, -0.7, 0.04);
  const Eigen::Vector3d f = hull.hydrodynamic_forces(nu, nu);
  const double damping_power = 1e-3 * (nu.x() * nu.x() + nu.y() * nu.y() + nu.z() * nu.z());
  // What remains is the tiny linear damping power only (rounding ≈ 1e-10 of |ν||f|).
  EXPECT_NEAR(nu.dot(f), -damping_power, 1e-9 * nu.norm() * f.norm());
}

TEST(Hull, NomotoTimeConstantShortensWithSpeedWithinThesisRange) {
  const Hull hull;
  const double x_rudder = -14.5;
  const Hull::Nomoto slow = hull.nomoto(3.0 * 1852.0 / 3600.0, x_rudder);
  const Hull::Nomoto fast = hull.nomoto(6.0 * 1852.0 / 3600.0, x_rudder);
  // Table 3.31: T_r 4.7–5.6 s at 3 kn and 2.9–3.0 s at 6 kn; we accept ±0.3 s around the
  // 6 kn band because the thesis reports only two runs there.
  EXPECT_GE(slow.tr_s, 4.7);
  EXPECT_LE(slow.tr_s, 5.6);
  EXPECT_GE(fast.tr_s, 2.6);
  EXPECT_LE(fast.tr_s, 3.3);
  EXPECT_GT(slow.t1_s, 0.0);
  EXPECT_GT(fast.t2_s, 0.0);  // both poles stable
}

TEST(Hull, TurningHeelsOutward) {
  const Hull hull;
  State x = State::Zero();
  x[Hull::kSurge] = 3.0;
  // A steady starboard turn (r > 0) forced by a yaw moment: the roll settles to k·u·r < 0.
  x = integrate(hull, x, {hull.params().x_u_Ns_m * 3.0 + hull.params().x_uu_Ns2_m2 * 9.0, 0, 5e5},
                Eigen::Vector2d::Zero(), 400.0);
  ASSERT_GT(x[Hull::kYawRate], 0.0);
  const double expected = hull.params().heel_per_centripetal * x[Hull::kSurge] * x[Hull::kYawRate];
  // Steady state of the roll oscillator: within 1 % once the turn has settled.
  EXPECT_NEAR(x[Hull::kRoll], expected, 0.01 * std::abs(expected));
  EXPECT_LT(x[Hull::kRoll], 0.0);
}

TEST(Hull, CurrentDriftsAHullWithoutThrust) {
  const Hull hull;
  const Eigen::Vector2d current(0.3, -0.2);
  const State x = integrate(hull, State::Zero(), Eigen::Vector3d::Zero(), current, 3000.0);
  // With no forces the hull ends up moving with the water (ν_r → 0): its velocity over ground
  // R(ψ)ν equals the current to 1 mm/s (the heading may turn meanwhile).
  const double c = std::cos(x[Hull::kYaw]), s = std::sin(x[Hull::kYaw]);
  EXPECT_NEAR(c * x[Hull::kSurge] - s * x[Hull::kSway], 0.3, 1e-3);
  EXPECT_NEAR(s * x[Hull::kSurge] + c * x[Hull::kSway], -0.2, 1e-3);
}

TEST(HullParams, ValidateNamesTheField) {
  HullParams p;
  p.mass_kg = -1.0;
  try {
    p.validate();
    FAIL() << "no exception";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("hull.mass_kg"), std::string::npos);
  }
}

}  // namespace
}  // namespace dynpos::model
