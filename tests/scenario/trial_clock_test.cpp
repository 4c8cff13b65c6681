#include "dynpos/scenario/trial_clock.hpp"

#include <gtest/gtest.h>

namespace dynpos::scenario {
namespace {

ScenarioSpec spec_with(double settle_s, double log_rate_hz) {
  ScenarioSpec s;
  s.duration_s = 60.0;
  s.dt_s = 0.01;
  s.settle_s = settle_s;
  s.log_rate_hz = log_rate_hz;
  return s;
}

TEST(TrialClock, ScenarioTimeStartsAfterTheSettlingTime) {
  const TrialClock clock(spec_with(600.0, 10.0));
  EXPECT_EQ(clock.scenario_tick(60000), 0);
  EXPECT_EQ(clock.time(60000), 0.0);
  EXPECT_EQ(clock.time(60123), 0.01 * 123);  // (k − k_settle)·dt, one multiplication
  EXPECT_EQ(clock.time(0), -600.0);
  EXPECT_EQ(clock.end_time_s(), 660.0);
  EXPECT_DOUBLE_EQ(clock.log_period_s(), 0.1);
}

TEST(TrialClock, LoggersRecordOnTheLogTicksFromTimeZero) {
  const TrialClock clock(spec_with(1.0, 10.0));
  EXPECT_FALSE(clock.logs_at(0));   // settling
  EXPECT_FALSE(clock.logs_at(90));  // settling
  EXPECT_TRUE(clock.logs_at(100));  // t = 0
  EXPECT_FALSE(clock.logs_at(105));
  EXPECT_TRUE(clock.logs_at(110));
}

TEST(TrialClock, LogTicksAreTheSimulatorsEvenWhenTheSettlingIsNotALogPeriod) {
  // A 0.5 Hz log (2 s) after 1 s of settling: the loggers are periodic tasks from tick 0, so
  // they record at t = 1 s, 3 s, … and not at t = 0.
  const TrialClock clock(spec_with(1.0, 0.5));
  EXPECT_FALSE(clock.logs_at(100));
  EXPECT_TRUE(clock.logs_at(200));
  EXPECT_EQ(clock.time(200), 1.0);
}

TEST(TrialClock, ScenarioContextCarriesScenarioTime) {
  const TrialClock clock(spec_with(2.0, 10.0));
  Eigen::VectorXd x = Eigen::VectorXd::Constant(2, 3.0), u = Eigen::VectorXd::Zero(1);
  sim::TaskContext c(250, 2.5, x, u);
  const sim::TaskContext at = clock.scenario_context(c);
  EXPECT_EQ(at.tick(), 50);
  EXPECT_EQ(at.time(), 0.5);
  EXPECT_EQ(&at.state(), &x);
  EXPECT_EQ(&at.input(), &u);
}

}  // namespace
}  // namespace dynpos::scenario
