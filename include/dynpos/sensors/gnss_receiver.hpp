#pragma once
/// \file
/// GnssReceiver: a GNSS antenna at lever arm l_b, reporting geodetic latitude, longitude and
/// ellipsoidal height (WGS84, through core::LocalNedFrame) and the same position in a local NED
/// frame about a fixed geodetic origin, with white noise and a slowly varying (multipath-like)
/// bias.

#include <Eigen/Core>
#include <array>
#include <string>

#include "dynpos/core/local_ned_frame.hpp"
#include "dynpos/sensors/rigid_body_motion.hpp"
#include "dynpos/sensors/sensor_timing.hpp"
#include "dynpos/sim/noise.hpp"
#include "dynpos/sim/random.hpp"

namespace dynpos::sensors {

/// The WGS84 point that local NED coordinates are measured from.
struct GeodeticOrigin {
  double lat_deg = 63.4400;  ///< Source: reasoned — Trondheimsfjord, Gunnerus' home waters.
  double lon_deg = 10.3500;  ///< [deg east]
  double height_m = 39.5;    ///< ellipsoidal height of mean sea level there (geoid ≈ 39.5 m)
  /// Throws core::InputError naming the first value outside its range (the vessel file's
  /// [sensors] origin_* keys, sensor_suite.hpp).
  void validate() const;
};

struct GnssParams {
  std::string name = "gnss1";
  Eigen::Vector3d lever_arm_b = Eigen::Vector3d::Zero();  ///< l from the control origin [m]
  SensorTiming timing{1.0, 0.0};
  double horizontal_std_m = 0.01;       ///< white noise per horizontal axis [m]; RTK 1–2 cm
  double vertical_std_m = 0.02;         ///< white noise, vertical [m]; RTK 2–4 cm
  double bias_std_m = 0.0;              ///< stationary σ of a Gauss–Markov bias per axis [m]
  double bias_time_constant_s = 600.0;  ///< its correlation time [s]
  /// Throws core::InputError naming NAME.KEY for the first value outside its range (the vessel
  /// file's [gnssK] keys, sensor_suite.hpp).
  void validate() const;
};

/// One fix: geodetic and local NED coordinates of the antenna.
struct GnssFix {
  double lat_deg = 0, lon_deg = 0, height_m = 0;  ///< WGS84
  Eigen::Vector3d p_n = Eigen::Vector3d::Zero();  ///< local NED about the origin [m]
};

class GnssReceiver {
 public:
  /// A receiver sampled every period_s with noise streams from (seed, params.name).
  GnssReceiver(const GnssParams& params, const GeodeticOrigin& origin, double period_s,
               std::uint64_t seed);

  /// The fix for true motion m (already delayed by the receiver's latency).
  GnssFix measure(const RigidBodyMotion& m);

  /// Local NED [m] of a geodetic point, in this receiver's frame (for tests and tools).
  Eigen::Vector3d to_local_n(double lat_deg, double lon_deg, double height_m) const;

  const GnssParams& params() const noexcept { return params_; }

 private:
  GnssParams params_;
  core::LocalNedFrame frame_;
  std::array<sim::WhiteNoise, 3> noise_;
  std::array<sim::GaussMarkov, 3> bias_;
};

}  // namespace dynpos::sensors
