#include "dynpos/sim/noise.hpp"

#include "format_number.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

namespace dynpos::sim {

namespace {

void require(bool condition, const char* where, const std::string& message) {
  if (!condition) throw std::invalid_argument(std::string(where) + ": " + message);
}

void check_time_constant_and_dt(const char* where, double time_constant, double dt) {
  require(!std::isnan(time_constant) && time_constant > 0.0, where,
          "time constant T = " + detail::format_number(time_constant) +
              " s must be > 0 (+inf for a random walk)");
  require(std::isfinite(dt) && dt > 0.0, where,
          "dt = " + detail::format_number(dt) + " s must be finite and > 0");
}

}  // namespace

WhiteNoise::WhiteNoise(double std_dev, Rng rng) : std_dev_(std_dev), rng_(std::move(rng)) {
  require(std::isfinite(std_dev) && std_dev >= 0.0, "WhiteNoise",
          "std = " + detail::format_number(std_dev) + " must be finite and >= 0");
}

double discrete_std_from_psd(double psd, double dt) {
  require(std::isfinite(psd) && psd >= 0.0, "discrete_std_from_psd",
          "psd = " + detail::format_number(psd) + " must be finite and >= 0");
  require(std::isfinite(dt) && dt > 0.0, "discrete_std_from_psd",
          "dt = " + detail::format_number(dt) + " s must be finite and > 0");
  return std::sqrt(psd / dt);
}

GaussMarkov::GaussMarkov(double time_constant, double stationary_std, double phi, double step_std,
                         double dt, Rng rng, double initial)
    : time_constant_(time_constant),
      stationary_std_(stationary_std),
      phi_(phi),
      step_std_(step_std),
      dt_(dt),
      rng_(std::move(rng)),
      value_(initial) {}

GaussMarkov GaussMarkov::with_stationary_std(double time_constant, double stationary_std, double dt,
                                             Rng rng, double initial) {
  constexpr const char* kWhere = "GaussMarkov::with_stationary_std";
  check_time_constant_and_dt(kWhere, time_constant, dt);
  require(std::isfinite(time_constant), kWhere,
          "a random walk (T = inf) has no stationary std; use random_walk()");
  require(std::isfinite(stationary_std) && stationary_std >= 0.0, kWhere,
          "stationary std = " + detail::format_number(stationary_std) + " must be finite and >= 0");
  const double phi = std::exp(-dt / time_constant);
  // 1 − e^{−2dt/T} by expm1, accurate when dt ≪ T.
  const double step_std = stationary_std * std::sqrt(-std::expm1(-2.0 * dt / time_constant));
  return GaussMarkov(time_constant, stationary_std, phi, step_std, dt, std::move(rng), initial);
}

GaussMarkov GaussMarkov::with_noise_intensity(double time_constant, double noise_intensity,
                                              double dt, Rng rng, double initial) {
  constexpr const char* kWhere = "GaussMarkov::with_noise_intensity";
  check_time_constant_and_dt(kWhere, time_constant, dt);
  require(
      std::isfinite(noise_intensity) && noise_intensity >= 0.0, kWhere,
      "noise intensity q = " + detail::format_number(noise_intensity) + " must be finite and >= 0");
  if (std::isinf(time_constant)) {
    return GaussMarkov(time_constant, std::numeric_limits<double>::infinity(), 1.0,
                       noise_intensity * std::sqrt(dt), dt, std::move(rng), initial);
  }
  const double phi = std::exp(-dt / time_constant);
  // Var of the increment: q²·T/2·(1 − e^{−2dt/T}), which tends to q²·dt as T → ∞.
  const double step_std =
      noise_intensity * std::sqrt(-0.5 * time_constant * std::expm1(-2.0 * dt / time_constant));
  const double stationary_std = noise_intensity * std::sqrt(0.5 * time_constant);
  return GaussMarkov(time_constant, stationary_std, phi, step_std, dt, std::move(rng), initial);
}

GaussMarkov GaussMarkov::random_walk(double noise_intensity, double dt, Rng rng, double initial) {
  return with_noise_intensity(std::numeric_limits<double>::infinity(), noise_intensity, dt,
                              std::move(rng), initial);
}

void GaussMarkov::reset_stationary() {
  if (!std::isfinite(stationary_std_)) {
    throw std::logic_error("GaussMarkov::reset_stationary: a random walk has no stationary law");
  }
  value_ = stationary_std_ * rng_.normal();
}

double quantize(double value, double resolution) {
  if (!(std::isfinite(resolution) && resolution >= 0.0)) {  // message built only on failure
    require(false, "quantize",
            "resolution = " + detail::format_number(resolution) + " must be finite and >= 0");
  }
  if (resolution == 0.0) return value;
  return std::round(value / resolution) * resolution;
}

}  // namespace dynpos::sim
