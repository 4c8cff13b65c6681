// identify vessel on a vessel with a [[thruster]] layout (azimuths and tunnels, no rudders): the
// 80 m supply vessel's joystick programme (surge and sway steps, yaw-moment steps at rest, the
// yaw-moment zig-zag) gives the hull of osv-80m.toml back, and the held-out zig-zag re-simulates
// within 5 %; each unit's dead time, shaft time constant and (an azimuth's) slew rate come back
// from the file's values and from a start 30 % off them.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "../source_dir.hpp"
#include "dynpos/analysis/capability.hpp"
#include "dynpos/analysis/vessel_id.hpp"
#include "dynpos/core/parallel_for.hpp"
#include "dynpos/model/unit_drive.hpp"
#include "dynpos/scenario/run_files.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/vessel_config.hpp"
#include "identified_file_runs.hpp"

namespace dynpos {
namespace {

const std::filesystem::path kSource = DYNPOS_SOURCE_DIR;
const std::filesystem::path kVessel = kSource / "data" / "vessels" / "osv-80m.toml";

// The units' true values: the file's, with the drive's defaults where it leaves a key out.
std::map<std::string, double> unit_truth(const scenario::VesselConfig& vessel) {
  std::map<std::string, double> truth;
  for (const model::ThrusterUnit& u : vessel.thrusters) {
    truth["thruster." + u.name + ".dead_time_s"] = u.dead_time_s;
    truth["thruster." + u.name + ".time_constant_s"] = model::drive_params(u).time_constant_s;
    if (u.type == model::UnitType::kAzimuth) {
      truth["thruster." + u.name + ".rate_deg_per_s"] = u.rate_deg_per_s;
    }
  }
  return truth;
}

// Checks the units' values of `report` against `truth`: each determined one within 10 % and 3σ
// (as the hull's); returns how many are determined.
int check_units(const analysis::VesselIdReport& report, const std::map<std::string, double>& truth,
                const char* what) {
  int determined = 0;
  for (const analysis::VesselParameter& p : report.parameters) {
    const auto it = truth.find(p.key);
    if (it == truth.end()) continue;
    if (!p.determined) {
      std::printf("%s: %s not determined: %s\n", what, p.key.c_str(), p.note.c_str());
      continue;
    }
    ++determined;
    const double error = p.value - it->second;
    std::printf("%s: %s %.5g (truth %.5g, %+.2f %%, sigma %.2g = %.2f %%, %.1f sigma)\n", what,
                p.key.c_str(), p.value, it->second, 100.0 * error / it->second, p.sigma,
                100.0 * p.sigma / std::abs(p.value), std::abs(error) / p.sigma);
    EXPECT_LE(std::abs(error), 3.0 * p.sigma) << what << " " << p.key;
    EXPECT_LE(std::abs(error), 0.10 * std::abs(it->second)) << what << " " << p.key;
  }
  return determined;
}

TEST(VesselIdOnAnAzimuthVessel, TheJoystickProgrammeGivesTheHullBack) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "dynpos_vessel_id_layout";
  std::filesystem::remove_all(dir);
  const scenario::VesselConfig vessel = scenario::load_vessel_config(kVessel);
  ASSERT_FALSE(vessel.thrusters.empty()) << kVessel << " has no [[thruster]] layout";
  // The last is held out for the cross-validation (the request's default).
  const std::vector<std::string> names = {"surge-steps-forward", "sway-steps-port",
                                          "yaw-steps-joystick", "zig-zag-joystick"};
  analysis::VesselIdRequest request;
  request.logs.resize(names.size());
  core::parallel_for(names.size(), 2, [&](std::size_t k) {
    const scenario::ScenarioSpec spec =
        scenario::load_scenario(kSource / "data" / "scenarios" / (names[k] + ".toml"));
    scenario::write_scenario_run(scenario::run_scenario(spec, vessel, 1), dir / names[k]);
    request.logs[k].log = dir / names[k] / "log.csv";
  });
  request.vessel_file = kVessel;
  request.jobs = 2;
  const analysis::VesselIdReport report = analysis::run_vessel_id(request);
  std::cout << analysis::to_text(report);
  std::printf("identify vessel: the supply vessel's programme in %.1f s\n", report.run_time_s);

