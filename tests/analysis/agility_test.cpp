#include "dynpos/analysis/agility.hpp"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "dynpos/core/error.hpp"
#include "input_error_capture.hpp"

namespace dynpos::analysis {
namespace {

// A 120 s agility log at 10 Hz: the joystick demand steps to 50 % ahead at 20 s and to 50 % to
// starboard at 70 s (yaw 0). The port thruster follows the first step after a dead time of 1 s
// with a ramp of 1 kN/s to 10 kN and keeps it; the starboard one follows the second step after
// 2 s with a ramp of 2.5 kN/s to 10 kN. Wind 5 m/s from 90°, heading 0°. With
// `blank_port` the port thrust has no valid sample.
std::filesystem::path write_log(const std::string& name, bool blank_port = false) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "agility_test";
  std::filesystem::create_directories(dir);
  const std::filesystem::path path = dir / name;
  std::ofstream out(path);
  out << "time [s],command.surge [%],command.sway [%],command.yaw [%],thrust.port [kN],"
         "thrust.stb [kN],wind_speed [m/s],wind_dir [deg],heading [deg]\n";
  for (int i = 0; i <= 1200; ++i) {
    const double t = 0.1 * i;
    const double surge = i >= 200 && i < 700 ? 50.0 : 0.0;
    const double sway = i >= 700 ? 50.0 : 0.0;
    const double port = std::clamp(t - 21.0, 0.0, 10.0);
    const double stb = std::clamp((t - 72.0) * 2.5, 0.0, 10.0);
    out << fmt::format("{:.1f},{},{},0,{},{:.6f},5,90,0\n", t, surge, sway,
                       blank_port ? std::string() : fmt::format("{:.6f}", port), stb);
  }
  return path;
}

AgilityRequest request_for(const std::filesystem::path& log) {
  AgilityRequest r;
  r.source.log = log;
  return r;
}

TEST(AgilityAnalysis, TimesEachThrusterOnEachStepOfTheDemands) {
  const AgilityReport report = run_agility(request_for(write_log("steps.csv")));
  EXPECT_EQ(report.channel, "thrust");
  EXPECT_EQ(report.thrusters, (std::vector<std::string>{"port", "stb"}));
  EXPECT_FALSE(report.has_speed);
  ASSERT_EQ(report.result.steps.size(), 2u);
  const ident::AgilityStep& ahead = report.result.steps[0];
  const ident::AgilityStep& starboard = report.result.steps[1];
  EXPECT_NEAR(ahead.direction_deg, 0.0, 1e-12);
  EXPECT_NEAR(starboard.direction_deg, 90.0, 1e-12);
  EXPECT_NEAR(ahead.magnitude_pct, 50.0, 1e-9);
  EXPECT_NEAR(ahead.t_step, 20.0, 1e-9);
  EXPECT_NEAR(starboard.t_step, 70.0, 1e-9);
  // Port: from 0 to 10 kN, the 63.2 % level 6.32 kN is reached 1 s + 6.32 s after the step
  // (linear between the samples of the ramp, so exact up to rounding). Starboard: 2 s + 6.32/2.5.
  ASSERT_TRUE(ahead.thrusters[0].response_s);
  EXPECT_NEAR(*ahead.thrusters[0].response_s, 7.32, 1e-9);
  ASSERT_TRUE(starboard.thrusters[1].response_s);
  EXPECT_NEAR(*starboard.thrusters[1].response_s, 2.0 + 6.32 / 2.5, 1e-9);
  // A thruster that does not move has no response time: absent, never 0.
  EXPECT_FALSE(ahead.thrusters[1].response_s);
  EXPECT_FALSE(starboard.thrusters[0].response_s);
  EXPECT_NEAR(*thrust_envelope_s(ahead), 7.32, 1e-9);
  // Both steps are one case; its wind is the logged 5 m/s from 90° at heading 0°.
  ASSERT_EQ(report.cases.size(), 1u);
  EXPECT_EQ(report.cases[0].label, "50 % thrust, no yaw");
  EXPECT_EQ(report.cases[0].steps, (std::vector<std::size_t>{0, 1}));
  ASSERT_TRUE(report.cases[0].wind);
  EXPECT_NEAR(report.cases[0].wind->speed_mps, 5.0, 1e-12);
  EXPECT_NEAR(report.cases[0].wind->from_deg, 90.0, 1e-9);
  EXPECT_NEAR(*report.cases[0].wind->heading_deg, 0.0, 1e-9);
}

TEST(AgilityAnalysis, AnExplicitWindowGivesTheSameTimeAsTheDemands) {
  AgilityRequest request = request_for(write_log("window.csv"));
  request.windows = {ident::AgilityWindow{20.0, 69.9, 0.0, 50.0, 0.0}};
  const AgilityReport report = run_agility(request);
  ASSERT_EQ(report.result.steps.size(), 1u);
  ASSERT_TRUE(report.result.steps[0].thrusters[0].response_s);
  EXPECT_NEAR(*report.result.steps[0].thrusters[0].response_s, 7.32, 1e-9);
  EXPECT_EQ(report.cases[0].label, "50 % thrust, no yaw");
}

TEST(AgilityAnalysis, BadOptionsNameTheirKey) {
  const auto key_of = [](const auto& f) { return testing::option_key_of(f); };
  AgilityRequest r;
  r.min_response_pct = 120.0;
  EXPECT_EQ(key_of([&] { r.validate(); }), "min_response");
  r = {};
  r.min_demand_pct = -1.0;
  EXPECT_EQ(key_of([&] { r.validate(); }), "min_demand");
  r = {};
  r.min_demand_pct = std::nan("");  // NaN is no demand either
  EXPECT_EQ(key_of([&] { r.validate(); }), "min_demand");
  r = {};
  r.current = ObservedCurrent{-1.0, 0.0};
  EXPECT_EQ(key_of([&] { r.validate(); }), "current");
  r = {};
  EXPECT_EQ(key_of([&] { r.validate(); }), "no error");
}

TEST(AgilityAnalysis, AWindowOutsideTheLogNamesTheKeyAndTheLog) {
  const std::filesystem::path log = write_log("outside.csv");
  AgilityRequest request = request_for(log);
  request.windows = {ident::AgilityWindow{10.0, 5000.0, 90.0, 100.0, std::nullopt}};
  try {
    run_agility(request);
    FAIL() << "no error";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.option(), "window");
    EXPECT_EQ(e.where().file, log.string());
    EXPECT_NE(std::string(e.what()).find("is not inside the log"), std::string::npos);
  }
}

