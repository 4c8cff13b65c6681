#include "dynpos/model/rudder.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "dynpos/core/error.hpp"
#include "dynpos/sim/rk4.hpp"

namespace dynpos::model {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

TEST(Rudder, AngleSaturatesAtMaximumAndRespectsRate) {
  const Rudder rudder;
  const RudderParams& p = rudder.params();
  sim::Rk4<1> rk4;
  Eigen::Matrix<double, 1, 1> x(0.0);
  double max_rate = 0.0;
  for (int k = 0; k < 3000; ++k) {
    const double before = x[0];
    rk4.step(
        [&](double, const Eigen::Matrix<double, 1, 1>& xs, Eigen::Matrix<double, 1, 1>& dxs) {
          dxs[0] = rudder.angle_rate(xs[0], 90 * kDeg);
        },
        k * 0.01, 0.01, x, x);
    max_rate = std::max(max_rate, std::abs(x[0] - before) / 0.01);
  }
  // After 30 s the servo has long reached the 47° stop; error is e^{−(30−8)/0.3} ≈ 0.
  EXPECT_NEAR(x[0], p.max_angle, 1e-12);
  // Every RK4 stage slope is bounded by r, so the step slope is too (rounding only).
  EXPECT_LE(max_rate, p.rate_limit * (1.0 + 1e-9));
  EXPECT_NEAR(p.max_angle, 47.0 * kDeg, 1e-15);
}

TEST(Rudder, StepResponsesMatchTables333To336) {
  const Rudder rudder;
  struct Case {
    double from_deg, to_deg, t_lo, t_hi;
  };
  // Thesis ranges per step kind (tables 3.33–3.36), widened by ±0.1 s for reading precision.
  for (const Case& c : {Case{0, 20, 1.6, 2.1}, Case{20, 47, 2.0, 2.5}, Case{47, 0, 4.0, 4.5},
                        Case{0, -20, 1.6, 2.1}, Case{-47, 0, 4.0, 4.5}}) {
    SCOPED_TRACE(testing::Message() << c.from_deg << " -> " << c.to_deg << " deg");
    const FopdtTruth truth = rudder_step_truth(rudder, c.from_deg * kDeg, c.to_deg * kDeg);
    EXPECT_GE(truth.time_constant, c.t_lo);
    EXPECT_LE(truth.time_constant, c.t_hi);
    EXPECT_GE(truth.dead_time, 0.7);
    EXPECT_LE(truth.dead_time, 1.6);
  }
  // Larger steps are slower.
  EXPECT_LT(rudder_step_truth(rudder, 0, 20 * kDeg).time_constant,
            rudder_step_truth(rudder, 0, 40 * kDeg).time_constant);
}

TEST(Rudder, NoInflowNoForce) {
  const Rudder rudder;
  const RudderForce f = rudder.force(30 * kDeg, RudderInflow{0.0, 0.0, 0.0});
  EXPECT_EQ(f.f_b, Eigen::Vector2d::Zero());
  EXPECT_EQ(f.lift, 0.0);
  // Astern thrust gives no slipstream over the rudder either.
  EXPECT_EQ(rudder.force(30 * kDeg, RudderInflow{0.0, 0.0, -20e3}).f_b, Eigen::Vector2d::Zero());
}

TEST(Rudder, PositiveAngleTurnsToStarboardAheadAndReversesAstern) {
  const Rudder rudder;
  // Ahead at 3 m/s: α > 0 (trailing edge to starboard) pushes the stern to port (F_y < 0),
  // which at x < 0 is N = x·F_y > 0: a starboard turn. Drag opposes the motion (F_x < 0).
  const RudderForce ahead = rudder.force(15 * kDeg, RudderInflow{3.0, 0.0, 0.0});
  EXPECT_LT(ahead.f_b.y(), 0.0);
  EXPECT_LT(ahead.f_b.x(), 0.0);
  EXPECT_NEAR(ahead.angle_of_attack, 15 * kDeg, 1e-12);
  // Negative angle mirrors.
  const RudderForce mirror = rudder.force(-15 * kDeg, RudderInflow{3.0, 0.0, 0.0});
  EXPECT_NEAR(mirror.f_b.y(), -ahead.f_b.y(), 1e-9);
  // Astern at 3 m/s: the side force reverses and is weaker.
  const RudderForce astern = rudder.force(15 * kDeg, RudderInflow{-3.0, 0.0, 0.0});
  EXPECT_GT(astern.f_b.y(), 0.0);
  EXPECT_LT(std::abs(astern.f_b.y()), std::abs(ahead.f_b.y()));
  EXPECT_GT(astern.f_b.x(), 0.0);  // drag opposes astern motion
}

TEST(Rudder, SlipstreamSteersAtZeroSpeed) {
  const Rudder rudder;
  const RudderParams& p = rudder.params();
  const double thrust = 40e3;
  const RudderForce f = rudder.force(10 * kDeg, RudderInflow{0.0, 0.0, thrust});
  EXPECT_LT(f.f_b.y(), 0.0);
  // Momentum theory at V_a = 0: q = η·4T/(πD²); F_y = −q·A·C_Lα·α in the linear region.
  const double q = p.slipstream_fraction * 4.0 * thrust / (std::numbers::pi * 4.0);
  EXPECT_NEAR(f.dynamic_pressure, q, 1e-9 * q);
  EXPECT_NEAR(f.f_b.y(), -q * p.area * p.lift_slope * 10 * kDeg, 1e-9 * q * p.area);
}

TEST(Rudder, DriftAtTheRudderChangesTheAngleOfAttack) {
  const Rudder rudder;
  // Stern moving to port (v < 0) while turning to starboard: water comes from port and reduces
  // the effective angle of a starboard rudder, α_e = α − atan(γ|v|/u).
  const RudderForce f = rudder.force(20 * kDeg, RudderInflow{3.0, -1.0, 0.0});
  const double expected = 20 * kDeg - std::atan2(0.5 * 1.0, 3.0);
  EXPECT_NEAR(f.angle_of_attack, expected, 1e-12);
}

TEST(Rudder, LiftCurveIsLinearOddAndContinuousAtStall) {
  const Rudder rudder;
  const RudderParams& p = rudder.params();
  EXPECT_DOUBLE_EQ(rudder.lift_coefficient(0.1), p.lift_slope * 0.1);
  EXPECT_DOUBLE_EQ(rudder.lift_coefficient(-0.3), -rudder.lift_coefficient(0.3));
  // Continuity at stall: a 1e-9 rad step changes C_L by ≤ C_Lα·1e-9.
  EXPECT_NEAR(rudder.lift_coefficient(p.stall_angle + 1e-9), rudder.lift_coefficient(p.stall_angle),
              1e-8);
  EXPECT_LT(rudder.lift_coefficient(47 * kDeg), rudder.lift_coefficient(p.stall_angle));
  EXPECT_NEAR(rudder.lift_coefficient(std::numbers::pi / 2),
              p.post_stall_lift_fraction * p.lift_slope * p.stall_angle, 1e-12);
}

TEST(Rudder, LiftFallsOverThePostStallWidthAndStaysFlat) {
  RudderParams p;
  p.stall_angle = 30 * kDeg;
  p.post_stall_width = 10 * kDeg;
  p.post_stall_lift_fraction = 0.6;
  const Rudder rudder(p);
  const double peak = p.lift_slope * p.stall_angle;
  // Halfway through the fall: 1 − 0.4/2 of the peak; at its end and beyond: 0.6 of it.
  EXPECT_NEAR(rudder.lift_coefficient(35 * kDeg), 0.8 * peak, 1e-12);
  EXPECT_NEAR(rudder.lift_coefficient(40 * kDeg), 0.6 * peak, 1e-12);
  EXPECT_NEAR(rudder.lift_coefficient(47 * kDeg), 0.6 * peak, 1e-12);
  EXPECT_NEAR(rudder.lift_coefficient(-89 * kDeg), -0.6 * peak, 1e-12);
  // Width and fraction are validated.
  p.post_stall_width = 0.0;
  EXPECT_THROW(Rudder{p}, core::InputError);
  p.post_stall_width = 91 * kDeg;
  EXPECT_THROW(Rudder{p}, core::InputError);
}

TEST(Rudder, SideForceInversionRoundTrips) {
  const Rudder rudder;
  for (double u : {0.0, 1.5, 3.0}) {
    for (double thrust : {5e3, 40e3}) {
      const double y_max = rudder.max_side_force(u, thrust);
      for (double frac : {-0.9, -0.2, 0.5}) {
        const double y = frac * y_max;
        const double a = rudder.angle_for_side_force(y, u, thrust);
        // Straight-ahead flow: F_y = −L exactly; rounding only, 1e-9 relative.
        EXPECT_NEAR(rudder.force(a, RudderInflow{u, 0.0, thrust}).f_b.y(), y, 1e-9 * y_max);
      }
    }
  }
  EXPECT_EQ(rudder.angle_for_side_force(1e3, 0.0, 0.0), 0.0);
}

TEST(Rudder, ValidateNamesTheField) {
  RudderParams p;
  p.rate_limit = 0.0;
  EXPECT_THAT([&] { p.validate(); }, testing::ThrowsMessage<core::InputError>(
                                         testing::HasSubstr("rudder.rate_limit_deg_per_s")));
  p = RudderParams{};
  p.max_angle = 2.0;
  EXPECT_THROW(Rudder{p}, core::InputError);
}

}  // namespace
}  // namespace dynpos::model
