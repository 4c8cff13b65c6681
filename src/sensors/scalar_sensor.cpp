#include "dynpos/sensors/scalar_sensor.hpp"

#include <fmt/core.h>

#include <cmath>

#include "dynpos/core/error.hpp"

namespace dynpos::sensors {

void ScalarNoiseParams::validate(const char* what) const {
  const auto nonneg = [](double v) { return std::isfinite(v) && v >= 0.0; };
  if (!nonneg(noise_std) || !nonneg(bias_std) || !nonneg(resolution)) {
    throw core::InputError(
        {}, fmt::format("{}: noise std, bias std and resolution must be finite and ≥ 0", what));
  }
  if (!(bias_time_constant_s > 0.0)) {
    throw core::InputError({}, fmt::format("{}: bias time constant must be > 0", what));
  }
}

ScalarSensor::ScalarSensor(const ScalarNoiseParams& params, double period_s, sim::Rng rng)
    : params_(params),
      rng_(rng.next_u64()),
      bias_(sim::GaussMarkov::with_stationary_std(params.bias_time_constant_s, params.bias_std,
                                                  period_s, sim::Rng(rng.next_u64()))) {
  params_.validate("ScalarSensor");
  bias_.reset_stationary();
}

double ScalarSensor::measure(double x) {
  // Zero-std parts draw nothing: a noiseless channel costs no random numbers.
  double y = x;
  if (params_.bias_std > 0.0) {
    y += bias_.value();
    bias_.step();
  }
  if (params_.noise_std > 0.0) y += params_.noise_std * rng_.normal();
  return sim::quantize(y, params_.resolution);
}

}  // namespace dynpos::sensors
