#include "dynpos/sensors/sensor_suite.hpp"

#include <set>
#include <string>

#include "dynpos/core/error.hpp"
#include "param_tables.hpp"

namespace dynpos::sensors {

std::vector<GnssParams> SensorSuiteParams::default_gnss() {
  // Thesis table 4.1 [m], BODY (x fwd, y stb, z down) from the control origin.
  std::vector<GnssParams> g(3);
  g[0].name = "gnss1";  // DP antenna
  g[0].lever_arm_b = {0.202, -0.611, -13.891};
  g[1].name = "gnss2";  // Seapath forward
  g[1].lever_arm_b = {1.571, 0.691, -13.520};
  g[2].name = "gnss3";  // Seapath aft
  g[2].lever_arm_b = {-0.924, 0.574, -13.567};
  return g;
}

std::vector<MruParams> SensorSuiteParams::default_mru() {
  // Thesis table 4.6 [m]; MRU 1 z as in the case study (−4.321), see DESIGN.md.
  std::vector<MruParams> m(2);
  m[0].name = "mru1";
  m[0].lever_arm_b = {0.358, 0.804, -4.321};
  m[1].name = "mru2";
  m[1].lever_arm_b = {14.978, 0.039, 0.568};
  return m;
}

namespace {

using detail::ChannelUnit;
using detail::kDegToRad;
using detail::kRpmToRps;

const ChannelUnit kDeg{"deg", "deg", kDegToRad, 180};
const ChannelUnit kMps{"mps", "m/s", 1.0, 100};
const ChannelUnit kRpm{"rpm", "rpm", kRpmToRps, 1000};
const ChannelUnit kKw{"kW", "kW", 1e3, 1e4};

// A channel sensor with its own timing: PREFIXrate_hz, PREFIXtime_offset_s and its noise keys.
template <typename C>
detail::Fields<C> channel_fields(C& c, const std::string& prefix, const ChannelUnit& unit) {
  detail::Fields<C> f = detail::timing_fields(c.timing, prefix);
  detail::append<C>(f, detail::noise_fields(c.noise, prefix, unit));
  return f;
}

template <typename P>  // SensorSuiteParams, or const for checking
std::vector<core::BasicParamSection<core::ParamValue<P>>> sections(P& s) {
  using Fields = detail::Fields<P>;
  std::vector<core::BasicParamSection<core::ParamValue<P>>> out;
  out.push_back({"sensors", detail::origin_fields(s.origin)});
  for (std::size_t i = 0; i < s.gnss.size(); ++i) {
    out.push_back({"gnss" + std::to_string(i + 1), detail::gnss_fields(s.gnss[i])});
  }
  for (std::size_t i = 0; i < s.mru.size(); ++i) {
    out.push_back({"mru" + std::to_string(i + 1), detail::mru_fields(s.mru[i])});
  }
  out.push_back({"gyro", channel_fields(s.gyro, "", kDeg)});
  out.push_back({"speed_log", channel_fields(s.speed_log, "", kMps)});
  Fields wind = detail::timing_fields(s.wind_speed.timing);  // one instrument, one timing
  detail::append<P>(wind, detail::noise_fields(s.wind_speed.noise, "speed_", kMps));
  detail::append<P>(wind, detail::noise_fields(s.wind_dir.noise, "dir_", kDeg));
  out.push_back({"wind_sensor", wind});
  Fields feedback;
  detail::append<P>(feedback, channel_fields(s.propeller_rpm, "propeller_rpm_", kRpm));
  detail::append<P>(feedback, channel_fields(s.propeller_power, "propeller_power_", kKw));
  detail::append<P>(feedback, channel_fields(s.tunnel_rpm, "tunnel_rpm_", kRpm));
  detail::append<P>(feedback, channel_fields(s.tunnel_power, "tunnel_power_", kKw));
  const ChannelUnit rudder{"deg", "deg", kDegToRad, 90};
  detail::append<P>(feedback, channel_fields(s.rudder_angle, "rudder_", rudder));
  out.push_back({"feedback", feedback});
  return out;
}

}  // namespace

std::vector<core::ParamSection> param_sections(SensorSuiteParams& params) {
  return sections(params);
}

void SensorSuiteParams::validate() const {
  for (const auto& section : sections(*this)) core::check_ranges(section.name, section.fields);
  std::set<std::string> names;
  for (const GnssParams& g : gnss) {
    g.validate();
    if (!names.insert(g.name).second) throw core::InputError({}, "duplicate sensor " + g.name);
  }
  for (const MruParams& m : mru) {
    m.validate();
    if (!names.insert(m.name).second) throw core::InputError({}, "duplicate sensor " + m.name);
  }
  const std::pair<const char*, const ChannelSensorParams*> channels[] = {
      {"gyro", &gyro},
      {"speed_log", &speed_log},
      {"wind_speed", &wind_speed},
      {"wind_dir", &wind_dir},
      {"propeller_rpm", &propeller_rpm},
      {"propeller_power", &propeller_power},
      {"tunnel_rpm", &tunnel_rpm},
      {"tunnel_power", &tunnel_power},
      {"rudder_angle", &rudder_angle}};
  for (const auto& [what, c] : channels) {
    c->timing.validate(what);
    c->noise.validate(what);
  }
}

}  // namespace dynpos::sensors
