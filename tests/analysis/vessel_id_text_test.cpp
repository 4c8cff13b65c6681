// The identified vessel file of identify vessel: values replaced in the starting file's text,
// in its tables and in the tables of its [[thruster]] array by unit name, the rest of the text
// kept; the result read back by the vessel file reader.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynpos/analysis/vessel_id.hpp"
#include "dynpos/model/unit_drive.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::analysis {
namespace {

// Three units, the second's dead time given and its time constant left at the default; a
// multi-line array, comments and a blank line inside the tables.
const char* const kText = R"(# A layout vessel
name = "three units"

[hull]
x_u_Ns_m = 5000.0  # reasoned

[[thruster]]
name = "bow"
type = "tunnel"
x_m = 30.0
y_m = 0.0
max_thrust_N = 100000.0
dead_time_s = 1.0

[[thruster]]
# the port main unit
name = "main.port"
type = "azimuth"
x_m = -30.0
y_m = -5.0
forbidden_deg = [
  [250.0, 290.0],  # its neighbour's wake
]

max_thrust_N = 300000.0
dead_time_s = 1.0  # from the maker
group = "A"

[[thruster]]
name = 'main_stb'
type = "azimuth"
x_m = -30.0
y_m = 5.0
max_thrust_N = 300000.0
dead_time_s = 1.0
)";

VesselParameter determined(const std::string& key, double start, double value) {
  return {key, "s", start, value, 0.01, true, true, "steps: 4, in trial.csv"};
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

scenario::VesselConfig read_back(const std::string& text, const std::string& name) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  scenario::VesselConfig v = scenario::load_vessel_config(path);
  std::filesystem::remove(path);
  return v;
}

TEST(IdentifiedVesselText, EditsTheSecondOfThreeUnitsByName) {
  VesselIdReport report;
  report.vessel_text = kText;
  const scenario::VesselConfig start = read_back(kText, "dynpos_vessel_text_start.toml");
  ASSERT_EQ(start.thrusters.size(), 3U);
  const double default_t = model::drive_params(start.thrusters[1]).time_constant_s;
  report.parameters = {determined("thruster.main.port.dead_time_s", 1.0, 1.23456),
                       determined("thruster.main.port.time_constant_s", default_t, 2.5),
                       determined("hull.x_u_Ns_m", 5000.0, 5100.0)};
  const std::string text = identified_vessel_text(report);

  // The unit's dead time replaced on its line, its time constant added after its last key;
  // every other line as it was.
  const std::vector<std::string> before = lines_of(kText), after = lines_of(text);
  ASSERT_EQ(after.size(), before.size() + 1) << text;
  std::size_t j = 0;
  for (std::size_t i = 0; i < before.size(); ++i, ++j) {
    if (before[i].rfind("x_u_Ns_m", 0) == 0) {
      EXPECT_EQ(after[j].rfind("x_u_Ns_m = 5100.0  # identified: sigma 0.01", 0), 0U) << after[j];
      continue;
    }
    if (before[i] == "dead_time_s = 1.0  # from the maker") {
      EXPECT_EQ(after[j].rfind("dead_time_s = 1.23456  # identified: sigma 0.01 (0.8 %), ", 0), 0U)
          << after[j];
      continue;
    }
    EXPECT_EQ(after[j], before[i]) << "line " << i + 1;
    if (before[i] == "group = \"A\"") {
      ++j;  // the key the table lacked, after its last key
      EXPECT_EQ(after[j].rfind("time_constant_s = 2.5  # identified: ", 0), 0U) << after[j];
    }
  }

  // Read back: the second unit has the new values, the others and the hull's other values
  // are the start's.
  const scenario::VesselConfig v = read_back(text, "dynpos_vessel_text_identified.toml");
  ASSERT_EQ(v.thrusters.size(), 3U);
  EXPECT_EQ(v.thrusters[1].name, "main.port");
  EXPECT_DOUBLE_EQ(v.thrusters[1].dead_time_s, 1.23456);
  EXPECT_DOUBLE_EQ(v.thrusters[1].time_constant_s.value_or(0.0), 2.5);
  EXPECT_EQ(v.thrusters[1].forbidden_deg.size(), 1U);
  EXPECT_EQ(v.thrusters[1].group, "A");
  for (std::size_t k : {0U, 2U}) {
    EXPECT_DOUBLE_EQ(v.thrusters[k].dead_time_s, 1.0) << k;
    EXPECT_FALSE(v.thrusters[k].time_constant_s.has_value()) << k;
  }
  EXPECT_DOUBLE_EQ(v.hull.x_u_Ns_m, 5100.0);
  EXPECT_DOUBLE_EQ(v.hull.x_uu_Ns2_m2, start.hull.x_uu_Ns2_m2);
}

TEST(IdentifiedVesselText, AUnitTheFileDoesNotNameIsAnError) {
  VesselIdReport report;
  report.vessel_text = kText;
  report.parameters = {determined("thruster.stern.dead_time_s", 1.0, 1.2)};
  EXPECT_THROW(identified_vessel_text(report), std::invalid_argument);
  // A unit's key under the array's name alone names no unit.
  report.parameters = {determined("thruster.dead_time_s", 1.0, 1.2)};
  EXPECT_THROW(identified_vessel_text(report), std::invalid_argument);
}

TEST(IdentifiedVesselText, AValueNotFittedIsNotWritten) {
  VesselIdReport report;
  report.vessel_text = kText;
  VesselParameter kept = determined("thruster.bow.dead_time_s", 1.0, 1.0);
  kept.determined = kept.fitted = false;
  kept.sigma = std::numeric_limits<double>::quiet_NaN();
  report.parameters = {kept};
  EXPECT_EQ(identified_vessel_text(report), kText);
}

}  // namespace
}  // namespace dynpos::analysis
