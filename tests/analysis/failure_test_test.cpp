#include "dynpos/analysis/failure_test.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>

#include <fmt/core.h>

#include "../io/io_test_util.hpp"
#include "../source_dir.hpp"
#include "dynpos/analysis/demo_sections.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/scenario/run_files.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/vessel_config.hpp"
#include "input_error_capture.hpp"

namespace dynpos::analysis {
namespace {

using io::testing::TempDir;
using testing::input_error;
using testing::option_key_of;

// 300 s at 10 Hz, position as lat/lon: port's shaft speed 120 rpm trips at 100 s (a first-order
// decay, T = 1 s), its thrust column empty; stb's thrust steps from 30 to 50 kN at 100.5 s. The
// vessel moves 1 m north from 100 s to 130 s and back by 160 s.
std::filesystem::path write_log(const TempDir& dir) {
  std::string csv =
      "time [s],lat [deg],lon [deg],heading [deg],thrust.port [kN],rpm.port [rpm],"
      "thrust.stb [kN]\n";
  constexpr double kMetresPerDegree = 111'320.0;  // near enough for 1 m
  for (int i = 0; i <= 3000; ++i) {
    const double t = 0.1 * i;
    const double s = t - 100.0;
    const double north = (s > 0.0 && s < 60.0) ? std::sin(std::numbers::pi * s / 60.0) : 0.0;
    const double rpm = s < 0.0 ? 120.0 + 0.5 * std::sin(1.3 * i) : 120.0 * std::exp(-s);
    const double stb = (s < 0.5 ? 30.0 : 50.0) + 0.2 * std::sin(0.9 * i);
    csv += fmt::format("{:.1f},{:.9f},10,90,,{:.3f},{:.3f}\n", t,
                       63.0 + (north + 0.01 * std::sin(2.3 * i)) / kMetresPerDegree, rpm, stb);
  }
  return dir.write("log.csv", csv);
}

TEST(FailureTestAnalysis, ShaftSpeedWhereThrustIsNotLoggedAndLatLon) {
  TempDir dir;
  FailureTestRequest request;
  request.source.log = write_log(dir);
  const FailureTestReport report = run_failure_test(request);
  EXPECT_EQ(report.position, "lat/lon");
  ASSERT_EQ(report.units.size(), 2u);
  EXPECT_EQ(report.units[0].channel, "rpm.port");
  EXPECT_EQ(report.units[1].channel, "thrust.stb");
  ASSERT_EQ(report.notes.size(), 1u);
  EXPECT_EQ(report.notes[0], "thrust.port has no valid sample: left out");
  ASSERT_EQ(report.result.events.size(), 1u);
  const nlohmann::json e = to_json(report).at("events").at(0);
  EXPECT_EQ(e.at("unit"), "port");
  EXPECT_NEAR(e.at("time_s").get<double>(), 100.0, 0.5);
  EXPECT_NEAR(e.at("level_before").get<double>(), 120.0, 0.5);  // in rpm
  EXPECT_EQ(e.at("level_unit"), "rpm");
  EXPECT_NEAR(e.at("peak_excursion_m").get<double>(), 1.0, 0.05);
  EXPECT_NEAR(e.at("peak_heading_deg").get<double>(), 0.0, 1e-9);
  const nlohmann::json& stb = e.at("redistribution").at("stb");
  EXPECT_EQ(stb.at("unit"), "kN");
  EXPECT_NEAR(stb.at("change").get<double>(), 20.0 * (1.0 - 0.5 / 30.0), 0.3);
  EXPECT_TRUE(stb.at("took_over").get<bool>());
  EXPECT_NE(to_text(report).find("stb: 30.0 → 49."), std::string::npos) << to_text(report);
}

TEST(FailureTestAnalysis, BadInputNamesTheLogOrTheOption) {
  TempDir dir;
  FailureTestRequest request;
  request.source.log = write_log(dir);
  // --rpm on a log with thrust only.
  FailureTestRequest no_rpm = request;
  no_rpm.use_rpm = true;
  no_rpm.source.log =
      dir.write("thrust_only.csv", "time,north,east,thrust.stb\n0,0,0,1\n1,0,0,1\n");
  const core::InputError e = input_error([&] { run_failure_test(no_rpm); });
  EXPECT_NE(std::string(e.what()).find("thrust_only.csv"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("no shaft speed channel (rpm.NAME)"), std::string::npos)
      << e.what();
  FailureTestRequest bad = request;
  bad.max_fall_s = 0.0;
  EXPECT_EQ(option_key_of([&] { bad.validate(); }), "max_fall");
  bad = request;
  bad.arm_m = Eigen::Vector3d(std::nan(""), 0.0, 0.0);
  EXPECT_EQ(option_key_of([&] { bad.validate(); }), "arm");
}

// The demo's section on a campaign folder holding the thruster trip (seed 1, as `dynpos demo`
// writes a run): found against truth.json, the JSON with both; nothing without the run.
TEST(FailureTestAnalysis, DemoSectionComparesWithTheTruth) {
  TempDir dir;
  const std::filesystem::path source = DYNPOS_SOURCE_DIR;
  const scenario::ScenarioSpec spec =
      scenario::load_scenario(source / "data" / "scenarios" / "dp-thruster-trip.toml");
  const scenario::VesselConfig vessel =
      scenario::load_vessel_config(source / "data" / "vessels" / "gunnerus.toml");
  scenario::write_scenario_run(scenario::run_scenario(spec, vessel, 1),
                               dir.path() / "dp-thruster-trip");
  const ReportSection s = failure_test_demo_section(dir.path());
  EXPECT_EQ(s.title, "Failure test");
  for (const char* text : {"| dp-thruster-trip | found | tunnel | ",
                           "| dp-thruster-trip | true | tunnel | 600.0 |", "found − true"}) {
    EXPECT_NE(s.markdown.find(text), std::string::npos) << text << "\n" << s.markdown;
  }
  std::ifstream file(dir.path() / "analysis" / "failure-test" / "dp-thruster-trip.json");
  const nlohmann::json doc = nlohmann::json::parse(file);
  EXPECT_EQ(doc.at("log"), "dp-thruster-trip/log.csv");
  ASSERT_EQ(doc.at("events").size(), 1u);
  EXPECT_NEAR(doc.at("events").at(0).at("time_s").get<double>(), 600.0, 0.5);
  EXPECT_EQ(doc.at("truth").at("time_s"), 600.0);
  EXPECT_EQ(doc.at("truth").at("units"), nlohmann::json::array({"tunnel"}));
  EXPECT_EQ(failure_test_demo_section(dir.path() / "no-campaign").title, "");
}

}  // namespace
}  // namespace dynpos::analysis
