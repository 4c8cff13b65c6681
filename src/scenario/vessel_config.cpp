#include "dynpos/scenario/vessel_config.hpp"

#include <stdexcept>

#include "actuator_fields.hpp"
#include "dynpos/core/error.hpp"
#include "param_fields.hpp"
#include "toml_fields.hpp"

namespace dynpos::scenario {
namespace {

using detail::kDegToRad;
using detail::ParamField;

std::vector<ParamField> hull_fields(model::HullParams& p) {
  return {
      {"mass_kg", &p.mass_kg, 1e3, 1e8},
      {"iz_kgm2", &p.iz_kgm2, 1, 1e12},
      {"xg_m", &p.xg_m, -100, 100},
      {"x_udot_kg", &p.x_udot_kg, 0, 1e8},
      {"y_vdot_kg", &p.y_vdot_kg, 0, 1e8},
      {"y_rdot_kgm", &p.y_rdot_kgm, -1e10, 1e10},
      {"n_rdot_kgm2", &p.n_rdot_kgm2, 0, 1e12},
      {"x_u_Ns_m", &p.x_u_Ns_m, 1e-3, 1e8},
      {"x_uu_Ns2_m2", &p.x_uu_Ns2_m2, 0, 1e8},
      {"y_v_Ns_m", &p.y_v_Ns_m, 1e-3, 1e9},
      {"y_uv_Ns2_m2", &p.y_uv_Ns2_m2, 0, 1e9},
      {"y_vv_Ns2_m2", &p.y_vv_Ns2_m2, 0, 1e9},
      {"y_ur_Ns2", &p.y_ur_Ns2, -1e10, 1e10},
      {"n_uv_Ns2", &p.n_uv_Ns2, -1e10, 1e10},
      {"n_r_Nms", &p.n_r_Nms, 1e-3, 1e12},
      {"n_ur_Nms2", &p.n_ur_Nms2, 0, 1e12},
      {"n_rr_Nms2", &p.n_rr_Nms2, 0, 1e13},
      {"roll_period_s", &p.roll_period_s, 0.5, 60},
      {"roll_damping_ratio", &p.roll_damping_ratio, 1e-3, 2},
      {"heel_per_centripetal", &p.heel_per_centripetal, -10, 10},
      {"pitch_period_s", &p.pitch_period_s, 0.5, 60},
      {"pitch_damping_ratio", &p.pitch_damping_ratio, 1e-3, 2},
      {"trim_per_surge_accel", &p.trim_per_surge_accel, -10, 10},
  };
}

std::vector<ParamField> wave_fields(model::WaveResponseParams& p) {
  return {
      {"length_m", &p.length_m, 1, 500},
      {"beam_m", &p.beam_m, 0.5, 100},
      {"heave_period_s", &p.heave_period_s, 0.5, 60},
      {"heave_damping", &p.heave_damping, 1e-3, 2},
      {"roll_period_s", &p.roll_period_s, 0.5, 60},
      {"roll_damping", &p.roll_damping, 1e-3, 2},
      {"pitch_period_s", &p.pitch_period_s, 0.5, 60},
      {"pitch_damping", &p.pitch_damping, 1e-3, 2},
      {"yaw_factor", &p.yaw_factor, 0, 10},
      {"drift_coefficient", &p.drift_coefficient, 0, 5},
  };
}

std::vector<ParamField> wind_fields(model::WindParams& p) {
  return {
      {"gust_std_fraction", &p.gust_std_fraction, 0, 0.99},
      {"gust_time_constant_s", &p.gust_time_constant_s, 0.01, 1e4},
      {"dir_std_deg", &p.dir_std_rad, 0, 90, kDegToRad},
      {"frontal_area_m2", &p.frontal_area_m2, 0.1, 1e5},
      {"lateral_area_m2", &p.lateral_area_m2, 0.1, 1e5},
      {"length_m", &p.length_m, 1, 500},
      {"cx", &p.cx, 0, 5},
      {"cy", &p.cy, 0, 5},
      {"cn", &p.cn, -1, 1},
      {"rho_air_kg_m3", &p.rho_air, 0.5, 2},
  };
}

std::vector<ParamField> current_fields(model::CurrentParams& p) {
  return {
      {"speed_std_mps", &p.speed_std_mps, 0, 1},
      {"dir_std_deg", &p.dir_std_rad, 0, 90, kDegToRad},
      {"time_constant_s", &p.time_constant_s, 1, 1e6},
  };
}

std::vector<ParamField> bias_fields(model::BiasParams& p) {
  return {
      {"std_north_N", &p.std[0], 0, 1e7},
      {"std_east_N", &p.std[1], 0, 1e7},
      {"std_yaw_Nm", &p.std[2], 0, 1e9},
      {"time_constant_north_s", &p.time_constant_s[0], 1, 1e6},
      {"time_constant_east_s", &p.time_constant_s[1], 1, 1e6},
      {"time_constant_yaw_s", &p.time_constant_s[2], 1, 1e6},
      {"reference_hs_m", &p.reference_hs_m, 0.01, 19.99},
      {"calm_fraction", &p.calm_fraction, 0, 1},
  };
}

std::vector<ParamField> joystick_fields(JoystickParams& p) {
  return {
      {"max_surge_N", &p.max_surge_N, 1, 1e8},
      {"max_sway_N", &p.max_sway_N, 1, 1e8},
      {"max_yaw_Nm", &p.max_yaw_Nm, 1, 1e10},
      {"lever_exponent", &p.lever_exponent, 1, 3},
      {"control_rate_hz", &p.control_rate_hz, 0.01, 100},
      {"heading_hold_omega_rad_s", &p.heading_hold_omega_rad_s, 1e-3, 10},
      {"heading_hold_zeta", &p.heading_hold_zeta, 0.1, 5},
  };
}

std::vector<ParamField> timing_fields(sensors::SensorTiming& t) {
  return {{"rate_hz", &t.rate_hz, 0, 1000}, {"time_offset_s", &t.time_offset_s, 0, 60}};
}

void append(std::vector<ParamField>& to, std::vector<ParamField> more) {
  for (ParamField& f : more) to.push_back(std::move(f));
}

std::vector<ParamField> origin_fields(sensors::GeodeticOrigin& o) {
  return {
      {"origin_lat_deg", &o.lat_deg, -90, 90},
      {"origin_lon_deg", &o.lon_deg, -180, 180},
      {"origin_height_m", &o.height_m, -1000, 10000},
  };
}

std::vector<ParamField> gnss_fields(sensors::GnssParams& g) {
  std::vector<ParamField> f = {
      {"x_m", &g.lever_arm_b[0], -500, 500},
      {"y_m", &g.lever_arm_b[1], -500, 500},
      {"z_m", &g.lever_arm_b[2], -500, 500},
  };
  append(f, timing_fields(g.timing));
  append(f, {
                {"horizontal_std_m", &g.horizontal_std_m, 0, 100},
                {"vertical_std_m", &g.vertical_std_m, 0, 100},
                {"bias_std_m", &g.bias_std_m, 0, 100},
                {"bias_time_constant_s", &g.bias_time_constant_s, 1e-3, 1e7},
            });
  return f;
}

std::vector<ParamField> mru_fields(sensors::MruParams& m) {
  std::vector<ParamField> f = {
      {"x_m", &m.lever_arm_b[0], -500, 500},
      {"y_m", &m.lever_arm_b[1], -500, 500},
      {"z_m", &m.lever_arm_b[2], -500, 500},
  };
  append(f, timing_fields(m.timing));
  append(f, {
                {"angle_std_deg", &m.angle_std_rad, 0, 10, kDegToRad},
                {"rate_std_deg_s", &m.rate_std_rad_s, 0, 10, kDegToRad},
                {"accel_std_mps2", &m.accel_std_mps2, 0, 10},
                {"accel_bias_std_mps2", &m.accel_bias_std_mps2, 0, 10},
                {"accel_bias_time_constant_s", &m.accel_bias_time_constant_s, 1e-3, 1e7},
                {"angle_bias_std_deg", &m.angle_bias_std_rad, 0, 10, kDegToRad},
                {"angle_bias_time_constant_s", &m.angle_bias_time_constant_s, 1e-3, 1e7},
                {"rate_bias_std_deg_s", &m.rate_bias_std_rad_s, 0, 10, kDegToRad},
                {"rate_bias_time_constant_s", &m.rate_bias_time_constant_s, 1e-3, 1e7},
            });
  return f;
}

// A channel sensor's keys: `prefix` names the channel inside a shared section ("" for a
// section of one channel), `unit` the file unit and `to_si` its factor.
std::vector<ParamField> channel_fields(sensors::ChannelSensorParams& c, const std::string& prefix,
                                       const std::string& unit, double to_si, double hi,
                                       bool with_timing = true) {
  std::vector<ParamField> f;
  if (with_timing) {
    f = {{prefix + "rate_hz", &c.timing.rate_hz, 0, 1000},
         {prefix + "time_offset_s", &c.timing.time_offset_s, 0, 60}};
  }
  append(f, {
                {prefix + "std_" + unit, &c.noise.noise_std, 0, hi, to_si},
                {prefix + "bias_std_" + unit, &c.noise.bias_std, 0, hi, to_si},
                {prefix + "bias_time_constant_s", &c.noise.bias_time_constant_s, 1e-3, 1e7},
                {prefix + "resolution_" + unit, &c.noise.resolution, 0, hi, to_si},
            });
  return f;
}

constexpr double kRpmToRps = 1.0 / 60.0;

std::vector<ParamField> wind_sensor_fields(sensors::SensorSuiteParams& s) {
  std::vector<ParamField> f = {
      {"rate_hz", &s.wind_speed.timing.rate_hz, 0, 1000},
      {"time_offset_s", &s.wind_speed.timing.time_offset_s, 0, 60},
  };
  append(f, channel_fields(s.wind_speed, "speed_", "mps", 1.0, 100, false));
  append(f, channel_fields(s.wind_dir, "dir_", "deg", kDegToRad, 180, false));
  return f;
}

std::vector<ParamField> feedback_fields(sensors::SensorSuiteParams& s) {
  std::vector<ParamField> f;
  append(f, channel_fields(s.propeller_rpm, "propeller_rpm_", "rpm", kRpmToRps, 1000));
  append(f, channel_fields(s.propeller_power, "propeller_power_", "kW", 1e3, 1e4));
  append(f, channel_fields(s.tunnel_rpm, "tunnel_rpm_", "rpm", kRpmToRps, 1000));
  append(f, channel_fields(s.tunnel_power, "tunnel_power_", "kW", 1e3, 1e4));
  append(f, channel_fields(s.rudder_angle, "rudder_", "deg", kDegToRad, 90));
  return f;
}

// Every section of the vessel file, in file order.
struct Section {
  const char* name;
  std::vector<ParamField> fields;
};

std::vector<Section> sections(VesselConfig& c) {
  return {
      {"hull", hull_fields(c.hull)},
      {"propeller", detail::propeller_fields(c.propeller)},
      {"rudder", detail::rudder_fields(c.rudder)},
      {"tunnel", detail::tunnel_fields(c.tunnel)},
      {"layout", detail::layout_fields(c.layout)},
      {"allocation", detail::allocation_fields(c.allocation)},
      {"joystick", joystick_fields(c.joystick)},
      {"waves", wave_fields(c.waves)},
      {"wind", wind_fields(c.wind)},
      {"current", current_fields(c.current)},
      {"bias", bias_fields(c.bias)},
      {"sensors", origin_fields(c.sensors.origin)},
      {"gnss1", gnss_fields(c.sensors.gnss.at(0))},
      {"gnss2", gnss_fields(c.sensors.gnss.at(1))},
      {"gnss3", gnss_fields(c.sensors.gnss.at(2))},
      {"mru1", mru_fields(c.sensors.mru.at(0))},
      {"mru2", mru_fields(c.sensors.mru.at(1))},
      {"gyro", channel_fields(c.sensors.gyro, "", "deg", kDegToRad, 180)},
      {"speed_log", channel_fields(c.sensors.speed_log, "", "mps", 1.0, 100)},
      {"wind_sensor", wind_sensor_fields(c.sensors)},
      {"feedback", feedback_fields(c.sensors)},
  };
}

// The [sensors] key that is not a number.
constexpr const char* kMruAccelerationKey = "mru_acceleration";

}  // namespace

void JoystickParams::validate() const {
  if (!(max_surge_N > 0 && max_sway_N > 0 && max_yaw_Nm > 0)) {
    throw std::invalid_argument("JoystickParams maxima must be > 0");
  }
  if (!(control_rate_hz > 0)) throw std::invalid_argument("JoystickParams.control_rate_hz > 0");
  if (!(lever_exponent >= 1.0 && lever_exponent <= 3.0)) {
    throw std::invalid_argument("JoystickParams.lever_exponent must be in [1, 3]");
  }
}

void VesselConfig::validate() const {
  hull.validate();
  propeller.validate();
  rudder.validate();
  tunnel.validate();
  layout.validate();
  allocation.validate();
  waves.validate();
  wind.validate();
  current.validate();
  bias.validate();
  joystick.validate();
  sensors.validate();
  if (sensors.gnss.size() != 3 || sensors.mru.size() != 2) {
    throw std::invalid_argument("VesselConfig: the vessel file has 3 antennas and 2 MRUs");
  }
}

nlohmann::json VesselConfig::to_json() const {
  VesselConfig copy = *this;  // the field tables bind mutable pointers
  nlohmann::json out;
  out["name"] = name;
  for (const Section& s : sections(copy)) out[s.name] = detail::fields_to_json(s.fields);
  out["sensors"][kMruAccelerationKey] = sensors::to_string(sensors.mru_acceleration);
  return out;
}

VesselConfig load_vessel_config(const std::filesystem::path& path) {
  const std::string file = path.string();
  const toml::table doc = detail::TomlTable::parse_file(file);
  const detail::TomlTable root(doc, file, "");
  VesselConfig config;
  config.source = file;
  std::vector<Section> all = sections(config);
  std::set<std::string, std::less<>> known{"name"};
  for (const Section& s : all) known.insert(s.name);
  root.reject_unknown(known);
  config.name = root.string_or("name", config.name);
  for (const Section& s : all) {
    auto table = root.optional_table(s.name);
    if (!table) continue;
    if (std::string_view(s.name) == "sensors") {
      detail::read_fields(*table, s.fields, {kMruAccelerationKey});
      if (table->has(kMruAccelerationKey)) {
        const std::string name = table->string_or(kMruAccelerationKey, "");
        const auto c = sensors::parse_acceleration_convention(name);
        if (!c) {
          throw core::InputError({file, {}, {}, std::string("sensors.") + kMruAccelerationKey},
                                 "unknown MRU acceleration convention '" + name + "'",
                                 "use \"kinematic\" (gravity removed) or \"specific-force\"");
        }
        config.sensors.mru_acceleration = *c;
      }
    } else {
      detail::read_fields(*table, s.fields);
    }
  }
  try {
    config.validate();
  } catch (const std::invalid_argument& e) {
    throw core::InputError({file, {}, {}, {}}, e.what(), "check the vessel file's values");
  }
  return config;
}

}  // namespace dynpos::scenario
