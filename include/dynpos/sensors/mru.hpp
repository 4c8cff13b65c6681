#pragma once
/// \file
/// Mru: a motion reference unit at lever arm l_b, reporting roll, pitch, body angular rates and
/// the linear acceleration at its own location in BODY axes (4.65), either as kinematic
/// acceleration (gravity removed) or as specific force (what the accelerometers sense).

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dynpos/core/angle.hpp"
#include "dynpos/sensors/rigid_body_motion.hpp"
#include "dynpos/sensors/sensor_timing.hpp"
#include "dynpos/sim/noise.hpp"

namespace dynpos::sensors {

/// What an MRU's acceleration channels hold.
enum class AccelerationConvention {
  kKinematic,      ///< a = R(Θ)ᵀA, gravity removed (the default, as lever-arm tools expect)
  kSpecificForce,  ///< f = R(Θ)ᵀ(A − g_n); a level hull at rest reads (0, 0, −g)
};

/// "kinematic" or "specific-force".
std::string_view to_string(AccelerationConvention c);
/// The convention named s, or nullopt.
std::optional<AccelerationConvention> parse_acceleration_convention(std::string_view s);

struct MruParams {
  std::string name = "mru1";
  Eigen::Vector3d lever_arm_b = Eigen::Vector3d::Zero();  ///< l from the control origin [m]
  SensorTiming timing{100.0, 0.0};
  double angle_std_rad = core::deg_to_rad(0.02);   ///< roll/pitch white noise [rad] (MRU 5 class)
  double rate_std_rad_s = core::deg_to_rad(0.03);  ///< angular-rate white noise [rad/s]
  double accel_std_mps2 = 0.01;                    ///< acceleration white noise [m/s²]
  double accel_bias_std_mps2 = 0.0;           ///< stationary σ of an accelerometer bias [m/s²]
  double accel_bias_time_constant_s = 600.0;  ///< [s]
  /// Slowly varying roll/pitch error of the aided attitude (Gauss–Markov, per axis) [rad].
  double angle_bias_std_rad = 0.0;
  double angle_bias_time_constant_s = 600.0;  ///< [s]
  /// Gyro bias left after the MRU's own filter (Gauss–Markov, per body axis) [rad/s].
  double rate_bias_std_rad_s = 0.0;
  double rate_bias_time_constant_s = 600.0;  ///< [s]
  /// Throws core::InputError naming NAME.KEY for the first value outside its range (the vessel
  /// file's [mruK] keys, sensor_suite.hpp).
  void validate() const;
};

struct MruSample {
  double roll = 0, pitch = 0;                         ///< [rad]
  Eigen::Vector3d omega_b = Eigen::Vector3d::Zero();  ///< (p, q, r) [rad/s]
  Eigen::Vector3d accel_b = Eigen::Vector3d::Zero();  ///< [m/s²], see the convention
};

class Mru {
 public:
  Mru(const MruParams& params, AccelerationConvention convention, double period_s,
      std::uint64_t seed);

  /// The sample for true motion m (already delayed by the MRU's latency).
  MruSample measure(const RigidBodyMotion& m);

  const MruParams& params() const noexcept { return params_; }

 private:
  MruParams params_;
  AccelerationConvention convention_;
  sim::Rng rng_;
  std::vector<sim::GaussMarkov> accel_bias_;  // x, y, z
  std::vector<sim::GaussMarkov> angle_bias_;  // roll, pitch
  std::vector<sim::GaussMarkov> rate_bias_;   // p, q, r
};

}  // namespace dynpos::sensors
