#include "dynpos/analysis/four_corner.hpp"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "dynpos/core/error.hpp"
#include "input_error_capture.hpp"

namespace dynpos::analysis {
namespace {

// Two legs of a 4-corner at 1 Hz, heading 0° throughout: hold at (0, 0) to 60 s; ahead to
// (50, 0) at 0.5 m/s over 60–160 s; hold to 200 s; crab to starboard to (50, 50) at 0.5 m/s
// over 200–300 s; hold to 340 s. The setpoint changes at 60 and 200 s. One thruster: 10 kN and
// 50 kW throughout.
std::filesystem::path write_log(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::path(::testing::TempDir()) / "four_corner_test";
  std::filesystem::create_directories(dir);
  const std::filesystem::path path = dir / name;
  std::ofstream out(path);
  out << "time [s],north [m],east [m],heading [deg],setpoint.north [m],setpoint.east [m],"
         "setpoint.heading [deg],thrust.port [kN],power.port [kW]\n";
  for (int t = 0; t <= 340; ++t) {
    const double north = 0.5 * std::clamp(t - 60, 0, 100);
    const double east = 0.5 * std::clamp(t - 200, 0, 100);
    const double sp_north = t >= 60 ? 50.0 : 0.0;
    const double sp_east = t >= 200 ? 50.0 : 0.0;
    out << fmt::format("{},{},{},0,{},{},0,10,50\n", t, north, east, sp_north, sp_east);
  }
  return path;
}

FourCornerRequest request_for(const std::filesystem::path& log) {
  FourCornerRequest r;
  r.source.log = log;
  r.radius_m = 2.25;  // crossed between two samples: the first sample inside is unambiguous
  return r;
}

TEST(FourCornerAnalysis, LegsFromTheSetpointsWithThrustAndEnergy) {
  const FourCornerReport report = run_four_corner(request_for(write_log("box.csv")));
  EXPECT_EQ(report.result.segmentation, "setpoints");
  ASSERT_EQ(report.result.legs.size(), 2u);
  // Each leg starts at its setpoint change and ends at the first sample inside the 2.25 m circle
  // of the position averaged over ±5 s (the wave filter): at 156 s the mean over 151–161 s is
  // 47.95 m, 2.05 m short; at 155 s it is 47.5 m, 2.5 m short.
  const double starts[] = {60.0, 200.0};
  const double ends[] = {156.0, 296.0};
  for (std::size_t k = 0; k < 2; ++k) {
    SCOPED_TRACE(k);
    const ident::Leg& leg = report.result.legs[k];
    EXPECT_NEAR(leg.t_start_s, starts[k], 1e-9);
    EXPECT_NEAR(leg.t_end_s, ends[k], 1e-9);
    EXPECT_TRUE(leg.reached);
    // Constant 10 kN and 50 kW: duration × value (the trapezoid rule is exact on a constant).
    ASSERT_EQ(leg.thrusters.size(), 1u);
    EXPECT_NEAR(*leg.thrusters[0].accumulated_thrust_Ns, 10e3 * 96.0, 1e-6);
    EXPECT_NEAR(*leg.thrusters[0].energy_J, 50e3 * 96.0, 1e-6);
  }
  EXPECT_EQ(report.result.legs[0].name, "ahead 50 m");
  EXPECT_EQ(report.result.legs[1].name, "crab to starboard 50 m");
  EXPECT_NEAR(report.result.total.duration_s, 192.0, 1e-9);
}

TEST(FourCornerAnalysis, TheWindowCutsTheLog) {
  FourCornerRequest request = request_for(write_log("window.csv"));
  request.t_to_s = 190.0;  // the first leg only
  const FourCornerReport report = run_four_corner(request);
  ASSERT_EQ(report.result.legs.size(), 1u);
  EXPECT_EQ(report.track.t_s.back(), 190.0);
  EXPECT_NEAR(report.result.legs[0].t_end_s, 156.0, 1e-9);
  // Only the window is read of the file (rows 0 … 190 s of 0 … 340 s).
  EXPECT_EQ(report.input.files.at(0).records, 191u);
}

TEST(FourCornerAnalysis, BadOptionsNameTheirKey) {
  const auto key_of = [](const auto& f) { return testing::option_key_of(f); };
  EXPECT_EQ(key_of([] { parse_leg_segmentation("box"); }), "segment");
  EXPECT_EQ(parse_leg_segmentation("track"), ident::LegSegmentation::kTrack);
  FourCornerRequest r;
  r.radius_m = 0.0;
  EXPECT_EQ(key_of([&] { r.validate(); }), "radius/heading_tol");
  r = {};
  r.heading_tol_deg = -1.0;
  EXPECT_EQ(key_of([&] { r.validate(); }), "radius/heading_tol");
  r = {};
  EXPECT_EQ(key_of([&] { r.validate(); }), "no error");
  r.arm_m = Eigen::Vector2d(0.5, std::nan(""));
  EXPECT_EQ(key_of([&] { r.validate(); }), "arm");
  // A window without a row of the log names the option and the log (LogSource::load).
  FourCornerRequest outside = request_for(write_log("outside.csv"));
  outside.t_from_s = 5000.0;
  try {
    run_four_corner(outside);
    FAIL() << "no error";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.option(), "from/to");
    EXPECT_EQ(e.where().file, outside.source.log.string());
    EXPECT_NE(
        e.problem().find("the window from 5000 s on starts after the log's last row at 340 s"),
        std::string::npos)
        << e.problem();
  }
}

// The segmentations by name: the names reports show are the names the options take.
TEST(FourCornerAnalysis, SegmentationsByName) {
  ASSERT_EQ(leg_segmentation_names().size(), 3u);
  for (const auto& [name, segmentation] : leg_segmentation_names()) {
    EXPECT_EQ(to_string(segmentation), name);
    EXPECT_EQ(parse_leg_segmentation(name), segmentation);
  }
  EXPECT_EQ(to_string(FourCornerRequest{}.segmentation), "auto");
}

// The same bad windows give the same errors as every windowed analysis (LogSource::load):
// one without a row of the log, and an empty one; the ident error of the legs names the log.
TEST(FourCornerAnalysis, WindowErrorsAreTheLogSources) {
  FourCornerRequest request = request_for(write_log("windows.csv"));
  const auto problem_of = [&](double from, double to) {
    request.t_from_s = from;
    request.t_to_s = to;
    const core::InputError e = testing::input_error([&] { run_four_corner(request); });
    EXPECT_EQ(e.option(), "from/to");
    EXPECT_EQ(e.where().file, request.source.log.string());
    return e.problem();
  };
  EXPECT_EQ(problem_of(5000.0, 6000.0),
            "the window 5000 … 6000 s starts after the log's last row at 340 s");
  EXPECT_EQ(problem_of(50.0, 10.0), "the window 50 … 10 s is empty");
  // A window inside the log is read alone: the legs it holds.
  request.t_from_s = 50.0;
  request.t_to_s = 190.0;
  const FourCornerReport report = run_four_corner(request);
  EXPECT_EQ(report.input.files.at(0).records, 141u);
  EXPECT_EQ(report.track.t_s.front(), 50.0);
}

TEST(FourCornerAnalysis, JsonTableAndPlot) {
  FourCornerRequest request = request_for(write_log("adapters.csv"));
  request.arm_m = Eigen::Vector2d::Zero();
  const FourCornerReport report = run_four_corner(request);
  const nlohmann::json doc = to_json(report);
  for (const char* key : {"analysis", "log", "segmentation", "radius_m", "arm_m", "heading_tol_deg",
                          "thrusters", "legs", "total"}) {
    EXPECT_TRUE(doc.contains(key)) << key;
  }
  EXPECT_EQ(doc["analysis"], "four-corner");
  EXPECT_EQ(doc["arm_m"], nlohmann::json::array({0.0, 0.0}));
  EXPECT_EQ(doc["thrusters"], nlohmann::json::array({"port"}));
  const nlohmann::json& leg = doc["legs"][0];
  for (const char* key : {"name", "t_start", "t_end", "duration_s", "reached", "move", "setpoint",
                          "thrust_kNs", "energy_kJ"}) {
    EXPECT_TRUE(leg.contains(key)) << key;
  }
  EXPECT_NEAR(leg["thrust_kNs"]["port"].get<double>(), 960.0, 1e-9);
  EXPECT_NEAR(leg["energy_kJ"]["total"].get<double>(), 4800.0, 1e-9);
  EXPECT_FALSE(doc["total"].contains("move"));

  const std::string text = to_text(report);
  EXPECT_EQ(text.rfind(report.log.string() + ": DP 4-corner, 2 legs from the setpoints\n", 0), 0u)
      << text;
  const report::Table table = four_corner_table(report);
  ASSERT_EQ(table.rows.size(), 3u);  // two legs and the total
  EXPECT_EQ(table.rows[2][0], "total");
  EXPECT_EQ(table.rows[0][4], "960");   // thrust port [kNs]
  EXPECT_EQ(table.rows[2][7], "9600");  // energy total [kJ]

  const std::filesystem::path svg = report.log.parent_path() / "ne.svg";
  write_plot(report, svg);
  std::ifstream in(svg);
  const std::string content((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(content.find("<svg"), std::string::npos);
  EXPECT_NE(content.find("DP 4-corner: " + report.log.string()), std::string::npos);
}

}  // namespace
}  // namespace dynpos::analysis
