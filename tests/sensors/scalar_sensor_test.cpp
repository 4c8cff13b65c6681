#include "dynpos/sensors/scalar_sensor.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "dynpos/core/error.hpp"

namespace dynpos::sensors {
namespace {

TEST(ScalarSensor, NoiselessSensorQuantises) {
  ScalarSensor s({0.0, 0.0, 600.0, 0.1}, 1.0, sim::Rng(1));
  EXPECT_DOUBLE_EQ(s.measure(1.234), 1.2);
  EXPECT_DOUBLE_EQ(s.measure(-0.26), -0.3);
}

TEST(ScalarSensor, NoiseHasTheConfiguredStd) {
  ScalarSensor s({0.5, 0.0, 600.0, 0.0}, 1.0, sim::Rng(7));
  const int n = 20000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    const double y = s.measure(3.0) - 3.0;
    sum += y;
    sum2 += y * y;
  }
  const double mean = sum / n, std_dev = std::sqrt(sum2 / n - mean * mean);
  // Sample std of n = 2·10⁴ normals has relative std 1/√(2n) = 0.5 %; 3 % is > 5σ.
  EXPECT_NEAR(std_dev, 0.5, 0.03 * 0.5);
  // Mean: std 0.5/√n = 0.0035; 0.02 is > 5σ.
  EXPECT_NEAR(mean, 0.0, 0.02);
}

TEST(ScalarSensor, BiasIsSlowlyVarying) {
  // Bias only, σ_b = 1, T = 1000 samples: consecutive samples differ by ~σ√(2/T) ≈ 0.045.
  ScalarSensor s({0.0, 1.0, 1000.0, 0.0}, 1.0, sim::Rng(3));
  double prev = s.measure(0.0), max_step = 0.0;
  for (int i = 0; i < 1000; ++i) {
    const double y = s.measure(0.0);
    max_step = std::max(max_step, std::abs(y - prev));
    prev = y;
  }
  EXPECT_LT(max_step, 0.3);  // > 6σ of the increment
}

TEST(ScalarSensor, SameStreamSameSamples) {
  ScalarSensor a({0.5, 0.2, 60.0, 0.01}, 0.1, sim::Rng(42, "gyro"));
  ScalarSensor b({0.5, 0.2, 60.0, 0.01}, 0.1, sim::Rng(42, "gyro"));
  for (int i = 0; i < 100; ++i) EXPECT_EQ(a.measure(i), b.measure(i));
}

TEST(ScalarSensor, RejectsNegativeNoise) {
  EXPECT_THROW(ScalarSensor({-1.0, 0.0, 600.0, 0.0}, 1.0, sim::Rng(1)), core::InputError);
}

}  // namespace
}  // namespace dynpos::sensors
