#include "dynpos/sensors/mru.hpp"

#include <cmath>
#include <stdexcept>

namespace dynpos::sensors {

std::string_view to_string(AccelerationConvention c) {
  return c == AccelerationConvention::kKinematic ? "kinematic" : "specific-force";
}

std::optional<AccelerationConvention> parse_acceleration_convention(std::string_view s) {
  if (s == "kinematic") return AccelerationConvention::kKinematic;
  if (s == "specific-force") return AccelerationConvention::kSpecificForce;
  return std::nullopt;
}

void MruParams::validate() const {
  timing.validate(name.c_str());
  if (!lever_arm_b.allFinite()) throw std::invalid_argument(name + ": lever arm must be finite");
  const auto nonneg = [](double v) { return std::isfinite(v) && v >= 0.0; };
  if (!nonneg(angle_std_rad) || !nonneg(rate_std_rad_s) || !nonneg(accel_std_mps2) ||
      !nonneg(accel_bias_std_mps2)) {
    throw std::invalid_argument(name + ": noise and bias std must be ≥ 0");
  }
  if (!(accel_bias_time_constant_s > 0.0)) {
    throw std::invalid_argument(name + ": bias time constant must be > 0");
  }
}

namespace {

sim::GaussMarkov accel_bias(const MruParams& p, double period_s, std::uint64_t seed,
                            const char* axis) {
  sim::GaussMarkov b =
      sim::GaussMarkov::with_stationary_std(p.accel_bias_time_constant_s, p.accel_bias_std_mps2,
                                            period_s, sim::Rng(seed, p.name + ".bias." + axis));
  b.reset_stationary();
  return b;
}

}  // namespace

Mru::Mru(const MruParams& params, AccelerationConvention convention, double period_s,
         std::uint64_t seed)
    : params_(params),
      convention_(convention),
      rng_(seed, params.name + ".noise"),
      accel_bias_{accel_bias(params, period_s, seed, "x"), accel_bias(params, period_s, seed, "y"),
                  accel_bias(params, period_s, seed, "z")} {
  params_.validate();
}

MruSample Mru::measure(const RigidBodyMotion& m) {
  MruSample s;
  const MruParams& p = params_;
  // Zero-std parts draw nothing (noise-free runs are cheap and exact).
  const auto noise = [this](double std_dev) {
    return std_dev > 0.0 ? std_dev * rng_.normal() : 0.0;
  };
  s.roll = m.theta.x() + noise(p.angle_std_rad);
  s.pitch = m.theta.y() + noise(p.angle_std_rad);
  for (int i = 0; i < 3; ++i) s.omega_b[i] = m.omega_nb_b[i] + noise(p.rate_std_rad_s);
  s.accel_b = convention_ == AccelerationConvention::kKinematic
                  ? point_acceleration_b(m, p.lever_arm_b)
                  : point_specific_force_b(m, p.lever_arm_b);
  for (int i = 0; i < 3; ++i) {
    s.accel_b[i] += noise(p.accel_std_mps2);
    if (p.accel_bias_std_mps2 > 0.0) {
      s.accel_b[i] += accel_bias_[i].value();
      accel_bias_[i].step();
    }
  }
  return s;
}

}  // namespace dynpos::sensors
