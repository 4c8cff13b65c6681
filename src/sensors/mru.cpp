#include "dynpos/sensors/mru.hpp"

#include <cmath>
#include <string>

#include "param_tables.hpp"

namespace dynpos::sensors {

std::string_view to_string(AccelerationConvention c) {
  return c == AccelerationConvention::kKinematic ? "kinematic" : "specific-force";
}

std::optional<AccelerationConvention> parse_acceleration_convention(std::string_view s) {
  if (s == "kinematic") return AccelerationConvention::kKinematic;
  if (s == "specific-force") return AccelerationConvention::kSpecificForce;
  return std::nullopt;
}

void MruParams::validate() const { core::check_ranges(name, detail::mru_fields(*this)); }

namespace {

// A stationary Gauss–Markov bias with its own random stream, "<mru>.<stream>".
sim::GaussMarkov bias(double time_constant_s, double std, double period_s, std::uint64_t seed,
                      const std::string& stream) {
  sim::GaussMarkov b =
      sim::GaussMarkov::with_stationary_std(time_constant_s, std, period_s, sim::Rng(seed, stream));
  b.reset_stationary();
  return b;
}

// Adds the bias's value to x and advances it; a zero-σ bias draws nothing.
void add_bias(double& x, sim::GaussMarkov& b, double std) {
  if (std > 0.0) {
    x += b.value();
    b.step();
  }
}

}  // namespace

Mru::Mru(const MruParams& params, AccelerationConvention convention, double period_s,
         std::uint64_t seed)
    : params_(params), convention_(convention), rng_(seed, params.name + ".noise") {
  params_.validate();
  const MruParams& p = params_;
  // The accelerometer streams keep their names ("<mru>.bias.x"), so logs with an accelerometer
  // bias are unchanged by the angle and rate biases.
  const char* axes[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    accel_bias_.push_back(bias(p.accel_bias_time_constant_s, p.accel_bias_std_mps2, period_s, seed,
                               p.name + ".bias." + axes[i]));
    rate_bias_.push_back(bias(p.rate_bias_time_constant_s, p.rate_bias_std_rad_s, period_s, seed,
                              p.name + ".rate_bias." + axes[i]));
  }
  for (int i = 0; i < 2; ++i) {
    angle_bias_.push_back(bias(p.angle_bias_time_constant_s, p.angle_bias_std_rad, period_s, seed,
                               p.name + ".angle_bias." + axes[i]));
  }
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
  add_bias(s.roll, angle_bias_[0], p.angle_bias_std_rad);
  add_bias(s.pitch, angle_bias_[1], p.angle_bias_std_rad);
  for (int i = 0; i < 3; ++i) {
    s.omega_b[i] = m.omega_nb_b[i] + noise(p.rate_std_rad_s);
    add_bias(s.omega_b[i], rate_bias_[i], p.rate_bias_std_rad_s);
  }
  s.accel_b = convention_ == AccelerationConvention::kKinematic
                  ? point_acceleration_b(m, p.lever_arm_b)
                  : point_specific_force_b(m, p.lever_arm_b);
  for (int i = 0; i < 3; ++i) {
    s.accel_b[i] += noise(p.accel_std_mps2);
    add_bias(s.accel_b[i], accel_bias_[i], p.accel_bias_std_mps2);
  }
  return s;
}

}  // namespace dynpos::sensors
