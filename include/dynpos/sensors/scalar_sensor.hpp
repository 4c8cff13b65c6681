#pragma once
/// \file
/// ScalarSensor: one measured channel, y = quantize(x + b + w), with white noise w, a first-order
/// Gauss–Markov bias b (2.22) and a resolution. Gyro compass, speed log, wind sensor, rudder
/// and thruster feedback are made of these.

#include "dynpos/sim/noise.hpp"
#include "dynpos/sim/random.hpp"

namespace dynpos::sensors {

struct ScalarNoiseParams {
  double noise_std = 0.0;  ///< σ_w of the white noise, in the channel's SI unit (≥ 0)
  double bias_std = 0.0;   ///< stationary σ of the bias, SI unit (≥ 0; 0: no bias)
  double bias_time_constant_s = 600.0;  ///< T of the bias (> 0) [s]
  double resolution = 0.0;              ///< quantisation step, SI unit (≥ 0; 0: none)

  /// Throws core::InputError naming `what` unless the sensor can run (the signs above); the
  /// vessel file's ranges in the channel's unit are checked by SensorSuiteParams::validate.
  void validate(const char* what) const;
};

class ScalarSensor {
 public:
  /// A channel sampled every period_s (> 0) with its own stream `rng`; the bias starts from its
  /// stationary distribution.
  ScalarSensor(const ScalarNoiseParams& params, double period_s, sim::Rng rng);

  /// The measurement of the true value x; advances the noise by one sample.
  double measure(double x);

 private:
  ScalarNoiseParams params_;
  sim::Rng rng_;
  sim::GaussMarkov bias_;
};

}  // namespace dynpos::sensors