  const std::map<std::string, double> truth = unit_truth(vessel);
  int determined = 0;
  for (const analysis::VesselParameter& p : report.parameters) {
    if (!p.fitted || truth.contains(p.key)) continue;
    // Truth: the starting file is osv-80m.toml itself. 3σ for every fitted value, 10 % for
    // the determined ones (as on the Gunnerus).
    EXPECT_LE(std::abs(p.value - p.start), 3.0 * p.sigma) << p.key;
    if (!p.determined) continue;
    ++determined;
    EXPECT_LE(std::abs(p.value - p.start), 0.10 * std::abs(p.start)) << p.key;
  }
  // The added masses and the linear damping of all three axes at least.
  EXPECT_GE(determined, 6);
  ASSERT_FALSE(report.tests.empty());
  const analysis::TestResponse& held = report.tests.back();
  ASSERT_TRUE(held.held_out);
  for (int c = 0; c < 3; ++c) EXPECT_LE(held.nrmse[static_cast<std::size_t>(c)], 0.05) << c;

  // Every unit's dead time and time constant, and the azimuths' slew rates (5 + 5 + 3).
  EXPECT_EQ(check_units(report, truth, "from the file"), 13);

  // The identified file keeps its layout, has the units' values (the file leaves their dead time
  // and time constant at the defaults: the keys are added to each [[thruster]] table) and runs
  // in simulate and capability as written.
  const std::filesystem::path out = dir / "identified.toml";
  analysis::write_outputs(report, out, {});
  const scenario::VesselConfig identified = scenario::load_vessel_config(out);
  ASSERT_EQ(identified.thrusters.size(), vessel.thrusters.size());
  for (const analysis::VesselParameter& p : report.parameters) {
    if (!p.determined || !truth.contains(p.key)) continue;
    const std::map<std::string, double> written = unit_truth(identified);
    // Written with at least 6 significant digits.
    EXPECT_NEAR(written.at(p.key), p.value, 1e-5 * std::abs(p.value)) << p.key;
  }
  testing::expect_identified_file_runs(out, "pure-dp");

  // A start 30 % off in every unit's dead time, time constant and slew rate: the same logs give
  // the units back (the hull's fit, coarse here, is not what this checks).
  std::string text;
  {
    std::ifstream in(kVessel);
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  std::string off;
  for (std::size_t at = 0, next = 0; at < text.size(); at = next) {
    next = std::min(text.find('\n', at), text.size()) + 1;
    const std::string line = text.substr(at, next - at);
    if (line.rfind("rate_deg_per_s", 0) == 0) continue;  // set below
    off += line;
    if (line.rfind("name = \"", 0) != 0) continue;
    for (const model::ThrusterUnit& u : vessel.thrusters) {
      if (line != "name = \"" + u.name + "\"\n") continue;
      off += "dead_time_s = " + std::to_string(1.3 * u.dead_time_s) + "\n";
      off += "time_constant_s = " + std::to_string(1.3 * model::drive_params(u).time_constant_s) +
             "\n";
      if (u.type == model::UnitType::kAzimuth) {
        off += "rate_deg_per_s = " + std::to_string(1.3 * u.rate_deg_per_s) + "\n";
      }
    }
  }
  const std::filesystem::path off_file = dir / "off.toml";
  std::ofstream(off_file) << off;
  const scenario::VesselConfig off_vessel = scenario::load_vessel_config(off_file);
  ASSERT_EQ(off_vessel.thrusters.size(), vessel.thrusters.size());
  for (std::size_t k = 0; k < vessel.thrusters.size(); ++k) {
    ASSERT_NEAR(off_vessel.thrusters[k].dead_time_s, 1.3 * vessel.thrusters[k].dead_time_s, 1e-5);
  }
  analysis::VesselIdRequest off_request = request;
  off_request.vessel_file = off_file;
  off_request.holdout = "none";
  off_request.step_s = 1.0;
  off_request.sample_s = 60.0;
  off_request.stretch_s = 1e6;
  const analysis::VesselIdReport from_off = analysis::run_vessel_id(off_request);
  EXPECT_EQ(check_units(from_off, truth, "from 30 % off"), 13);
  // The same dead times and time constants as from the file (the rounds settle where the
  // model's fits are the log's; the turns taken for a slew rate depend on the file's rate).
  for (const analysis::VesselParameter& p : from_off.parameters) {
    if (!p.determined || !truth.contains(p.key) || p.key.ends_with("rate_deg_per_s")) continue;
    for (const analysis::VesselParameter& q : report.parameters) {
      if (q.key == p.key && q.determined) {
        EXPECT_NEAR(p.value, q.value, 0.1 * q.sigma) << p.key;
      }
    }
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace dynpos