TEST(AgilityAnalysis, WriteOutputsWritesThePlotThenTheJson) {
  const std::filesystem::path log = write_log("outputs.csv");
  const AgilityReport report = run_agility(request_for(log));
  Outputs outputs;
  outputs.figures = log.parent_path() / "agility_outputs.svg";
  outputs.json = (log.parent_path() / "agility_outputs.json").string();
  const Written written = write_outputs(report, outputs);
  ASSERT_EQ(written.size(), 2u);
  EXPECT_EQ(written[0], outputs.figures);
  EXPECT_EQ(written[1], std::filesystem::path(outputs.json));
  EXPECT_TRUE(std::filesystem::exists(outputs.figures));
  EXPECT_TRUE(std::filesystem::exists(outputs.json));
}

TEST(AgilityAnalysis, ErrorsInTheLogNameTheFileAndTheChannelRole) {
  const std::filesystem::path blank = write_log("blank.csv", true);
  try {
    run_agility(request_for(blank));
    FAIL() << "no error";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.where().file, blank.string());
    EXPECT_EQ(e.where().column_name, "thrust.port");
  }
  AgilityRequest rpm = request_for(write_log("no_rpm.csv"));
  rpm.use_rpm = true;
  try {
    run_agility(rpm);
    FAIL() << "no error";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.where().file, rpm.source.log.string());
    EXPECT_EQ(e.problem(), "no shaft speed channel (rpm.NAME) in the log");
  }
}

TEST(AgilityAnalysis, JsonTextAndPlot) {
  AgilityRequest request = request_for(write_log("adapters.csv"));
  request.current = ObservedCurrent{0.2, 318.0};
  const AgilityReport report = run_agility(request);
  const nlohmann::json doc = to_json(report);
  for (const char* key :
       {"analysis", "log", "definition", "channel", "thrusters", "min_response_fraction", "status",
        "message", "current", "cases", "directions"}) {
    EXPECT_TRUE(doc.contains(key)) << key;
  }
  EXPECT_EQ(doc["analysis"], "agility");
  EXPECT_EQ(doc["status"], "ok");
  EXPECT_EQ(doc["current"]["to_deg"], 318.0);
  ASSERT_EQ(doc["directions"].size(), 2u);
  const nlohmann::json& d = doc["directions"][0];
  for (const char* key : {"direction_deg", "magnitude_pct", "yaw_pct", "case", "t_step", "t_end",
                          "response_s", "thrust_envelope_s", "speed_response_s", "notes"}) {
    EXPECT_TRUE(d.contains(key)) << key;
  }
  EXPECT_NEAR(d["response_s"]["port"].get<double>(), 7.32, 1e-9);
  EXPECT_TRUE(d["response_s"]["stb"].is_null());  // no response: null, never 0
  EXPECT_TRUE(d["speed_response_s"].is_null());   // no speed logged
  EXPECT_EQ(doc["cases"][0]["steps"], 2);

  const std::string text = to_text(report);
  EXPECT_EQ(text.rfind(report.log.string() + ": thrust agility", 0), 0u) << text;
  EXPECT_NE(text.find("50 % thrust, no yaw: wind 5.0 m/s from 90°\n"), std::string::npos) << text;
  EXPECT_NE(text.find("7.3"), std::string::npos) << text;

  const std::filesystem::path svg = report.log.parent_path() / "agility.svg";
  write_plot(report, svg);
  std::ifstream in(svg);
  const std::string content((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(content.find("<svg"), std::string::npos);
  EXPECT_NE(content.find("Thrust agility: adapters.csv"), std::string::npos);
  EXPECT_NE(content.find(">current 0.2 m/s<"), std::string::npos);
}

}  // namespace
}  // namespace dynpos::analysis
