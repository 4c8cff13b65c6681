// identify vessel on a vessel with a [[thruster]] layout (azimuths and tunnels, no rudders): the
// 80 m supply vessel's joystick programme (surge and sway steps, yaw-moment steps at rest, the
// yaw-moment zig-zag) gives the hull of osv-80m.toml back, and the held-out zig-zag re-simulates
// within 5 %.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "../source_dir.hpp"
#include "dynpos/analysis/capability.hpp"
#include "dynpos/analysis/vessel_id.hpp"
#include "dynpos/core/parallel_for.hpp"
#include "dynpos/scenario/run_files.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos {
namespace {

const std::filesystem::path kSource = DYNPOS_SOURCE_DIR;
const std::filesystem::path kVessel = kSource / "data" / "vessels" / "osv-80m.toml";

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

  int determined = 0;
  for (const analysis::VesselParameter& p : report.parameters) {
    if (!p.fitted) continue;
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

  // The identified file keeps its layout and runs in simulate and capability as written.
  const std::filesystem::path out = dir / "identified.toml";
  analysis::write_outputs(report, out, {});
  const scenario::VesselConfig identified = scenario::load_vessel_config(out);
  EXPECT_EQ(identified.thrusters.size(), vessel.thrusters.size());
  scenario::ScenarioSpec spec =
      scenario::load_scenario(kSource / "data" / "scenarios" / "pure-dp.toml");
  spec.set_duration(20.0);
  EXPECT_NO_THROW(scenario::run_scenario(spec, identified, 1));
  analysis::CapabilityRequest cap;
  cap.vessel = out;
  cap.failure = "none";
  cap.direction_step = 30.0;
  EXPECT_NO_THROW(analysis::run_capability(cap));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace dynpos
