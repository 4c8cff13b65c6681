#include "dynpos/analysis/station_keeping.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <string>

#include <fmt/core.h>

#include "../io/io_test_util.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/io/csv_reader.hpp"
#include "input_error_capture.hpp"

namespace dynpos::analysis {
namespace {

using io::testing::TempDir;
using testing::input_error;

// 400 s at 1 Hz: the DP setpoint (and the heading) 0° for t < 200 s, then 90°. North alternates
// 100.5 / 99.5 m (std 0.5 m), east is 200 m; wind 8 m/s from 350°; the port thruster gives
// 20 kN at 100 kW; the tunnel logs thrust only.
std::filesystem::path write_log(const TempDir& dir) {
  std::string csv =
      "time [s],north [m],east [m],heading [deg],setpoint.heading [deg],wind_speed [m/s],"
      "wind_dir [deg],thrust.port [kN],power.port [kW],thrust.tunnel [kN]\n";
  for (int i = 0; i < 400; ++i) {
    const double heading = i < 200 ? 0.0 : 90.0;
    csv += fmt::format("{},{},200,{},{},8,350,20,100,-5\n", i, i % 2 == 0 ? 100.5 : 99.5, heading,
                       heading);
  }
  return dir.write("log.csv", csv);
}

TEST(StationKeepingAnalysis, ReportsWhatWasRead) {
  TempDir dir;
  StationKeepingRequest request;
  request.source.log = write_log(dir);
  const StationKeepingReport report = run_station_keeping(request);
  ASSERT_EQ(report.input.files.size(), 1u);
  EXPECT_EQ(report.input.files[0].path, request.source.log.string());
  EXPECT_EQ(report.input.files[0].format, "csv");
  EXPECT_EQ(report.input.files[0].records, 400u);
  // Every channel is a role of the one file, logged at 1 Hz.
  ASSERT_FALSE(report.input.roles.empty());
  for (const io::RoleOrigin& r : report.input.roles) {
    EXPECT_EQ(r.file, request.source.log.string()) << r.role;
    ASSERT_TRUE(r.rate_hz) << r.role;
    EXPECT_DOUBLE_EQ(*r.rate_hz, 1.0) << r.role;
  }
  const nlohmann::json j = to_json(report);
  EXPECT_EQ(j.at("input").at("files").at(0).at("records"), 400);
  EXPECT_NE(to_text(report).find("input: " + request.source.log.string() + " (csv"),
            std::string::npos);
}

TEST(StationKeepingAnalysis, PerSetpointWindowsOfAKnownLog) {
  TempDir dir;
  StationKeepingRequest request;
  request.source.log = write_log(dir);
  request.per_setpoint = true;
  request.duration_s = 100.0;
  const StationKeepingReport report = run_station_keeping(request);
  // The last 100 s of each hold: 99 … 199 s and 299 … 399 s.
  ASSERT_EQ(report.windows.size(), 2u);
  EXPECT_EQ(report.windows[0].window.name, "heading 0");
  EXPECT_DOUBLE_EQ(report.windows[0].window.t_from_s, 99.0);
  EXPECT_DOUBLE_EQ(report.windows[0].window.t_to_s, 199.0);
  EXPECT_EQ(report.windows[1].window.name, "heading 90");
  EXPECT_DOUBLE_EQ(report.windows[1].window.t_to_s, 399.0);
  const ident::StationKeepingResult& w = report.windows[1];
  // ±0.5 m over 101 samples (one extra of one sign): std 0.5·√(1 − 1/101²), within 1e-4 m.
  ASSERT_TRUE(w.position_std_north_m);
  EXPECT_NEAR(*w.position_std_north_m, 0.5, 1e-4);
  EXPECT_NEAR(*w.position_std_east_m, 0.0, 1e-9);
  ASSERT_EQ(w.thrusters.size(), 2u);
  EXPECT_EQ(w.thrusters[0].name, "port");
  EXPECT_NEAR(*w.thrusters[0].mean_abs_thrust_N, 20e3, 1e-6);
  EXPECT_NEAR(*w.thrusters[0].energy_J, 100e3 * 100.0, 1e-3);  // 100 kW for 100 s
  EXPECT_NEAR(*w.total_mean_abs_thrust_N, 25e3, 1e-6);         // |−5| + 20 kN
  EXPECT_FALSE(w.total_energy_J);                              // the tunnel's power is not logged

  const nlohmann::json doc = to_json(report);
  EXPECT_EQ(doc.at("analysis"), "station-keeping");
  EXPECT_EQ(doc.at("log"), request.source.log.string());
  EXPECT_TRUE(doc.at("observed").at("waves").is_null());
  ASSERT_EQ(doc.at("windows").size(), 2u);
  const nlohmann::json& j = doc.at("windows")[1];
  for (const char* key : {"name", "t_from", "t_to", "position_samples", "position_std_m",
                          "heading_deg", "wind_speed_mps", "wind_dir_deg", "thrusters", "thrust_kN",
                          "energy_kJ", "accumulated_thrust_kNs"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_NEAR(j.at("heading_deg").at("mean").get<double>(), 90.0, 1e-9);
  EXPECT_NEAR(j.at("wind_dir_deg").at("mean").get<double>(), 350.0, 1e-9);
  EXPECT_NEAR(j.at("thrust_kN").at("total").get<double>(), 25.0, 1e-9);
  EXPECT_NEAR(j.at("energy_kJ").at("port").get<double>(), 10000.0, 1e-6);
  EXPECT_TRUE(j.at("energy_kJ").at("total").is_null());
}

TEST(StationKeepingAnalysis, NoHoldLongEnoughIsAnErrorNotAnEmptyTable) {
  TempDir dir;
  StationKeepingRequest request;
  request.source.log = write_log(dir);  // two holds of 200 s
  request.per_setpoint = true;
  request.duration_s = 1000.0;  // a hold needs 500 s
  const core::InputError e = testing::input_error([&] { run_station_keeping(request); });
  EXPECT_EQ(e.option(), "per_setpoint");
  EXPECT_EQ(e.where().file, request.source.log.string());
  EXPECT_NE(e.problem().find("no setpoint is held for 500 s"), std::string::npos);
}

TEST(StationKeepingAnalysis, OneWindowIsTheTopLevelOfTheDocument) {
  TempDir dir;
  StationKeepingRequest request;
  request.source.log = write_log(dir);
  request.t_from_s = 250.0;  // to = from + duration
  request.duration_s = 50.0;
  request.waves = "Hs 2 m";
  const StationKeepingReport report = run_station_keeping(request);
  ASSERT_EQ(report.windows.size(), 1u);
  EXPECT_DOUBLE_EQ(report.windows[0].window.t_to_s, 300.0);
  const nlohmann::json doc = to_json(report);
  EXPECT_FALSE(doc.contains("windows"));
  EXPECT_EQ(doc.at("name"), "window");
  EXPECT_EQ(doc.at("observed").at("waves"), "Hs 2 m");
  EXPECT_EQ(doc.at("position_samples"), 51);

  const std::string text = to_text(report);
  EXPECT_NE(text.find("stationkeeping, 1 window(s)\n  window: 250.0 … 300.0 s\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("waves (observed): Hs 2 m\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("current (observed)"), std::string::npos) << text;
  const report::Table table = station_keeping_table(report);
  ASSERT_EQ(table.header.size(), 2u);
  // Rows: wind ×4, position ×2, heading ×2, then thrust and energy of port, tunnel and total.
  ASSERT_EQ(table.rows.size(), 14u);
  EXPECT_EQ(table.rows[2][0], "wind from, mean [deg]");
  EXPECT_EQ(table.rows[2][1], "350");
  EXPECT_EQ(table.rows[6][1], "90.0");  // heading mean
  EXPECT_EQ(table.rows[10][0], "mean thrust total [kN]");
  EXPECT_EQ(table.rows[10][1], "25.0");
  EXPECT_EQ(table.rows[12][0], "energy tunnel [kJ]");
  EXPECT_EQ(table.rows[12][1], "—");
}

TEST(StationKeepingAnalysis, TheDefaultWindowIsTheEndOfTheLog) {
  TempDir dir;
  StationKeepingRequest request;
  request.source.log = write_log(dir);
  const StationKeepingReport report = run_station_keeping(request);
  ASSERT_EQ(report.windows.size(), 1u);
  EXPECT_EQ(report.windows[0].window.name, "last 300 s");
  EXPECT_DOUBLE_EQ(report.windows[0].window.t_from_s, 99.0);
  EXPECT_DOUBLE_EQ(report.windows[0].window.t_to_s, 399.0);
}

TEST(StationKeepingAnalysis, ValidateNamesTheDuration) {
  StationKeepingRequest request;
  request.duration_s = 0.0;
  const core::InputError e = input_error([&] { request.validate(); });
  EXPECT_EQ(e.option(), "duration");
  EXPECT_EQ(e.problem(), "the window duration must be > 0 s");
  request.duration_s = 1.0;
  EXPECT_NO_THROW(request.validate());
}

TEST(StationKeepingAnalysis, ErrorsAboutTheLogNameIt) {
  TempDir dir;
  const std::filesystem::path log = dir.write("flat.csv", "time [s],x [m]\n0,1\n1,2\n2,3\n");
  StationKeepingRequest request;
  request.source.log = log;
  core::InputError e = input_error([&] { run_station_keeping(request); });
  EXPECT_EQ(e.where().file, log.string());
  EXPECT_EQ(e.problem(), "no position in the log");

  request.per_setpoint = true;
  const std::filesystem::path no_setpoints =
      dir.write("no_setpoints.csv", "time [s],north [m],east [m]\n0,1,2\n1,1,2\n2,1,2\n3,1,2\n");
  request.source.log = no_setpoints;
  e = input_error([&] { run_station_keeping(request); });
  EXPECT_EQ(e.where().file, no_setpoints.string());
  EXPECT_EQ(e.problem(), "--per-setpoint needs the DP setpoints in the log");
}

// A window given with --from/--to is all that is read of the file (finding M2: a 200 s window
// of a 4.8 GB log used to read it whole), and the figures are those of the whole log in the
// window: the same as from the log read whole into memory.
TEST(StationKeepingAnalysis, AGivenWindowIsAllThatIsRead) {
  TempDir dir;
  StationKeepingRequest request;
  request.source.log = write_log(dir);
  request.t_from_s = 100.5;
  request.t_to_s = 250.5;
  const StationKeepingReport windowed = run_station_keeping(request);
  EXPECT_EQ(windowed.input.files.at(0).records, 150u);  // rows 101 … 250 of 400

  StationKeepingRequest whole = request;
  whole.source.memory =
      std::make_shared<const core::Log>(io::read_csv_all(request.source.log, {}, {}));
  const StationKeepingReport in_memory = run_station_keeping(whole);
  EXPECT_EQ(in_memory.input.files.at(0).records, 400u);
  nlohmann::json a = to_json(windowed), b = to_json(in_memory);
  for (nlohmann::json* j : {&a, &b}) {
    j->erase("input");
    j->erase("log");
  }
  EXPECT_EQ(a.dump(), b.dump());

  // A window that reaches past either end of the log is still not inside it (the analysis'
  // rule); one without a row of the log is refused by LogSource::load, as in every analysis.
  const auto problem_of = [&](double from, double to) {
    request.t_from_s = from;
    request.t_to_s = to;
    const core::InputError e = input_error([&] { run_station_keeping(request); });
    EXPECT_EQ(e.option(), "from/to") << from;
    EXPECT_EQ(e.where().file, request.source.log.string());
    return e.problem();
  };
  EXPECT_EQ(problem_of(300.0, 450.0), "the window 300 … 450 s is not inside the log (0 … 399 s)");
  // (Read up to the window's end, the log is known to reach the first row after it.)
  EXPECT_EQ(problem_of(-50.0, 100.0), "the window -50 … 100 s is not inside the log (0 … 101 s)");
  EXPECT_EQ(problem_of(500.0, 600.0),
            "the window 500 … 600 s starts after the log's last row at 399 s");
  EXPECT_EQ(problem_of(50.0, 10.0), "the window 50 … 10 s is empty");
  // A missing end is duration_s from the other: 5000 … 5300 s.
  request.t_to_s.reset();
  request.t_from_s = 5000.0;
  const core::InputError e = input_error([&] { run_station_keeping(request); });
  EXPECT_EQ(e.problem(), "the window 5000 … 5300 s starts after the log's last row at 399 s");
}

// The outputs: the JSON only (the analysis draws no figure), listed as written.
TEST(StationKeepingAnalysis, WritesItsJson) {
  TempDir dir;
  StationKeepingRequest request;
  request.source.log = write_log(dir);
  const StationKeepingReport report = run_station_keeping(request);
  const std::filesystem::path json = dir.path() / "sk.json";
  const Written written = write_outputs(report, {.json = json.string(), .figures = {}});
  ASSERT_EQ(written.size(), 1u);
  EXPECT_EQ(written[0], json);
  std::ifstream in(json);
  EXPECT_EQ(nlohmann::json::parse(in), to_json(report));
  EXPECT_TRUE(write_outputs(report, {}).empty());
}

}  // namespace
}  // namespace dynpos::analysis
