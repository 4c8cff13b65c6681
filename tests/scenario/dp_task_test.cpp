#include "dynpos/scenario/dp_task.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dynpos/core/log.hpp"

namespace dynpos::scenario {
namespace {

ScenarioSpec dp_spec(bool hybrid) {
  ScenarioSpec s;
  s.duration_s = 100.0;
  s.setpoints = {{10.0, 0.0, 0.0, 0.0, "hold"}};
  if (hybrid) s.hybrid_integral = hybrid::IntegralJumpParams{};
  return s;
}

TEST(DpTask, ControllerModelIsTheHullsWithSymmetricCoupling) {
  const VesselConfig vessel;
  const model::Hull hull(vessel.hull);
  const control::DpControllerParams p = dp_controller_params(vessel, hull);
  EXPECT_EQ(p.M(1, 2), p.M(2, 1));
  EXPECT_EQ(p.M(1, 2), 0.5 * (hull.mass_matrix()(1, 2) + hull.mass_matrix()(2, 1)));
  EXPECT_EQ(p.M(0, 0), hull.mass_matrix()(0, 0));
  EXPECT_EQ(p.D.diagonal(),
            Eigen::Vector3d(vessel.hull.x_u_Ns_m, vessel.hull.y_v_Ns_m, vessel.hull.n_r_Nms));
  EXPECT_NO_THROW(p.validate());
}

TEST(DpTask, NoDemandBeforeTheFirstSetpoint) {
  const VesselConfig vessel;
  DpTask dp(dp_spec(false), vessel, model::Hull(vessel.hull), Eigen::Vector3d::Zero(), 0.1);
  EXPECT_FALSE(dp.control(5.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()).has_value());
  EXPECT_FALSE(dp.active());
  EXPECT_TRUE(core::is_missing(dp.setpoint_n().x()));
  dp.integrate_bias(0.0, true);  // nothing to integrate
  EXPECT_EQ(dp.bias_hat_n(), Eigen::Vector3d::Zero());
}

TEST(DpTask, AtRestOnTheSetpointTheDemandIsZeroAndTheSplitHeld) {
  const VesselConfig vessel;
  DpTask dp(dp_spec(false), vessel, model::Hull(vessel.hull), Eigen::Vector3d::Zero(), 0.1);
  const std::optional<DpDemand> d =
      dp.control(10.0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  ASSERT_TRUE(d.has_value());
  EXPECT_TRUE(dp.active());
  EXPECT_EQ(d->tau_b, Eigen::Vector3d::Zero());
  EXPECT_TRUE(d->hold_split);
}

TEST(DpTask, OffsetGivesARestoringDemandAndTheBiasIntegratesOnlyWhenMet) {
  const VesselConfig vessel;
  const model::Hull hull(vessel.hull);
  DpTask dp(dp_spec(false), vessel, hull, Eigen::Vector3d::Zero(), 0.1);
  // 3 m north of the setpoint: the demand pushes south (5.38), and b̂ (5.36) grows as if a
  // bias pushed north.
  const Eigen::Vector3d eta(3.0, 0.0, 0.0);
  const std::optional<DpDemand> d = dp.control(10.0, eta, Eigen::Vector3d::Zero());
  ASSERT_TRUE(d.has_value());
  EXPECT_LT(d->tau_b.x(), 0.0);
  dp.integrate_bias(0.0, false);  // saturated allocation: frozen
  EXPECT_EQ(dp.bias_hat_n(), Eigen::Vector3d::Zero());
  dp.integrate_bias(0.0, true);
  const control::DpController controller(dp_controller_params(vessel, hull));
  const control::DpCommand c = controller.control(eta, Eigen::Vector3d::Zero(),
                                                  control::DpReference{}, Eigen::Vector3d::Zero());
  EXPECT_EQ(dp.bias_hat_n(), controller.advance_bias(Eigen::Vector3d::Zero(), 0.0, c.x2, 0.1));
  EXPECT_GT(dp.bias_hat_n().x(), 0.0);  // b̂ takes up a force pushing north
}

TEST(DpTask, HybridIntegralActionJumpsTheBiasEstimate) {
  // 5 m north of the setpoint drifting further north at 0.3 m/s: x₁ = 5 m, x₂ = ν − μ =
  // 0.3 + K_p·5 = 0.7 m/s, constant, so ẋ₂ = 0 and x̂₃ = x₁ + K_d·x₂ ≈ 56 kN north: inside the
  // jump set, and Δb̂ = λ·x₂ = 42 kN north (within the 60 kN bound).
  const VesselConfig vessel;
  const model::Hull hull(vessel.hull);
  const Eigen::Vector3d eta(5.0, 0.0, 0.0), nu(0.3, 0.0, 0.0);
  DpTask with(dp_spec(true), vessel, hull, Eigen::Vector3d::Zero(), 0.1);
  DpTask without(dp_spec(false), vessel, hull, Eigen::Vector3d::Zero(), 0.1);
  ASSERT_TRUE(with.jumps().has_value());
  EXPECT_FALSE(without.jumps().has_value());
  (void)with.control(10.0, eta, nu);
  (void)without.control(10.0, eta, nu);
  EXPECT_EQ(with.bias_hat_n(), without.bias_hat_n());  // one sample: no ẋ₂ yet
  (void)with.control(10.1, eta, nu);
  (void)without.control(10.1, eta, nu);
  ASSERT_EQ(with.jumps()->jump_times().size(), 1u);
  EXPECT_EQ(with.jumps()->jump_times()[0], 10.1);
  EXPECT_NEAR(with.bias_hat_n().x() - without.bias_hat_n().x(),
              hybrid::IntegralJumpParams{}.lambda.x() * 0.7, 1e-6);
}

}  // namespace
}  // namespace dynpos::scenario
