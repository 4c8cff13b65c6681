#include "dynpos/scenario/operator_commands.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dynpos/core/angle.hpp"
#include "dynpos/core/log.hpp"
#include "dynpos/sim/sim_time.hpp"

namespace dynpos::scenario {
namespace {

TEST(JoystickSchedule, CommandHoldsFromTheFirstControlStepAtItsTime) {
  JoystickSchedule js({{10.0, 30.0, 0.0, 0.0}, {20.0, 30.0, 40.0, 10.0}},
                      Eigen::Vector3d(5.0, 0.0, 0.0));
  EXPECT_FALSE(js.advance(0.0));
  EXPECT_EQ(js.lever_pct(), Eigen::Vector3d(5.0, 0.0, 0.0));  // the trim until the first
  // Control steps are products k·dt: 10 s may come out a rounding below 10.
  const sim::TimeGrid grid(0.01);
  EXPECT_FALSE(js.advance(grid.time(999)));
  EXPECT_TRUE(js.advance(std::nextafter(10.0, 0.0)));
  EXPECT_EQ(js.lever_pct(), Eigen::Vector3d(30.0, 0.0, 0.0));
  EXPECT_FALSE(js.advance(10.1));  // held, and not applied again
  EXPECT_EQ(js.lever_pct(), Eigen::Vector3d(30.0, 0.0, 0.0));
  EXPECT_TRUE(js.advance(25.0));
  EXPECT_EQ(js.lever_pct(), Eigen::Vector3d(30.0, 40.0, 10.0));
}

TEST(JoystickSchedule, SeveralDueCommandsLeaveTheLastOne) {
  JoystickSchedule js({{1.0, 10.0, 0.0, 0.0}, {2.0, 20.0, 0.0, 0.0}}, Eigen::Vector3d::Zero());
  EXPECT_TRUE(js.advance(5.0));
  EXPECT_EQ(js.lever_pct().x(), 20.0);
}

class RudderScheduleTest : public testing::Test {
 protected:
  model::Rudder rudder;
  model::Hull hull;
  const double x_rudder_m = -14.0;
  const double dt_s = 0.01;
};

TEST_F(RudderScheduleTest, StepOverridesBothRuddersAndRecordsItsTruth) {
  RudderSchedule schedule({{10.0, 20.0, false}}, rudder, hull, x_rudder_m, dt_s);
  EXPECT_FALSE(schedule.advance(9.9, 0.01, 3.0).has_value());
  const std::optional<double>& angle = schedule.advance(10.0, 0.01, 3.0);
  ASSERT_TRUE(angle.has_value());
  EXPECT_EQ(*angle, core::deg_to_rad(20.0));
  ASSERT_EQ(schedule.steps().size(), 1u);
  const RudderStepTruth& step = schedule.steps()[0];
  EXPECT_EQ(step.t_s, 10.0);
  EXPECT_EQ(step.from_deg, core::rad_to_deg(0.01));  // from the allocation's last command
  EXPECT_EQ(step.to_deg, 20.0);
  EXPECT_EQ(step.surge_mps, 3.0);
  const model::FopdtTruth servo =
      model::rudder_step_truth(rudder, 0.01, core::deg_to_rad(20.0), dt_s);
  EXPECT_EQ(step.servo.time_constant, servo.time_constant);
  EXPECT_EQ(step.servo.dead_time, servo.dead_time);
  ASSERT_TRUE(step.nomoto.has_value());
  EXPECT_EQ(step.nomoto->Tr_s, hull.nomoto(3.0, x_rudder_m).tr_s);
  // Held at later steps, without a new record.
  EXPECT_EQ(*schedule.advance(11.0, 0.0, 3.0), core::deg_to_rad(20.0));
  EXPECT_EQ(schedule.steps().size(), 1u);
}

TEST_F(RudderScheduleTest, NextStepStartsAtTheOverrideAndReleaseHandsBack) {
  RudderSchedule schedule({{10.0, 20.0, false}, {30.0, -20.0, false}, {50.0, 0.0, true}}, rudder,
                          hull, x_rudder_m, dt_s);
  (void)schedule.advance(10.0, 0.0, 3.0);
  (void)schedule.advance(30.0, 0.3, 3.0);  // the allocation's command is not where it starts
  ASSERT_EQ(schedule.steps().size(), 2u);
  EXPECT_NEAR(schedule.steps()[1].from_deg, 20.0, 1e-12);
  EXPECT_EQ(schedule.steps()[1].to_deg, -20.0);
  EXPECT_FALSE(schedule.advance(50.0, 0.0, 3.0).has_value());
  EXPECT_EQ(schedule.steps().size(), 2u);  // a release is not a step
}

TEST_F(RudderScheduleTest, TruthIsWithinTheServoLimitAndNomotoNeedsSpeed) {
  RudderSchedule schedule({{0.0, 80.0, false}}, rudder, hull, x_rudder_m, dt_s);
  // The override is the command as given (the servo limits it); the truth is where it ends.
  EXPECT_EQ(*schedule.advance(0.0, 0.0, 0.05), core::deg_to_rad(80.0));
  const RudderStepTruth& step = schedule.steps()[0];
  EXPECT_NEAR(step.to_deg, core::rad_to_deg(rudder.params().max_angle), 1e-12);
  EXPECT_LT(step.to_deg, 80.0);
  EXPECT_FALSE(step.nomoto.has_value());  // 0.05 m/s: no Nomoto model at rest
}

TEST(SetpointSchedule, TimedSetpointsApplyAtTheirTimes) {
  SetpointSchedule schedule({{0.0, 0.0, 0.0, 0.0, "hold"}, {100.0, 50.0, 0.0, 90.0, "ahead"}});
  EXPECT_FALSE(schedule.active());
  EXPECT_TRUE(core::is_missing(schedule.setpoint_n().x()));
  schedule.advance(0.0, Eigen::Vector3d(10.0, 0.0, 0.0));  // 10 m off: not reached
  ASSERT_TRUE(schedule.active());
  EXPECT_EQ(schedule.setpoint_n(), Eigen::Vector3d::Zero());
  ASSERT_EQ(schedule.legs().size(), 1u);
  EXPECT_FALSE(schedule.legs()[0].t_reached_s.has_value());
  schedule.advance(40.0, Eigen::Vector3d(1.0, 0.0, 0.0));  // inside the 2 m circle
  EXPECT_EQ(schedule.legs()[0].t_reached_s, 40.0);
  schedule.advance(50.0, Eigen::Vector3d(0.0, 0.0, 0.0));
  EXPECT_EQ(schedule.legs()[0].t_reached_s, 40.0);  // the first time only
  schedule.advance(100.0, Eigen::Vector3d(0.0, 0.0, 0.0));
  ASSERT_EQ(schedule.legs().size(), 2u);
  EXPECT_EQ(schedule.legs()[0].t_end_s, 100.0);
  EXPECT_EQ(schedule.legs()[1].name, "ahead");
  EXPECT_EQ(schedule.legs()[1].t_start_s, 100.0);
  EXPECT_EQ(schedule.setpoint_n(), Eigen::Vector3d(50.0, 0.0, core::deg_to_rad(90.0)));
  EXPECT_FALSE(schedule.legs()[1].t_end_s.has_value());
}

TEST(SetpointSchedule, UntimedSetpointFollowsWhenThePreviousIsReached) {
  SetpointSchedule schedule({{0.0, 0.0, 0.0, 0.0, "hold"}, {-1.0, 50.0, 0.0, 0.0, "ahead"}});
  schedule.advance(0.0, Eigen::Vector3d(5.0, 0.0, 0.0));
  schedule.advance(10.0, Eigen::Vector3d(3.0, 0.0, 0.0));
  ASSERT_EQ(schedule.legs().size(), 1u);
  // Heading outside its 2° tolerance: not reached yet.
  schedule.advance(20.0, Eigen::Vector3d(0.5, 0.0, core::deg_to_rad(5.0)));
  ASSERT_EQ(schedule.legs().size(), 1u);
  schedule.advance(30.0, Eigen::Vector3d(0.5, 0.0, 0.0));
  ASSERT_EQ(schedule.legs().size(), 2u);
  EXPECT_EQ(schedule.legs()[0].t_reached_s, 30.0);
  EXPECT_EQ(schedule.legs()[0].t_end_s, 30.0);
  EXPECT_EQ(schedule.legs()[1].t_start_s, 30.0);
  EXPECT_FALSE(schedule.legs()[1].t_reached_s.has_value());  // 49.5 m from the new one
}

}  // namespace
}  // namespace dynpos::scenario
