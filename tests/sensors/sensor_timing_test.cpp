#include "dynpos/sensors/sensor_timing.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "dynpos/core/error.hpp"

namespace dynpos::sensors {
namespace {

TEST(SensorTiming, SlowSensorFiresOnEveryNthLoggerTick) {
  const SampleSchedule s = make_schedule({1.0, 0.0}, 100.0, "gnss1");
  EXPECT_EQ(s.every, 100u);
  EXPECT_EQ(s.delay, 0u);
  EXPECT_DOUBLE_EQ(s.period_s, 1.0);
  EXPECT_TRUE(s.fires(0));
  EXPECT_FALSE(s.fires(99));
  EXPECT_TRUE(s.fires(200));
}

TEST(SensorTiming, FastSensorIsRecordedAtTheLoggerRate) {
  const SampleSchedule s = make_schedule({100.0, 0.0}, 50.0, "mru1");
  EXPECT_EQ(s.every, 1u);
  EXPECT_DOUBLE_EQ(s.period_s, 0.02);
}

TEST(SensorTiming, LatencyInLoggerTicks) {
  EXPECT_EQ(make_schedule({1.0, 0.2}, 100.0, "gnss1").delay, 20u);
  EXPECT_EQ(make_schedule({1.0, 0.2}, 10.0, "gnss1").delay, 2u);
}

TEST(SensorTiming, RejectsRatesThatDoNotDivideTheLoggerRate) {
  EXPECT_THROW(make_schedule({3.0, 0.0}, 10.0, "gyro"), std::invalid_argument);
}

TEST(SensorTiming, RejectsOffsetsOffTheTickGridAndNegativeOffsets) {
  EXPECT_THROW(make_schedule({1.0, 0.15}, 10.0, "gnss1"), std::invalid_argument);
  EXPECT_THROW(make_schedule({1.0, -0.1}, 10.0, "gnss1"), core::InputError);
  EXPECT_THROW(make_schedule({0.0, 0.0}, 10.0, "gnss1"), std::invalid_argument);
}

}  // namespace
}  // namespace dynpos::sensors
