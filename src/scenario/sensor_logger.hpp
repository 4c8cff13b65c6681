#pragma once
// SensorLogger: the vessel's sensors as a trial logger records them — each at its own rate
// (blank cells between samples), with its noise and latency — in the units real loggers use
// (deg, deg/s, rpm, kW, kN), the unit in every column header.

#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "dynpos/core/log.hpp"
#include "dynpos/model/thruster.hpp"
#include "dynpos/model/tunnel_thruster.hpp"
#include "dynpos/model/unit_drive.hpp"
#include "dynpos/scenario/vessel_config.hpp"
#include "dynpos/scenario/vessel_sample.hpp"
#include "dynpos/sensors/gnss_receiver.hpp"
#include "dynpos/sensors/mru.hpp"
#include "dynpos/sensors/rigid_body_motion.hpp"
#include "dynpos/sensors/scalar_sensor.hpp"
#include "dynpos/sensors/sensor_timing.hpp"

namespace dynpos::scenario::detail {

class SensorLogger {
 public:
  /// Sensors of `vessel` on a logger of rate log_rate_hz; noise streams from `seed`. Throws
  /// std::invalid_argument if a sensor's rate or latency does not fit the logger's tick grid.
  SensorLogger(const VesselConfig& vessel, const model::Thruster& propeller,
               const model::TunnelThruster& tunnel, double log_rate_hz, std::uint64_t seed);
  /// The same with the units of `drives` (a [[thruster]] layout) in place of the model's
  /// propellers, tunnel and rudders: per unit rpm.NAME, thrust.NAME (from the measured shaft
  /// speed), power.NAME and azimuth.NAME or rudder.NAME, on the vessel's propeller (tunnel)
  /// rpm and power sensors and its rudder angle sensor.
  SensorLogger(const VesselConfig& vessel, const std::vector<model::UnitDrive>& drives,
               double log_rate_hz, std::uint64_t seed);

  /// Declares the measured channels, in column order, on `log`.
  void declare(core::Log& log) const;
  std::size_t channel_count() const noexcept { return names_.size(); }

  /// Records logger tick k (ticks are consecutive from 0) with the truth `now`: fills `row`
  /// (channel_count() values, missing where no sensor sampled) from the delayed truths; with
  /// gnss_lost (a GNSS dropout) no receiver gives a fix.
  void record(std::size_t tick, const VesselSample& now, std::span<double> row,
              bool gnss_lost = false);

 private:
  struct Channel {
    std::optional<sensors::ScalarSensor> sensor;
    sensors::SampleSchedule schedule;
    double scale = 1.0;       // SI → logged unit
    double resolution = 0.0;  // in the logged unit
  };
  const VesselSample& delayed(std::size_t delay) const;
  // The sensors common to both kinds of vessel: GNSS, MRU, gyro, speed log, wind.
  void add_motion_sensors(const VesselConfig& vessel, double log_rate_hz, std::uint64_t seed);
  Channel channel(const sensors::ChannelSensorParams& p, const std::string& stream, double scale,
                  double log_rate_hz, std::uint64_t seed);
  void add_name(std::string name, std::string unit);
  double measure(Channel& c, double x_si);
  void record_units(std::size_t tick, std::span<double> row, std::size_t& i);

  // A layout unit's feedback channels.
  struct UnitChannels {
    const model::UnitDrive* drive = nullptr;
    std::optional<Channel> rpm, power, angle;
  };

  model::Thruster propeller_;
  model::TunnelThruster tunnel_;
  std::vector<std::pair<std::string, std::string>> names_;
  std::vector<std::pair<sensors::GnssReceiver, sensors::SampleSchedule>> gnss_;
  std::vector<std::pair<sensors::Mru, sensors::SampleSchedule>> mru_;
  std::optional<Channel> gyro_;
  std::optional<std::array<Channel, 2>> speed_;
  std::optional<std::array<Channel, 2>> wind_;
  std::array<std::optional<Channel>, 3> rpm_, power_;
  std::array<std::optional<Channel>, 2> rudder_;
  std::vector<UnitChannels> units_;
  std::size_t max_delay_ = 0;
  std::deque<VesselSample> history_;
};

}  // namespace dynpos::scenario::detail
