#include "dynpos/model/thruster.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "dynpos/core/error.hpp"
#include "dynpos/model/delay_line.hpp"
#include "dynpos/model/fopdt_truth.hpp"
#include "dynpos/sim/rk4.hpp"

namespace dynpos::model {
namespace {

constexpr double kPi = std::numbers::pi;

// Percent of full ahead (or astern) thrust to shaft speed: T ∝ n², so n = n_max·√(p/100).
double percent_to_n(double percent) {
  return (percent >= 0.0 ? 1.0 : -1.0) * 3.0 * std::sqrt(std::abs(percent) / 100.0);
}

// Simulates the thruster from state x for duration [s] with a held (already delayed) command,
// RK4 at dt = 0.01 s; calls observe(x) after every step.
template <typename Observe>
Thruster::State run(const Thruster& thruster, Thruster::State x, double n_command, double duration,
                    Observe&& observe) {
  sim::Rk4<4> rk4;
  const double dt = 0.01;
  const ThrusterInput u{n_command, 0.0};
  const auto steps = static_cast<int>(std::round(duration / dt));
  for (int k = 0; k < steps; ++k) {
    rk4.step([&](double, const Thruster::State& xs,
                 Thruster::State& dxs) { dxs = thruster.derivatives(xs, u); },
             k * dt, dt, x, x);
    observe(x);
  }
  return x;
}

TEST(Thruster, ThrustMapMatchesTable32ForwardAndReverse) {
  const Thruster thruster;
  // T = c·n|n| (3.17) with c = 8.13 / 5.8 kN/rps² (Table 3.2). Tolerance: a few ulps of the
  // K_T = c/(ρD⁴) round trip, relative 1e-12.
  EXPECT_NEAR(thruster.thrust(2.0), 8130.0 * 4.0, 1e-12 * 8130.0 * 4.0);
  EXPECT_NEAR(thruster.thrust(-2.0), -5800.0 * 4.0, 1e-12 * 5800.0 * 4.0);
  EXPECT_NEAR(thruster.thrust_coefficient(1.0), 8130.0, 1e-9);
  EXPECT_NEAR(thruster.thrust_coefficient(-1.0), 5800.0, 1e-9);
  EXPECT_EQ(thruster.thrust(0.0), 0.0);
}

TEST(Thruster, FullThrustAndPowerAreGunnerusLike) {
  const Thruster thruster;
  EXPECT_GT(thruster.max_thrust_forward(), 60e3);
  EXPECT_LT(thruster.max_thrust_forward(), 80e3);
  // Rated power ≈ 500 kW at n_max, below the motor limit.
  const double p_max = thruster.power(3.0);
  EXPECT_GT(p_max, 450e3);
  EXPECT_LT(p_max, thruster.params().max_power);
}

TEST(Thruster, PowerIsTwoPiNTimesTorque) {
  const Thruster thruster;
  const ThrusterParams& p = thruster.params();
  for (double n : {-3.0, -1.3, 0.0, 0.7, 2.9}) {
    const double q = thruster.torque(n);
    // (2.28) both ways; tolerance relative 1e-12 for rounding.
    EXPECT_NEAR(thruster.power(n), 2.0 * kPi * n * q, 1e-12 * (1.0 + std::abs(q)));
    const double kq = n >= 0.0 ? p.kq_forward : p.kq_reverse;
    // (2.28): P = sign(n)·2πK_Qρ D⁵n³ ≥ 0 in both directions.
    const double closed =
        (n < 0.0 ? -1.0 : 1.0) * 2.0 * kPi * kq * p.rho * std::pow(p.diameter, 5) * n * n * n;
    EXPECT_GE(thruster.power(n), 0.0);
    EXPECT_NEAR(thruster.power(n), closed, 1e-9 * (1.0 + std::abs(closed)));
  }
}

TEST(Thruster, InverseMapRoundTrips) {
  const Thruster thruster;
  for (double t : {-40e3, -1e3, 0.0, 5e3, 70e3}) {
    // Tolerance: relative 1e-12, sqrt and square round trip.
    EXPECT_NEAR(thruster.thrust(thruster.shaft_speed_for_thrust(t)), t, 1e-12 * 1e5);
  }
  // Beyond the maximum the command clamps to n_max.
  EXPECT_DOUBLE_EQ(thruster.shaft_speed_for_thrust(1e7), thruster.params().max_shaft_speed);
}

TEST(Thruster, AdvanceRatioSlopeReducesThrust) {
  ThrusterParams p;
  p.kt_slope = 0.3;
  const Thruster thruster(p);
  // K_T = K_T0 − k·J with J = V_a/(nD): closed form at n = 2, V_a = 2 (J = 0.5).
  const double expected = p.rho * std::pow(p.diameter, 4) * 4.0 * (p.kt_forward - 0.3 * 0.5);
  EXPECT_NEAR(thruster.thrust(2.0, 2.0), expected, 1e-9 * expected);
  EXPECT_LT(thruster.thrust(2.0, 2.0), thruster.thrust(2.0, 0.0));
}

TEST(Thruster, SteadyStateIsAnEquilibrium) {
  const Thruster thruster;
  for (double n : {-2.5, 0.0, 1.0, 3.0}) {
    const Thruster::State x = thruster.steady_state(n);
    const Thruster::State dx = thruster.derivatives(x, {n, 0.0});
    // The equilibrium is built analytically; residual torques are rounding of ~3e4 N·m terms,
    // so 1e-8 relative to the scale of each row.
    EXPECT_NEAR(dx[Thruster::kNRef], 0.0, 1e-12);
    EXPECT_NEAR(dx[Thruster::kIntegral], 0.0, 1e-12);
    EXPECT_NEAR(dx[Thruster::kMotorTorque], 0.0, 1e-8 * 3e4 / 0.15);
    EXPECT_NEAR(dx[Thruster::kOmega], 0.0, 1e-8 * 3e4 / 2000.0);
  }
}

TEST(Thruster, PiLoopSettlesOnTheCommandWithoutOvershootBeyondOnePercent) {
  const Thruster thruster;
  double n_peak = 0.0;
  const Thruster::State x =
      run(thruster, thruster.steady_state(0.0), 2.2, 60.0, [&](const Thruster::State& xs) {
        n_peak = std::max(n_peak, xs[Thruster::kOmega] / (2 * kPi));
      });
  const ThrusterOutput y = thruster.outputs(x);
  // 60 s is > 10 ramp-plus-loop settling times; the error left is below 1e-6 rps.
  EXPECT_NEAR(y.shaft_speed, 2.2, 1e-6);
  EXPECT_NEAR(y.thrust, 8130.0 * 2.2 * 2.2, 1e-6 * 2 * 8130.0 * 2.2);
  EXPECT_LT(n_peak, 2.2 * 1.01);
}

TEST(Thruster, ReferenceRateLimitIsRespected) {
  const Thruster thruster;
  const double rate = thruster.params().ref_rate_limit;
  double max_ref_rate = 0.0;
  double max_shaft_rate = 0.0;
  Thruster::State prev = thruster.steady_state(-3.0);
  run(thruster, prev, 3.0, 40.0, [&](const Thruster::State& xs) {
    const double dn_ref = (xs[Thruster::kNRef] - prev[Thruster::kNRef]) / 0.01;
    const double dn = (xs[Thruster::kOmega] - prev[Thruster::kOmega]) / (2 * kPi * 0.01);
    max_ref_rate = std::max(max_ref_rate, std::abs(dn_ref));
    max_shaft_rate = std::max(max_shaft_rate, std::abs(dn));
    prev = xs;
  });
  // The reference slope is bounded exactly (RK4 averages bounded slopes); rounding only.
  EXPECT_LE(max_ref_rate, rate * (1.0 + 1e-9));
  // The shaft follows the ramp; near n = 0 the load torque gradient vanishes and the speed loop
  // catches up its lag with a slope up to ≈ 1.2× the ramp; 1.3× bounds that transient.
  EXPECT_LE(max_shaft_rate, rate * 1.3);
  EXPECT_GT(max_shaft_rate, rate * 0.9);
}

TEST(Thruster, PowerLimitCapsShaftSpeed) {
  ThrusterParams p;
  p.max_power = 200e3;
  const Thruster thruster(p);
  const Thruster::State x =
      run(thruster, thruster.steady_state(0.0), 3.0, 80.0, [](const Thruster::State&) {});
  const ThrusterOutput y = thruster.outputs(x);
  // Motor power Q_m·ω ≤ P_max (plus a 0.1 % margin for the torque lag at equilibrium).
  EXPECT_LE(y.motor_torque * 2 * kPi * y.shaft_speed, 200e3 * 1.001);
  EXPECT_LT(y.shaft_speed, 2.5);
  EXPECT_TRUE(x.allFinite());
}

TEST(Thruster, StepResponsesMatchThesisRanges) {
  const Thruster thruster;
  // Steps of tables 3.23, 3.25, 3.27, 3.29 in % thrust.
  const std::vector<std::pair<double, double>> steps = {
      {0, 80},  {25, 40}, {15, 25}, {10, 15},   {5, 10},    {0, 25},   {0, 50}, {0, 75},
      {0, 100}, {100, 0}, {0, -40}, {-15, -20}, {-10, -15}, {-5, -10}, {-20, 0}};
  for (const auto& [from, to] : steps) {
    SCOPED_TRACE(testing::Message() << from << " -> " << to << " %");
    const ThrusterStepTruth truth =
        thruster_step_truth(thruster, percent_to_n(from), percent_to_n(to));
    // The design envelope (DESIGN.md, from the thesis tables).
    EXPECT_GE(truth.shaft_speed.time_constant, 0.5);
    EXPECT_LE(truth.shaft_speed.time_constant, 5.5);
    EXPECT_GE(truth.shaft_speed.dead_time, 1.2);
    EXPECT_LE(truth.shaft_speed.dead_time, 3.3);
    EXPECT_GE(truth.thrust.time_constant, 0.3);
    EXPECT_LE(truth.thrust.time_constant, 4.7);
    EXPECT_GE(truth.thrust.dead_time, 1.0);
    EXPECT_LE(truth.thrust.dead_time, 5.6);
  }
}

TEST(Thruster, LargerStepsAreSlower) {
  const Thruster thruster;
  double previous = 0.0;
  for (double to : {25.0, 50.0, 75.0, 100.0}) {
    const double t_n =
        thruster_step_truth(thruster, 0.0, percent_to_n(to)).shaft_speed.time_constant;
    EXPECT_GT(t_n, previous) << "0 -> " << to << " %";
    previous = t_n;
  }
}

TEST(Thruster, ValidateNamesTheField) {
  ThrusterParams p;
  p.diameter = -1.0;
  EXPECT_THAT([&] { p.validate(); },
              testing::ThrowsMessage<core::InputError>(testing::HasSubstr("propeller.diameter_m")));
  p = ThrusterParams{};
  p.motor_time_constant = 0.0;
  EXPECT_THAT([&] { Thruster{p}; },
              testing::ThrowsMessage<core::InputError>(testing::HasSubstr("motor_time_constant")));
  EXPECT_NO_THROW(ThrusterParams{}.validate());
}

TEST(FirstOrderThruster, MatchesExponentialClosedForm) {
  const FirstOrderThruster thruster;
  const double tc = thruster.params().time_constant;
  sim::Rk4<1> rk4;
  Eigen::Matrix<double, 1, 1> x(0.0);
  const double dt = 0.01;
  for (int k = 0; k < 500; ++k) {
    rk4.step([&](double, const Eigen::Matrix<double, 1, 1>& xs,
                 Eigen::Matrix<double, 1, 1>& dxs) { dxs[0] = thruster.derivative(xs[0], 30e3); },
             k * dt, dt, x, x);
  }
  // RK4 global error O(dt⁴·t/T⁵) ≈ 1e-9 relative here; 1e-7 relative leaves margin.
  EXPECT_NEAR(x[0], 30e3 * (1.0 - std::exp(-5.0 / tc)), 30e3 * 1e-7);
  // The command saturates at the forward maximum.
  EXPECT_DOUBLE_EQ(thruster.derivative(0.0, 1e9), thruster.params().max_thrust_forward / tc);
}

TEST(DelayLine, DelaysByWholeTicks) {
  DelayLine line(0.03, 0.01, -1.0);
  EXPECT_EQ(line.delay_ticks(), 3u);
  std::vector<double> out;
  for (int k = 0; k < 6; ++k) out.push_back(line.push(k));
  EXPECT_EQ(out, (std::vector<double>{-1.0, -1.0, -1.0, 0.0, 1.0, 2.0}));
  DelayLine zero(0.0, 0.01);
  EXPECT_EQ(zero.push(4.5), 4.5);
  line.reset(7.0);
  EXPECT_EQ(line.push(0.0), 7.0);
  EXPECT_THROW(DelayLine(-1.0, 0.01), std::invalid_argument);
  EXPECT_THROW(DelayLine(1.0, 0.0), std::invalid_argument);
}

TEST(FopdtTwoPoint, RecoversAnExactFopdtResponse) {
  const double T = 2.0;
  const double delta = 1.5;
  std::vector<double> t;
  std::vector<double> y;
  for (int k = -100; k <= 20000; ++k) {
    const double tk = k * 0.001;
    t.push_back(tk);
    y.push_back(3.0 + (tk > delta ? 4.0 * (1.0 - std::exp(-(tk - delta) / T)) : 0.0));
  }
  const auto fit = fopdt_two_point(t, y, 0.0);
  ASSERT_TRUE(fit.has_value());
  // Linear interpolation between 1 ms samples and the 20 s tail (e^{−9.25} of the change not
  // yet reached) bound the error to ≈ 1e-3 s.
  EXPECT_NEAR(fit->time_constant, T, 2e-3);
  EXPECT_NEAR(fit->dead_time, delta, 2e-3);
  const std::vector<double> flat(t.size(), 1.0);
  EXPECT_FALSE(fopdt_two_point(t, flat, 0.0).has_value());
}

}  // namespace
}  // namespace dynpos::model
