#pragma once
/// \file
/// SensorSuiteParams: every sensor of the virtual vessel — GNSS antennas, MRUs, gyro compass,
/// speed log, wind sensor and actuator feedback — with rates, noise and latencies. Defaults are
/// the virtual Gunnerus (lever arms from thesis tables 4.1 and 4.6).

#include <vector>

#include "dynpos/core/param_range.hpp"

#include "dynpos/core/angle.hpp"
#include "dynpos/sensors/gnss_receiver.hpp"
#include "dynpos/sensors/mru.hpp"
#include "dynpos/sensors/scalar_sensor.hpp"
#include "dynpos/sensors/sensor_timing.hpp"

namespace dynpos::sensors {

/// A sensor of one or a few scalar channels that share a timing.
struct ChannelSensorParams {
  SensorTiming timing;
  ScalarNoiseParams noise;
};

struct SensorSuiteParams {
  GeodeticOrigin origin;
  AccelerationConvention mru_acceleration = AccelerationConvention::kKinematic;
  /// Antennas, thesis table 4.1: DP, Seapath forward, Seapath aft.
  std::vector<GnssParams> gnss = default_gnss();
  /// MRUs, thesis table 4.6 (MRU 1 with z = −4.321 m as in the case study, see DESIGN).
  std::vector<MruParams> mru = default_mru();
  /// Gyro compass heading [rad]. Source: reasoned — 0.05° noise, 0.01° resolution, 10 Hz.
  ChannelSensorParams gyro{{10.0, 0.0},
                           {core::deg_to_rad(0.05), 0.0, 600.0, core::deg_to_rad(0.01)}};
  /// Speed log, BODY surge and sway velocity over ground [m/s]. Source: reasoned — Doppler log,
  /// 0.02 m/s noise, 0.01 m/s resolution, 1 Hz.
  ChannelSensorParams speed_log{{1.0, 0.0}, {0.02, 0.0, 600.0, 0.01}};
  /// Wind sensor speed [m/s] (true wind, as the DP system reports it). Source: reasoned.
  ChannelSensorParams wind_speed{{1.0, 0.0}, {0.2, 0.0, 600.0, 0.1}};
  /// Wind sensor direction (coming from) [rad]. Source: reasoned — 2° noise, 1° resolution.
  ChannelSensorParams wind_dir{{1.0, 0.0},
                               {core::deg_to_rad(2.0), 0.0, 600.0, core::deg_to_rad(1.0)}};
  /// Main propeller shaft speed feedback [rps]. Source: reasoned — 0.2 rpm noise (a shaft pickup
  /// resolves about 0.1 rpm), 0.1 rpm resolution; logged at the trial logger's rate (thesis: 100 Hz
  /// in August).
  ChannelSensorParams propeller_rpm{{100.0, 0.0}, {0.2 / 60.0, 0.0, 600.0, 0.1 / 60.0}};
  /// Main propeller power feedback [W]. Source: reasoned — 1 kW noise, 0.1 kW resolution.
  ChannelSensorParams propeller_power{{100.0, 0.0}, {1e3, 0.0, 600.0, 100.0}};
  /// Tunnel thruster shaft speed feedback [rps], 1 Hz as on Gunnerus (DESIGN rates).
  ChannelSensorParams tunnel_rpm{{1.0, 0.0}, {0.5 / 60.0, 0.0, 600.0, 0.1 / 60.0}};
  /// Tunnel thruster power feedback [W], 1 Hz.
  ChannelSensorParams tunnel_power{{1.0, 0.0}, {1e3, 0.0, 600.0, 100.0}};
  /// Rudder angle feedback [rad]. Source: reasoned — 0.1° noise and resolution.
  ChannelSensorParams rudder_angle{{100.0, 0.0},
                                   {core::deg_to_rad(0.1), 0.0, 600.0, core::deg_to_rad(0.1)}};

  /// Throws core::InputError naming the first value outside its range (param_sections) or a
  /// sensor name used twice.
  void validate() const;

  static std::vector<GnssParams> default_gnss();
  static std::vector<MruParams> default_mru();
};

/// The suite as the vessel file's sensor sections, in file order: [sensors] (the origin),
/// [gnss1]…, [mru1]…, [gyro], [speed_log], [wind_sensor] (its timing is the wind speed's) and
/// [feedback]; each key with its unit and range (core/param_range.hpp): the one table
/// validate(), the file reader and the docs use.
std::vector<core::ParamSection> param_sections(SensorSuiteParams& params);

}  // namespace dynpos::sensors
