#include "dynpos/scenario/vessel_config.hpp"

#include <fmt/core.h>

#include <set>
#include <stdexcept>

#include "dynpos/core/error.hpp"
#include "dynpos/model/unit_drive.hpp"
#include "param_fields.hpp"
#include "toml_fields.hpp"
#include "vessel_thrusters.hpp"

namespace dynpos::scenario {
namespace {

// The [joystick] table (core/param_range.hpp).
template <typename P>
std::vector<core::BasicParamField<core::ParamValue<P>>> joystick_fields(P& p) {
  return {
      {{"max_surge_N", "N", 1, 1e8}, &p.max_surge_N},
      {{"max_sway_N", "N", 1, 1e8}, &p.max_sway_N},
      {{"max_yaw_Nm", "N·m", 1, 1e10}, &p.max_yaw_Nm},
      {{"lever_exponent", "1", 1, 3}, &p.lever_exponent},
      {{"control_rate_hz", "Hz", 0.01, 100}, &p.control_rate_hz},
      {{"heading_hold_omega_rad_s", "rad/s", 1e-3, 10}, &p.heading_hold_omega_rad_s},
      {{"heading_hold_zeta", "1", 0.1, 5}, &p.heading_hold_zeta},
  };
}

}  // namespace

std::vector<core::ParamSection> vessel_param_sections(VesselConfig& c) {
  std::vector<core::ParamSection> out = {
      {"hull", model::param_fields(c.hull)},     {"propeller", model::param_fields(c.propeller)},
      {"rudder", model::param_fields(c.rudder)}, {"tunnel", model::param_fields(c.tunnel)},
      {"layout", model::param_fields(c.layout)}, {"allocation", model::param_fields(c.allocation)},
      {"joystick", joystick_fields(c.joystick)}, {"waves", model::param_fields(c.waves)},
      {"wind", model::param_fields(c.wind)},     {"current", model::param_fields(c.current)},
      {"bias", model::param_fields(c.bias)},
  };
  for (core::ParamSection& s : sensors::param_sections(c.sensors)) out.push_back(std::move(s));
  return out;
}

std::string vessel_param_tables_markdown() {
  VesselConfig defaults;
  std::string out;
  for (const core::ParamSection& s : vessel_param_sections(defaults)) {
    out += fmt::format("\n### [{}]\n\n| key | unit | range |\n|---|---|---|\n", s.name);
    for (const core::ParamField& f : s.fields) {
      out += fmt::format("| `{}` | {} | {} |\n", f.range.key, f.range.unit, f.range.interval());
    }
  }
  return out;
}

namespace {

// The [sensors] key that is not a number.
constexpr const char* kMruAccelerationKey = "mru_acceleration";

}  // namespace

void JoystickParams::validate() const { core::check_ranges("joystick", joystick_fields(*this)); }

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
    throw core::InputError({}, "VesselConfig: the vessel file has 3 antennas and 2 MRUs");
  }
  for (const model::ThrusterUnit& unit : thrusters) unit.validate();
  if (!thruster_capacity.empty() && thruster_capacity.size() != thrusters.size()) {
    throw core::InputError::for_option(
        "thruster_capacity",
        fmt::format("{} capacities for {} units", thruster_capacity.size(), thrusters.size()));
  }
  for (const double c : thruster_capacity) {
    if (!(c >= 0.0 && c <= 1.0)) {
      throw core::InputError::for_option("thruster_capacity",
                                         fmt::format("{} is not a capacity in [0, 1]", c));
    }
  }
}

