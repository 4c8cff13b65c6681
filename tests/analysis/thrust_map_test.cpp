#include "dynpos/analysis/thrust_map.hpp"

#include <fmt/core.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../io/io_test_util.hpp"
#include "dynpos/analysis/data_dir.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/model/thruster.hpp"
#include "dynpos/model/tunnel_thruster.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::analysis {
namespace {

using io::testing::TempDir;
using ::testing::HasSubstr;

// Thesis table 3.2: c₊ = 8.13 kN/rps², c₋ = −5.8 kN/rps².
constexpr double kCForward = 8130.0, kCReverse = -5800.0;

// Shaft speed −180 … 180 rpm in 1 rpm steps, one a second. The port propeller logs the thrust
// of table 3.2's map; the tunnel logs its shaft speed only (forward only, 0 … 90 rpm).
std::string thrust_csv() {
  std::string csv = "time [s],rpm.port [rpm],thrust.port [kN],rpm.tunnel [rpm]\n";
  for (int k = 0; k <= 360; ++k) {
    const double n_rpm = k - 180.0, n = n_rpm / 60.0;
    const double thrust_N = (n >= 0.0 ? kCForward : kCReverse) * n * n;
    csv += fmt::format("{},{},{:.17g},{}\n", k, n_rpm, thrust_N / 1000.0, k / 4.0);
  }
  return csv;
}

ThrustMapRequest request_for(const std::filesystem::path& log) {
  ThrustMapRequest r;
  r.source.log = log;
  return r;
}

TEST(RunThrustMap, BackCalculatesTable32) {
  const TempDir dir;
  ThrustMapRequest r = request_for(dir.write("log.csv", thrust_csv()));
  r.min_speed_rpm = 10.5;
  const ThrustMapReport report = run_thrust_map(r);
  EXPECT_FALSE(report.applied.has_value());
  // The tunnel has no thrust: nothing to fit.
  ASSERT_EQ(report.thrusters.size(), 1u);
  const ThrusterMapFit& port = report.thrusters[0];
  EXPECT_EQ(port.name, "port");
  EXPECT_EQ(port.fit.status, core::Status::kOk);
  ASSERT_TRUE(port.fit.c_forward && port.fit.c_reverse && port.c_mean);
  // Exact data but for the unit conversions (rpm, kN): round-off only.
  EXPECT_NEAR(port.fit.c_forward->value, kCForward, kCForward * 1e-9);
  EXPECT_NEAR(port.fit.c_reverse->value, kCReverse, -kCReverse * 1e-9);
  EXPECT_NEAR(*port.c_mean, 6965.0, 6965.0 * 1e-9);  // (3.18)
  // |n| ≥ 10.5 rpm: 11 … 180 rpm on each side.
  EXPECT_EQ(port.fit.samples_forward, 170u);
  EXPECT_EQ(port.fit.samples_reverse, 170u);
}

TEST(RunThrustMap, AppliesTheVesselModelsCoefficients) {
  const TempDir dir;
  ThrustMapRequest r;
  r.source.log = dir.write("log.csv", thrust_csv());
  r.apply = true;
  r.out = "out.csv";
  const ThrustMapReport report = run_thrust_map(r);
  ASSERT_TRUE(report.applied.has_value());
  EXPECT_TRUE(report.thrusters.empty());
  EXPECT_EQ(report.applied->thrusters, 2u);
  const core::Log& log = report.applied->log;
  // The thruster models at zero advance speed / zero surge speed (no speed loss there).
  const scenario::VesselConfig vessel =
      scenario::load_vessel_config(find_data_dir() / "vessels" / "gunnerus.toml");
  const model::Thruster propeller(vessel.propeller);
  const model::TunnelThruster tunnel(vessel.tunnel);
  const std::vector<double>& rpm = log.values("rpm.port");
  const std::vector<double>& thrust_kN = log.values("thrust.port");
  ASSERT_EQ(rpm.size(), 361u);
  for (std::size_t i = 0; i < rpm.size(); ++i) {
    const double want_kN = propeller.thrust(rpm[i] / 60.0, 0.0) / 1000.0;
    EXPECT_NEAR(thrust_kN[i], want_kN, 1e-12 * (1.0 + std::abs(want_kN))) << rpm[i];
  }
  const double n_tunnel = log.values("rpm.tunnel").back() / 60.0;
  EXPECT_NEAR(log.values("thrust.tunnel").back(), tunnel.thrust(n_tunnel, 0.0) / 1000.0, 1e-12);
  EXPECT_THAT(to_text(report), HasSubstr("thrust of 2 thruster(s) from " + vessel.source +
                                         " (signed n: c+ / c- (3.17)) into out.csv"));
}

TEST(RunThrustMap, ErrorsNameTheLogOrTheKey) {
  const TempDir dir;
  ThrustMapRequest r = request_for(dir.write("log.csv", thrust_csv()));
  r.min_speed_rpm = -1.0;
  try {
    r.validate();
    ADD_FAILURE() << "a negative speed must not validate";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.option(), "min_speed");
  }
  // No thrust column at all: the log is named.
  r.min_speed_rpm = 3.0;
  r.source.log = dir.write("speed_only.csv", "time [s],rpm.port [rpm]\n0,1\n1,2\n");
  try {
    run_thrust_map(r);
    ADD_FAILURE() << "a log without thrust must not fit";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.where().file, r.source.log.string());
    EXPECT_THAT(e.what(), HasSubstr("no thruster with both shaft speed and thrust"));
  }
  // A thruster the vessel file has no map for.
  r.source.log = dir.write("odd.csv", "time [s],rpm.aft [rpm]\n0,1\n1,2\n");
  r.apply = true;
  try {
    run_thrust_map(r);
    ADD_FAILURE() << "apply needs a CSV to write";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.option(), "out");
  }
  r.out = dir.path() / "applied.csv";
  try {
    run_thrust_map(r);
    ADD_FAILURE() << "no map for 'aft'";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.where().file, r.source.log.string());
    EXPECT_EQ(e.where().column_name, "rpm.aft");
  }
}

