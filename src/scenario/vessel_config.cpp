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
  };
}

std::vector<ParamField> joystick_fields(JoystickParams& p) {
  return {
      {"max_surge_N", &p.max_surge_N, 1, 1e8},
      {"max_sway_N", &p.max_sway_N, 1, 1e8},
      {"max_yaw_Nm", &p.max_yaw_Nm, 1, 1e10},
      {"control_rate_hz", &p.control_rate_hz, 0.01, 100},
  };
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
  };
}

}  // namespace

void JoystickParams::validate() const {
  if (!(max_surge_N > 0 && max_sway_N > 0 && max_yaw_Nm > 0)) {
    throw std::invalid_argument("JoystickParams maxima must be > 0");
  }
  if (!(control_rate_hz > 0)) throw std::invalid_argument("JoystickParams.control_rate_hz > 0");
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
}

nlohmann::json VesselConfig::to_json() const {
  VesselConfig copy = *this;  // the field tables bind mutable pointers
  nlohmann::json out;
  out["name"] = name;
  for (const Section& s : sections(copy)) out[s.name] = detail::fields_to_json(s.fields);
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
    if (auto table = root.optional_table(s.name)) detail::read_fields(*table, s.fields);
  }
  try {
    config.validate();
  } catch (const std::invalid_argument& e) {
    throw core::InputError({file, {}, {}, {}}, e.what(), "check the vessel file's values");
  }
  return config;
}

}  // namespace dynpos::scenario
