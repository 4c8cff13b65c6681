#include "dynpos/control/inertial_position.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>

namespace dynpos::control {
namespace {

constexpr double kDt = 0.1;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const Eigen::Vector2d kNoFix(kNaN, kNaN);

// A DP vessel's horizontal motion: wave motion (0.5 m at 0.8 rad/s N, 0.3 m at 1.1 rad/s E) on a
// slow drift that accelerates (the load changing), its velocity v(t) and position p(t).
Eigen::Vector2d position(double t) {
  return {0.5 * std::sin(0.8 * t) + 0.02 * t + 1e-4 * t * t,
          0.3 * std::cos(1.1 * t) - 0.01 * t + 2e-3 * std::sin(0.02 * t) * t};
}
Eigen::Vector2d velocity(double t) {
  return {0.4 * std::cos(0.8 * t) + 0.02 + 2e-4 * t,
          -0.33 * std::sin(1.1 * t) - 0.01 +
              2e-3 * (std::sin(0.02 * t) + 0.02 * t * std::cos(0.02 * t))};
}

// The mean acceleration over the step ending at t, as an accelerometer's samples summed give it.
Eigen::Vector2d accel(double t) { return (velocity(t) - velocity(t - kDt)) / kDt; }

TEST(InertialPosition, DeadReckonsThroughALossOnAnExactAcceleration) {
  InertialPositionTuning tuning;
  tuning.accel_bias_std_mps2 = 0.0;  // an exact accelerometer: no bias to learn
  InertialPosition ins(tuning);
  // 300 s of fixes, then a 30 s loss.
  double worst_m = 0.0;
  for (int k = 0; k <= 3300; ++k) {
    const double t = k * kDt;
    const bool lost = k > 3000;
    const Eigen::Vector2d p = ins.step(lost ? kNoFix : position(t), accel(t), kDt);
    ASSERT_TRUE(p.allFinite()) << "t " << t;
    EXPECT_EQ(ins.bridging(), lost);
    if (lost) worst_m = std::max(worst_m, (p - position(t)).norm());
  }
  // With exact fixes and the exact mean acceleration the position step is the trapezoid on the
  // velocity, whose error per step, dt³/12 times the jerk, the fixes put into the velocity: an
  // offset of dt²/12 times the jerk at the loss (up to 2.1e-4 m/s for this motion's
  // 0.26 m/s³) moves the bridged position by up to 6.4 mm in 30 s. A centimetre bounds it.
  EXPECT_LT(worst_m, 0.01);
}

TEST(InertialPosition, ItsErrorThroughALossMatchesItsOwnSigma) {
  // Monte Carlo: 400 losses of 30 s after 120 s of fixes, the acceleration with white noise σ_a
  // and a Gauss–Markov bias of σ_β (drawn stationary per run), the fixes with σ_p. The rms error
  // at the end must be the filter's σ: within 10 % (the rms of 400 runs × 2 axes scatters by
  // 1/√1600 = 2.5 %).
  InertialPositionTuning tuning;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> unit(0.0, 1.0);
  const double phi = std::exp(-kDt / tuning.accel_bias_time_constant_s);
  double sum_sq = 0.0, sigma = 0.0;
  constexpr int kRuns = 400;
  for (int run = 0; run < kRuns; ++run) {
    InertialPosition ins(tuning);
    Eigen::Vector2d bias(unit(rng), unit(rng));
    bias *= tuning.accel_bias_std_mps2;
    Eigen::Vector2d p;
    double t = 0.0;
    for (int k = 0; k <= 1500; ++k) {
      t = k * kDt + run;  // each run on another stretch of the motion
      bias = phi * bias + std::sqrt(1.0 - phi * phi) * tuning.accel_bias_std_mps2 *
                              Eigen::Vector2d(unit(rng), unit(rng));
      const Eigen::Vector2d a =
          accel(t) + bias + tuning.accel_std_mps2 * Eigen::Vector2d(unit(rng), unit(rng));
      const Eigen::Vector2d fix =
          position(t) + tuning.position_std_m * Eigen::Vector2d(unit(rng), unit(rng));
      p = ins.step(k > 1200 ? kNoFix : fix, a, kDt);
    }
    sum_sq += (p - position(t)).squaredNorm() / 2.0;  // per axis
    sigma = ins.position_std_m();
  }
  const double rms_m = std::sqrt(sum_sq / kRuns);
  EXPECT_NEAR(rms_m / sigma, 1.0, 0.1) << "rms " << rms_m << " m, sigma " << sigma << " m";
  // The white acceleration alone gives σ_a √(dt t³/3) = 0.30 m at 30 s; the velocity's and the
  // bias's σ at the loss add to it (0.47 m in all).
  EXPECT_GT(sigma, 0.30);
}

TEST(InertialPosition, LearnsTheAccelerometersBiasFromTheFixes) {
  // A constant bias of 5e-3 m/s² (2.5 σ_β) on an otherwise exact acceleration: 300 s of fixes,
  // then 30 s without.
  const Eigen::Vector2d bias(5e-3, -5e-3);
  const auto bridge = [&](double bias_std) {
    InertialPositionTuning tuning;
    tuning.accel_bias_std_mps2 = bias_std;
    InertialPosition ins(tuning);
    Eigen::Vector2d p;
    for (int k = 0; k <= 3300; ++k) {
      const double t = k * kDt;
      p = ins.step(k > 3000 ? kNoFix : position(t), accel(t) + bias, kDt);
    }
    return std::pair((p - position(3300 * kDt)).norm(), ins.position_std_m());
  };
  // Unlearnt (a filter told of no bias) it moves the position by β t²/2 = 2.25 m per axis,
  // 3.2 m in all, and more as the fixes' velocity took some of it: measured 3.6 m.
  const auto [unlearnt_m, unlearnt_sigma_m] = bridge(0.0);
  EXPECT_GT(unlearnt_m, 3.2);
  // Learnt, what is left of a deterministic bias lies within the filter's own σ (0.47 m; the
  // Gauss–Markov model pulls its estimate towards zero between fixes, and on through the loss):
  // measured 0.23 m, a fifteenth of the unlearnt error.
  const auto [learnt_m, learnt_sigma_m] = bridge(2e-3);
  EXPECT_LT(learnt_m, learnt_sigma_m);
  EXPECT_LT(learnt_m, 0.1 * unlearnt_m);
}

TEST(InertialPosition, TheBridgeEndsWhereItsSigmaPassesTheLimit) {
  InertialPositionTuning tuning;
  tuning.max_position_std_m = 0.5;
  tuning.accel_bias_std_mps2 = 0.0;
  InertialPosition ins(tuning);
  for (int k = 0; k <= 600; ++k) ins.step(position(k * kDt), accel(k * kDt), kDt);
  int bridged = 0;
  for (int k = 601; k < 2000; ++k) {
    const double sigma_before = ins.position_std_m();
    const Eigen::Vector2d p = ins.step(kNoFix, accel(k * kDt), kDt);
    if (!ins.bridging()) {
      EXPECT_TRUE(std::isnan(p.x()) && std::isnan(p.y()));
      EXPECT_GT(ins.position_std_m(), 0.5);
      EXPECT_LE(sigma_before, 0.5);
      break;
    }
    ++bridged;
  }
  // σ² = σ_a² dt t³/3 + σ_v² t² (+ σ_p²): the acceleration's white noise alone reaches 0.5 m
  // at t = 42.2 s; with the velocity's σ at the loss, at most 5 mm/s (its steady state is
  // √(√2 q^¾ r^¼) = 4.5 mm/s for q = σ_a² dt, r = σ_p² dt), not before 39.5 s.
  EXPECT_GE(bridged * kDt, 39.5);
  EXPECT_LE(bridged * kDt, 42.3);
  // A fix ends the loss.
  EXPECT_EQ(ins.step(Eigen::Vector2d(1.0, 2.0), accel(200.0), kDt), Eigen::Vector2d(1.0, 2.0));
  EXPECT_FALSE(ins.bridging());
}

TEST(InertialPosition, NoBridgeWithoutTheAccelerationOrBeforeAFix) {
  InertialPosition ins;
  EXPECT_TRUE(std::isnan(ins.step(kNoFix, accel(1.0), kDt).x()));  // no fix yet
  for (int k = 0; k <= 100; ++k) ins.step(position(k * kDt), accel(k * kDt), kDt);
  // The acceleration missing over a step of the loss: the state no longer follows the vessel.
  EXPECT_TRUE(ins.step(kNoFix, accel(10.1), kDt).allFinite());
  EXPECT_TRUE(std::isnan(ins.step(kNoFix, kNoFix, kDt).x()));
  EXPECT_TRUE(std::isnan(ins.step(kNoFix, accel(10.3), kDt).x()));
  // A fix restarts it at the fix; the next loss is bridged again.
  EXPECT_EQ(ins.step(position(10.4), accel(10.4), kDt), position(10.4));
  for (int k = 105; k <= 200; ++k) ins.step(position(k * kDt), accel(k * kDt), kDt);
  EXPECT_TRUE(ins.step(kNoFix, accel(20.1), kDt).allFinite());
  EXPECT_TRUE(ins.bridging());
}

TEST(InertialPosition, RejectsBadTuningAndSteps) {
  const auto message = [](const InertialPositionTuning& t) {
    try {
      InertialPosition ins(t);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  for (double bad : {-1.0, kNaN, std::numeric_limits<double>::infinity()}) {
    InertialPositionTuning b;
    b.accel_bias_std_mps2 = bad;
    EXPECT_THAT(message(b), ::testing::HasSubstr("the accelerometer bias sigma must be finite "
                                                 "and >= 0"));
  }
  for (double bad : {0.0, -1.0, kNaN, std::numeric_limits<double>::infinity()}) {
    InertialPositionTuning tc;
    tc.accel_bias_time_constant_s = bad;
    EXPECT_THAT(message(tc), ::testing::HasSubstr("its time constant finite and > 0"));
    InertialPositionTuning a;
    a.accel_std_mps2 = bad;
    InertialPositionTuning p;
    p.position_std_m = bad;
    InertialPositionTuning m;
    m.max_position_std_m = bad;
    for (const InertialPositionTuning& t : {a, p, m}) {
      EXPECT_THAT(message(t), ::testing::HasSubstr("inertial position: the acceleration and fix "
                                                   "noise and the largest position sigma"));
    }
  }
  InertialPosition ins;
  for (double dt : {0.0, -0.1, kNaN}) {
    EXPECT_THROW(ins.step(position(0.0), accel(0.1), dt), std::invalid_argument);
  }
}

}  // namespace
}  // namespace dynpos::control
