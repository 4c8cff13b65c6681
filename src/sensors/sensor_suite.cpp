#include "dynpos/sensors/sensor_suite.hpp"

#include <set>
#include <stdexcept>

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

void SensorSuiteParams::validate() const {
  origin.validate();
  std::set<std::string> names;
  for (const GnssParams& g : gnss) {
    g.validate();
    if (!names.insert(g.name).second) throw std::invalid_argument("duplicate sensor " + g.name);
  }
  for (const MruParams& m : mru) {
    m.validate();
    if (!names.insert(m.name).second) throw std::invalid_argument("duplicate sensor " + m.name);
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
