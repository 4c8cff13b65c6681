// Estimate GNSS antenna lever arms from vessel motion (thesis section 4.2), and check them
// against the truth of a virtual sea trial.
//
// The built-in turning circle (data/scenarios/turning-circle.toml, shortened to 150 s) runs on
// the virtual Gunnerus, whose three antennas sit at the arms of thesis table 4.1 and log RTK
// fixes at 1 Hz. Batch least squares recovers each arm from how the fixes move as the vessel
// turns and rolls. With real data the motion comes from the logged attitude, rates and speed
// (calib::motion_from_mixed_log of the log read from CSV, as `dynpos leverarm gnss` does).

#include <fmt/core.h>

#include <exception>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynpos/analysis/data_dir.hpp"
#include "dynpos/calib/gnss_lever_arm.hpp"
#include "dynpos/scenario/runner.hpp"

namespace {

void estimate() {
  using namespace dynpos;
  // The scenario and the vessel come with dynpos (share/dynpos, or $DYNPOS_DATA_DIR).
  const std::filesystem::path data = analysis::find_data_dir();
  scenario::ScenarioSpec spec = scenario::load_scenario(data / "scenarios" / "turning-circle.toml");
  spec.set_duration(150.0);  // the rudder goes over at 20 s: half a turn is rotation enough
  const scenario::VesselConfig vessel =
      scenario::load_vessel_config(data / "vessels" / "gunnerus.toml");
  const scenario::ScenarioRun run = scenario::run_scenario(spec, vessel, /*seed=*/1);

  // The motion: true attitude, angular rates and velocity at 100 Hz. The fixes: each antenna's
  // noisy latitude, longitude and height from the trial logger, in one local NED frame.
  const calib::MotionFromLog motion = calib::motion_from_mixed_log(run.truth_log);
  std::vector<calib::GnssSource> sources;
  for (const std::string& name : calib::gnss_prefixes(run.log)) {
    sources.push_back({&run.log, name, "log"});
  }
  const calib::GnssArmResult result =
      calib::estimate_gnss_arms(motion.motion, calib::gnss_from_logs(sources));
  if (result.status != core::Status::kOk) throw std::runtime_error(result.message);

  fmt::print("{:6} {:>26} {:>26} {:>9}  determined (x, y, z)\n", "", "estimated arm x, y, z [m]",
             "true arm [m]", "error");
  for (const calib::ArmEstimate& arm : result.arms) {
    const Eigen::Vector3d& l_true = run.truth.lever_arms.at(arm.name);
    fmt::print(
        "{:6} {:8.3f} {:8.3f} {:8.3f}   {:8.3f} {:8.3f} {:8.3f} {:6.1f} mm  {}, {}, {}\n", arm.name,
        arm.l_b_m.x(), arm.l_b_m.y(), arm.l_b_m.z(), l_true.x(), l_true.y(), l_true.z(),
        1e3 * (arm.l_b_m - l_true).norm(), calib::determinacy_name(arm.determinacy[0]),
        calib::determinacy_name(arm.determinacy[1]), calib::determinacy_name(arm.determinacy[2]));
  }
}

}  // namespace

int main() {
  try {
    estimate();
    return 0;
  } catch (const std::exception& e) {
    fmt::print(stderr, "gnss_lever_arms: {}\n", e.what());
    return 1;
  }
}