TEST(RunThrustMap, WriteOutputsWritesTheAppliedCsvAndTheJson) {
  const TempDir dir;
  ThrustMapRequest r = request_for(dir.write("log.csv", thrust_csv()));
  r.apply = true;
  r.out = dir.path() / "applied.csv";
  const ThrustMapReport report = run_thrust_map(r);
  Outputs outputs;
  outputs.json = (dir.path() / "map.json").string();
  const Written written = write_outputs(report, outputs);
  ASSERT_EQ(written.size(), 1u);  // the CSV is named by the text, not listed
  EXPECT_EQ(written[0], dir.path() / "map.json");
  EXPECT_TRUE(std::filesystem::exists(r.out));
  EXPECT_THAT(to_text(report), HasSubstr("into " + r.out.string()));
  // Without apply: the JSON only.
  r.apply = false;
  const Written fit = write_outputs(run_thrust_map(r), outputs);
  EXPECT_EQ(fit.size(), 1u);
}

TEST(ThrustMapReport, JsonHasTheContractKeysAndNullNotZero) {
  const TempDir dir;
  // Forward speeds only: c₋ and c̄ are missing, null in JSON.
  std::string csv = "time [s],rpm.stb [rpm],thrust.stb [kN]\n";
  for (int k = 0; k < 100; ++k) {
    const double n = (k + 10) / 60.0;
    csv += fmt::format("{},{},{:.17g}\n", k, k + 10, kCForward * n * n / 1000.0);
  }
  const nlohmann::json doc = to_json(run_thrust_map(request_for(dir.write("fwd.csv", csv))));
  EXPECT_EQ(doc["analysis"], "thrust-map");
  EXPECT_EQ(doc["unit"], "N/rps^2");
  EXPECT_TRUE(doc.contains("log"));
  ASSERT_EQ(doc["thrusters"].size(), 1u);
  const nlohmann::json& stb = doc["thrusters"][0];
  for (const char* key : {"name", "c_pos", "c_neg", "sigma", "c_mean", "n_samples", "r_squared",
                          "status", "message"}) {
    EXPECT_TRUE(stb.contains(key)) << key;
  }
  EXPECT_EQ(stb["name"], "stb");
  EXPECT_NEAR(stb["c_pos"].get<double>(), kCForward, kCForward * 1e-9);
  EXPECT_TRUE(stb["c_neg"].is_null());
  EXPECT_TRUE(stb["c_mean"].is_null());
  EXPECT_EQ(stb["n_samples"]["pos"], 100);
  EXPECT_EQ(stb["n_samples"]["neg"], 0);
}

TEST(ThrustMapReport, TextShowsKilonewtons) {
  const TempDir dir;
  const std::string text = to_text(run_thrust_map(request_for(dir.write("l.csv", thrust_csv()))));
  EXPECT_THAT(text, HasSubstr("thrust map T = c·n|n| (3.17), |n| ≥ 3 rpm, ±1σ"));
  EXPECT_THAT(text, HasSubstr("8.130"));
  EXPECT_THAT(text, HasSubstr("-5.800"));
}

}  // namespace
}  // namespace dynpos::analysis
