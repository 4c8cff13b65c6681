#include "dynpos/scenario/vessel_config.hpp"

#include <fmt/core.h>

#include <set>
#include <stdexcept>

#include "dynpos/core/error.hpp"
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
}

nlohmann::json VesselConfig::to_json() const {
  VesselConfig copy = *this;  // the field tables bind mutable pointers
  nlohmann::json out;
  out["name"] = name;
  for (const core::ParamSection& s : vessel_param_sections(copy)) {
    out[s.name] = detail::fields_to_json(s.fields);
  }
  out["sensors"][kMruAccelerationKey] = sensors::to_string(sensors.mru_acceleration);
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
