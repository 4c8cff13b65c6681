#include "sensor_logger.hpp"

#include <cmath>
#include <stdexcept>

#include "dynpos/core/angle.hpp"
#include "dynpos/sim/noise.hpp"

namespace dynpos::scenario::detail {
namespace {

constexpr double kRpsToRpm = 60.0;
constexpr const char* kSide[] = {"port", "stb", "tunnel"};

// A direction in degrees on [0, 360), snapped to `resolution` [deg] (0: none) after wrapping.
double wrap_deg(double angle_deg, double resolution) {
  double a = std::fmod(angle_deg, 360.0);
  if (a < 0.0) a += 360.0;
  if (resolution > 0.0) a = sim::quantize(a, resolution);
  return a >= 360.0 ? a - 360.0 : a;
}

}  // namespace

SensorLogger::Channel SensorLogger::channel(const sensors::ChannelSensorParams& p,
                                            const std::string& stream, double scale,
                                            double log_rate_hz, std::uint64_t seed) {
  Channel c;
  c.schedule = make_schedule(p.timing, log_rate_hz, stream.c_str());
  max_delay_ = std::max(max_delay_, c.schedule.delay);
  c.sensor.emplace(p.noise, c.schedule.period_s, sim::Rng(seed, stream));
  c.scale = scale;
  c.resolution = p.noise.resolution * scale;
  return c;
}

void SensorLogger::add_motion_sensors(const VesselConfig& vessel, double log_rate_hz,
                                      std::uint64_t seed) {
  const sensors::SensorSuiteParams& s = vessel.sensors;
  s.validate();
  const auto track = [&](const sensors::SampleSchedule& sch) {
    max_delay_ = std::max(max_delay_, sch.delay);
    return sch;
  };
  for (const sensors::GnssParams& g : s.gnss) {
    if (!g.timing.enabled()) continue;
    const sensors::SampleSchedule sch = track(make_schedule(g.timing, log_rate_hz, g.name.c_str()));
    gnss_.emplace_back(sensors::GnssReceiver(g, s.origin, sch.period_s, seed), sch);
    for (const char* c : {"lat", "lon"}) add_name(g.name + "." + c, "deg");
    for (const char* c : {"height", "north", "east", "down"}) add_name(g.name + "." + c, "m");
  }
  for (const sensors::MruParams& m : s.mru) {
    if (!m.timing.enabled()) continue;
    const sensors::SampleSchedule sch = track(make_schedule(m.timing, log_rate_hz, m.name.c_str()));
    mru_.emplace_back(sensors::Mru(m, s.mru_acceleration, sch.period_s, seed), sch);
    for (const char* c : {"roll", "pitch"}) add_name(m.name + "." + c, "deg");
    for (const char* c : {"p", "q", "r"}) add_name(m.name + "." + c, "deg/s");
    for (const char* c : {"ax", "ay", "az"}) add_name(m.name + "." + c, "m/s^2");
  }
  const double deg = core::kDegPerRad;
  if (s.gyro.timing.enabled()) {
    gyro_ = channel(s.gyro, "gyro", deg, log_rate_hz, seed);
    add_name("heading", "deg");
  }
  if (s.speed_log.timing.enabled()) {
    speed_ = {channel(s.speed_log, "speed_log.u", 1.0, log_rate_hz, seed),
              channel(s.speed_log, "speed_log.v", 1.0, log_rate_hz, seed)};
    add_name("u", "m/s");
    add_name("v", "m/s");
  }
  if (s.wind_speed.timing.enabled()) {
    sensors::ChannelSensorParams dir = s.wind_dir;
    dir.timing = s.wind_speed.timing;  // one instrument, one timing
    wind_ = {channel(s.wind_speed, "wind.speed", 1.0, log_rate_hz, seed),
             channel(dir, "wind.dir", deg, log_rate_hz, seed)};
    add_name("wind_speed", "m/s");
    add_name("wind_dir", "deg");
  }
}

SensorLogger::SensorLogger(const VesselConfig& vessel, const model::Thruster& propeller,
                           const model::TunnelThruster& tunnel, double log_rate_hz,
                           std::uint64_t seed)
    : propeller_(propeller), tunnel_(tunnel) {
  add_motion_sensors(vessel, log_rate_hz, seed);
  const sensors::SensorSuiteParams& s = vessel.sensors;
  for (int i = 0; i < 3; ++i) {
    const bool main = i < 2;
    const auto& rpm = main ? s.propeller_rpm : s.tunnel_rpm;
    const auto& power = main ? s.propeller_power : s.tunnel_power;
    const std::string side = kSide[i];
    if (rpm.timing.enabled()) {
      rpm_[i] = channel(rpm, "rpm." + side, kRpsToRpm, log_rate_hz, seed);
      add_name("rpm." + side, "rpm");
      add_name("thrust." + side, "kN");  // the DP system's thrust from the measured rpm
    }
    if (power.timing.enabled()) {
      power_[i] = channel(power, "power." + side, 1e-3, log_rate_hz, seed);
      add_name("power." + side, "kW");
    }
  }
  if (s.rudder_angle.timing.enabled()) {
    for (int i = 0; i < 2; ++i) {
      rudder_[i] = channel(s.rudder_angle, std::string("rudder.") + kSide[i], core::kDegPerRad,
                           log_rate_hz, seed);
      add_name(std::string("rudder.") + kSide[i], "deg");
    }
  }
}

SensorLogger::SensorLogger(const VesselConfig& vessel, const std::vector<model::UnitDrive>& drives,
                           double log_rate_hz, std::uint64_t seed) {
  add_motion_sensors(vessel, log_rate_hz, seed);
  const sensors::SensorSuiteParams& s = vessel.sensors;
  for (const model::UnitDrive& drive : drives) {
    const model::ThrusterUnit& unit = drive.unit();
    const bool tunnel = unit.type == model::UnitType::kTunnel;
    const auto& rpm = tunnel ? s.tunnel_rpm : s.propeller_rpm;
    const auto& power = tunnel ? s.tunnel_power : s.propeller_power;
    UnitChannels u;
    u.drive = &drive;
    if (rpm.timing.enabled()) {
      u.rpm = channel(rpm, "rpm." + unit.name, kRpsToRpm, log_rate_hz, seed);
      add_name("rpm." + unit.name, "rpm");
      add_name("thrust." + unit.name, "kN");  // the DP system's thrust from the measured rpm
    }
    if (power.timing.enabled()) {
      u.power = channel(power, "power." + unit.name, 1e-3, log_rate_hz, seed);
      add_name("power." + unit.name, "kW");
    }
    const char* angle = unit.type == model::UnitType::kAzimuth           ? "azimuth."
                        : unit.type == model::UnitType::kPropellerRudder ? "rudder."
                                                                         : nullptr;
    if (angle != nullptr && s.rudder_angle.timing.enabled()) {
      u.angle = channel(s.rudder_angle, angle + unit.name, core::kDegPerRad, log_rate_hz, seed);
      add_name(angle + unit.name, "deg");
    }
    units_.push_back(std::move(u));
  }
}

void SensorLogger::add_name(std::string name, std::string unit) {
  names_.emplace_back(std::move(name), std::move(unit));
}

void SensorLogger::declare(core::Log& log) const {
  for (const auto& [name, unit] : names_) log.declare_channel(name, unit);
}

const VesselSample& SensorLogger::delayed(std::size_t delay) const {
  // Before the run has `delay` samples, the oldest (the initial state) stands for the past.
  const std::size_t n = history_.size();
  return history_[delay < n ? n - 1 - delay : 0];
}

double SensorLogger::measure(Channel& c, double x_si) {
  const double y = c.sensor->measure(x_si) * c.scale;
  return c.resolution > 0.0 ? sim::quantize(y, c.resolution) : y;
}

void SensorLogger::record(std::size_t tick, const VesselSample& now, std::span<double> row,
                          bool gnss_lost) {
  history_.push_back(now);
  while (history_.size() > max_delay_ + 1) history_.pop_front();
  std::size_t i = 0;
  const auto skip = [&](std::size_t n) {
    for (std::size_t k = 0; k < n; ++k) row[i++] = core::kMissing;
  };
  for (auto& [rx, sch] : gnss_) {
    if (!sch.fires(tick) || gnss_lost) {
      skip(6);
      continue;
    }
    const sensors::GnssFix fix = rx.measure(delayed(sch.delay).motion);
    row[i++] = fix.lat_deg;
    row[i++] = fix.lon_deg;
    row[i++] = fix.height_m;
    for (int k = 0; k < 3; ++k) row[i++] = fix.p_n[k];
  }
  const double deg = core::kDegPerRad;
  for (auto& [mru, sch] : mru_) {
    if (!sch.fires(tick)) {
      skip(8);
      continue;
    }
    const sensors::MruSample m = mru.measure(delayed(sch.delay).motion);
    row[i++] = m.roll * deg;
    row[i++] = m.pitch * deg;
    for (int k = 0; k < 3; ++k) row[i++] = m.omega_b[k] * deg;
    for (int k = 0; k < 3; ++k) row[i++] = m.accel_b[k];
  }
  // One scalar channel: measured when its schedule fires, else missing.
  const auto scalar = [&](Channel& c, auto truth_of) {
    row[i++] =
        c.schedule.fires(tick) ? measure(c, truth_of(delayed(c.schedule.delay))) : core::kMissing;
  };
  if (gyro_) {
    const std::size_t at = i;
    scalar(*gyro_, [](const VesselSample& t) { return t.motion.theta.z(); });
    if (!core::is_missing(row[at])) row[at] = wrap_deg(row[at], gyro_->resolution);
  }
  if (speed_) {
    for (int k = 0; k < 2; ++k) {
      scalar((*speed_)[k], [k](const VesselSample& t) { return t.motion.v_b()[k]; });
    }
  }
  if (wind_) {
    scalar((*wind_)[0], [](const VesselSample& t) { return t.wind_speed_mps; });
    const std::size_t at = i;
    scalar((*wind_)[1], [](const VesselSample& t) { return t.wind_from_rad; });
    if (!core::is_missing(row[at])) row[at] = wrap_deg(row[at], (*wind_)[1].resolution);
  }
  if (!units_.empty()) {
    record_units(tick, row, i);
    return;
  }
  for (int k = 0; k < 3; ++k) {
    if (rpm_[k]) {
      const std::size_t at = i;
      scalar(*rpm_[k], [k](const VesselSample& t) { return t.shaft_speed_rps[k]; });
      const double n_rps = row[at] / kRpsToRpm;
      const double thrust_N = core::is_missing(n_rps) ? core::kMissing
                              : k < 2                 ? propeller_.thrust(n_rps, 0.0)
                                                      : tunnel_.outputs(n_rps, 0.0).thrust;
      row[i++] = thrust_N * 1e-3;
    }
    if (power_[k]) scalar(*power_[k], [k](const VesselSample& t) { return t.power_W[k]; });
  }
  for (int k = 0; k < 2; ++k) {
    if (rudder_[k]) scalar(*rudder_[k], [k](const VesselSample& t) { return t.rudder_rad[k]; });
  }
}

void SensorLogger::record_units(std::size_t tick, std::span<double> row, std::size_t& i) {
  const auto scalar = [&](Channel& c, auto truth_of) {
    row[i++] =
        c.schedule.fires(tick) ? measure(c, truth_of(delayed(c.schedule.delay))) : core::kMissing;
  };
  for (std::size_t k = 0; k < units_.size(); ++k) {
    UnitChannels& u = units_[k];
    if (u.rpm) {
      const std::size_t at = i;
      scalar(*u.rpm, [k](const VesselSample& t) { return t.units[k].shaft_speed_rps; });
      const double n_rps = row[at] / kRpsToRpm;
      row[i++] = core::is_missing(n_rps) ? core::kMissing : u.drive->thrust_N(n_rps) * 1e-3;
    }
    if (u.power) scalar(*u.power, [k](const VesselSample& t) { return t.units[k].power_W; });
    if (u.angle) {
      const std::size_t at = i;
      const bool azimuth = u.drive->unit().type == model::UnitType::kAzimuth;
      scalar(*u.angle, [k, azimuth](const VesselSample& t) {
        return azimuth ? core::wrap_2pi(t.units[k].angle_rad) : t.units[k].angle_rad;
      });
      if (azimuth && !core::is_missing(row[at])) row[at] = wrap_deg(row[at], u.angle->resolution);
    }
  }
}

}  // namespace dynpos::scenario::detail