namespace {

// A [[thruster]] unit as the vessel file gives it, with the drive the simulator makes of it.
nlohmann::json unit_json(const model::ThrusterUnit& u) {
  nlohmann::json j = {{"name", u.name},
                      {"type", model::unit_type_name(u.type)},
                      {"x_m", u.x_m},
                      {"y_m", u.y_m},
                      {"max_thrust_N", u.max_thrust_N},
                      {"max_reverse_thrust_N", u.max_reverse_thrust_N},
                      {"weight", u.weight},
                      {"dead_time_s", u.dead_time_s}};
  if (!u.group.empty()) j["group"] = u.group;
  if (u.type == model::UnitType::kAzimuth) {
    j["rate_deg_per_s"] = u.rate_deg_per_s;
    nlohmann::json sectors = nlohmann::json::array();
    for (const model::AngleSector& s : u.forbidden_deg) sectors.push_back({s.from_deg, s.to_deg});
    j["forbidden_deg"] = sectors;
    nlohmann::json loss = nlohmann::json::array();
    for (const model::LossPoint& p : u.loss) loss.push_back({p.angle_deg, p.factor});
    j["loss"] = loss;
  }
  if (u.type == model::UnitType::kPropellerRudder) {
    j["rudder_lift_per_thrust"] = u.rudder_lift_per_thrust;
    j["rudder_lift_at_zero_N"] = u.rudder_lift_at_zero_N;
    j["rudder_max_force_N"] = u.rudder_max_force_N;
    j["rudder_x_m"] = u.rudder_x_m.value_or(u.x_m);
  }
  const model::UnitDriveParams d = model::drive_params(u);
  j["time_constant_s"] = d.time_constant_s;
  j["thrust_rate_N_per_s"] = u.thrust_rate_N_per_s.value_or(
      std::max(u.max_thrust_N, u.max_reverse_thrust_N) / (4.0 * d.time_constant_s));
  j["drive"] = {{"diameter_m", d.diameter_m},
                {"max_shaft_speed_rps", d.max_shaft_speed_rps},
                {"kt_ahead", d.kt_ahead},
                {"kt_astern", d.kt_astern},
                {"kq", d.kq},
                {"rate_limit_rps2", d.rate_limit_rps2}};
  return j;
}

}  // namespace

nlohmann::json VesselConfig::to_json() const {
  VesselConfig copy = *this;  // the field tables bind mutable pointers
  nlohmann::json out;
  out["name"] = name;
  for (const core::ParamSection& s : vessel_param_sections(copy)) {
    out[s.name] = detail::fields_to_json(s.fields);
  }
  out["sensors"][kMruAccelerationKey] = sensors::to_string(sensors.mru_acceleration);
  if (!thrusters.empty()) {
    out["thruster"] = nlohmann::json::array();
    for (const model::ThrusterUnit& u : thrusters) out["thruster"].push_back(unit_json(u));
  }
  return out;
}

VesselConfig load_vessel_config(const std::filesystem::path& path) {
  const std::string file = path.string();
  const toml::table doc = detail::TomlTable::parse_file(file);
  if (doc.empty()) {  // a file cut to nothing would otherwise be the built-in vessel, unsaid
    throw core::InputError({file, {}, {}, {}}, "the vessel file has no key",
                           "give the vessel's values (docs/vessel-file.md), or leave --vessel "
                           "out for the built-in Gunnerus");
  }
  const detail::TomlTable root(doc, file, "");
  VesselConfig config;
  config.source = file;
  std::vector<core::ParamSection> all = vessel_param_sections(config);
  std::set<std::string, std::less<>> known{"name", "thruster"};
  for (const core::ParamSection& s : all) known.insert(s.name);
  root.reject_unknown(known);
  config.name = root.string_or("name", config.name);
  config.thrusters = detail::read_thruster_units(doc, root);
  for (const core::ParamSection& s : all) {
    auto table = root.optional_table(s.name);
    if (!table) continue;
    if (s.name == "sensors") {
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
  // The keys are in range (read_fields); what is left are rules between keys.
  try {
    config.validate();
  } catch (const core::InputError& e) {
    throw core::InputError({file, {}, {}, e.where().column_name}, e.problem(),
                           e.hint().empty() ? "check the vessel file's values" : e.hint());
  } catch (const std::invalid_argument& e) {  // a model's precondition, should one remain
    throw core::InputError({file, {}, {}, {}}, e.what(), "check the vessel file's values");
  }
  return config;
}

}  // namespace dynpos::scenario
