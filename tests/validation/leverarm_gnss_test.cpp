// GNSS lever arms (thesis 4.2) against the virtual sea trial's turning circle: antennas at the
// arms of table 4.1 (truth.json "lever_arms"), RTK noise of the vessel file (1 cm horizontal,
// 2 cm vertical, white, 1 Hz), and a known GNSS latency of 0.2 s.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "../source_dir.hpp"
#include "dynpos/calib/gnss_lever_arm.hpp"
#include "dynpos/core/rotation.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/vessel_config.hpp"
#include "dynpos/sensors/gnss_receiver.hpp"

namespace dynpos {
namespace {

const std::filesystem::path kSource = DYNPOS_SOURCE_DIR;

scenario::ScenarioRun turning_circle(double gnss1_latency_s, std::uint64_t seed,
                                     bool gnss_noise = true) {
  const scenario::ScenarioSpec spec =
      scenario::load_scenario(kSource / "data" / "scenarios" / "turning-circle.toml");
  scenario::VesselConfig vessel =
      scenario::load_vessel_config(kSource / "data" / "vessels" / "gunnerus.toml");
  for (sensors::GnssParams& g : vessel.sensors.gnss) {
    if (g.name == "gnss1") g.timing.time_offset_s = gnss1_latency_s;
    if (!gnss_noise) {
      g.horizontal_std_m = 0.0;
      g.vertical_std_m = 0.0;
      g.bias_std_m = 0.0;
    }
  }
  return scenario::run_scenario(spec, vessel, seed);
}

// The motion is the reference (truth) log at 100 Hz, the fixes are the logger's noisy GNSS
// channels: the bounds below are on what the GNSS noise leaves (the motion sensors' own errors
// are another matter, see the CLI test on the logged motion).
struct Inputs {
  calib::MotionFromLog motion;
  std::vector<calib::GnssSeries> gnss;
};

Inputs inputs(const scenario::ScenarioRun& run, const std::vector<std::string>& antennas) {
  Inputs in;
  in.motion = calib::motion_from_mixed_log(run.truth_log);
  std::vector<calib::GnssSource> sources;
  for (const std::string& a : antennas) sources.push_back({&run.log, a, "log"});
  in.gnss = calib::gnss_from_logs(sources);
  return in;
}

Eigen::Vector3d true_arm(const scenario::ScenarioRun& run, const std::string& name) {
  return run.truth.lever_arms.at(name);
}

// Full turning circle (400 s, one and a bit turns, Hs 1 m), three antennas, default estimator
// (least squares, lag 10 epochs). Its own 1σ is 0.6–0.8 mm in x, y and 9 mm in z. Measured
// errors on seed 3: 0–2 mm in x and y, 16–18 mm in z, the same for the three antennas (their z
// arms are seen only through the small roll and pitch of the turn); seeds 1–6 give 1–18 mm in
// z. The target of 2 cm per axis is 2.2σ of z.
TEST(LeverarmGnss, TurningCircleDefaultEstimatorWithin2cm) {
  const scenario::ScenarioRun run = turning_circle(0.0, 3);
  const std::vector<std::string> names = {"gnss1", "gnss2", "gnss3"};
  const Inputs in = inputs(run, names);
  const calib::GnssArmResult r = calib::estimate_gnss_arms(in.motion.motion, in.gnss);
  ASSERT_EQ(r.status, core::Status::kOk) << r.message;
  EXPECT_EQ(r.method, calib::GnssArmMethod::kLsq);
  ASSERT_EQ(r.arms.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    const Eigen::Vector3d truth = true_arm(run, names[k]);
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(r.arms[k].l_b_m(j), truth(j), 0.02) << names[k] << " axis " << j;
      // The estimator's 1σ must be honest: the error within 4σ (plus 1 mm for rounding).
      EXPECT_LT(std::abs(r.arms[k].l_b_m(j) - truth(j)), 4.0 * r.arms[k].std_m(j) + 1e-3)
          << names[k] << " axis " << j;
    }
  }
  // The residual is the fix noise: 1 cm horizontal, 2 cm vertical (±30 %).
  EXPECT_NEAR(r.residual_rms_n_m(0), 0.01, 0.003);
  EXPECT_NEAR(r.residual_rms_n_m(1), 0.01, 0.003);
  EXPECT_NEAR(r.residual_rms_n_m(2), 0.02, 0.006);
}

// gnss1 delayed by 0.2 s (20 log periods) in the vessel file; the estimator scans ±1 s. The
// curvature of the residual gives a 1σ of about 1.5 ms here; the tolerance is one log period
// (10 ms, the resolution of the simulated latency and of the motion). Without the offset the
// arm is off by decimetres (a 13.9 m mast rolling at a few deg/s moves the antenna ~0.1 m in
// 0.2 s), so the test can fail; with it, the arm is back within 2 cm per axis (single antenna:
// 1σ about 1 mm in x, y, 16 mm in z).
TEST(LeverarmGnss, TurningCircleFindsGnssTimeOffset) {
  const scenario::ScenarioRun run = turning_circle(0.2, 5);
  const Inputs in = inputs(run, {"gnss1"});
  const Eigen::Vector3d truth = true_arm(run, "gnss1");

  calib::GnssArmOptions o;
  o.estimate_time_offset = true;
  const calib::GnssArmResult r = calib::estimate_gnss_arms(in.motion.motion, in.gnss, o);
  ASSERT_EQ(r.status, core::Status::kOk) << r.message;
  EXPECT_TRUE(r.time_offset_estimated);
  EXPECT_NEAR(r.time_offset_s, 0.2, 0.01);
  EXPECT_LT(r.time_offset_std_s, 0.01);
  ASSERT_EQ(r.arms.size(), 1u);
  for (int j = 0; j < 3; ++j) EXPECT_NEAR(r.arms[0].l_b_m(j), truth(j), 0.02) << "axis " << j;

  const calib::GnssArmResult ignored = calib::estimate_gnss_arms(in.motion.motion, in.gnss);
  ASSERT_EQ(ignored.status, core::Status::kOk) << ignored.message;
  EXPECT_GT((ignored.arms[0].l_b_m - truth).cwiseAbs().maxCoeff(), 0.05)
      << "a 0.2 s latency should spoil the arm when ignored";
  EXPECT_GT(ignored.residual_rms_n_m.head<2>().norm(), r.residual_rms_n_m.head<2>().norm());
}

// Per axis, the worst absolute error over the antennas.
Eigen::Vector3d worst_error(const calib::GnssArmResult& r,
                            const std::vector<Eigen::Vector3d>& truth) {
  Eigen::Vector3d e = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < truth.size(); ++k)
    e = e.cwiseMax((r.arms[k].l_b_m - truth[k]).cwiseAbs());
  return e;
}

// The start of the thesis' case study 1: arms 0.6, 0.4, 0.6 m off (the thesis started
// 0.5–1 m off) and P̂₀ at P₀ = P₁ − R·l₁ (4.2) of the first fix, as the thesis did.
calib::GnssArmOptions thesis_start(const Inputs& in, const std::vector<Eigen::Vector3d>& truth) {
  calib::GnssArmOptions o;
  for (const Eigen::Vector3d& l : truth)
    o.initial_arms_b_m.push_back(l + Eigen::Vector3d(-0.6, 0.4, 0.6));
  const auto& m = in.motion.motion;
  const double t0 = in.gnss[0].t_s.front();
  std::size_t i = 0;
  while (i + 1 < m.t_s.size() && m.t_s[i] < t0) ++i;
  const Eigen::Vector3d th = m.theta_rad[i];
  o.initial_p0_n_m = in.gnss[0].p_n_m.front() - core::R_nb_zyx(th(0), th(1), th(2)) * truth[0];
  return o;
}

// A turning circle with three antennas and their true arms.
struct ArmCase {
  scenario::ScenarioRun run;
  Inputs in;
  std::vector<Eigen::Vector3d> truth;
};

ArmCase three_antennas(bool gnss_noise) {
  ArmCase c{turning_circle(0.0, 3, gnss_noise), {}, {}};
  const std::vector<std::string> names = {"gnss1", "gnss2", "gnss3"};
  c.in = inputs(c.run, names);
  for (const std::string& n : names) c.truth.push_back(true_arm(c.run, n));
  return c;
}

// Per axis, the worst error of `method` started as `o`; infinite if the estimator failed.
Eigen::Vector3d error_of(const ArmCase& c, calib::GnssArmOptions o, calib::GnssArmMethod method) {
  o.method = method;
  const calib::GnssArmResult r = calib::estimate_gnss_arms(c.in.motion.motion, c.in.gnss, o);
  EXPECT_EQ(r.status, core::Status::kOk) << r.message;
  if (r.status != core::Status::kOk)
    return Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  return worst_error(r, c.truth);
}

// The thesis' case study 1 on our turning circle: noise-free fixes (which fall on motion
// samples, so P₀ from the first fix is exact), started as thesis_start(). Thesis table 4.2 reached
// ≈ 0.2 mm (Luenberger), table 4.3 ≈ 1 cm (adaptive): those are the bounds. Measured (seed 3):
// Luenberger 0.06 mm, adaptive 0.06 mm, least squares 0.01 mm. With the earlier gains (W₁ = 0.005,
// W₂ = 0.02; Γ = 10) the observers were off by 0.1–0.7 m on this maneuver, so the bounds can fail.
TEST(LeverarmGnss, TurningCircleNoiseFreeAllEstimatorsMatchTheThesis) {
  const ArmCase c = three_antennas(false);
  const calib::GnssArmOptions o = thesis_start(c.in, c.truth);
  const Eigen::Vector3d luen = error_of(c, o, calib::GnssArmMethod::kLuenberger);
  EXPECT_LT(luen.maxCoeff(), 2e-4) << luen.transpose();
  const Eigen::Vector3d adap = error_of(c, o, calib::GnssArmMethod::kAdaptive);
  EXPECT_LT(adap.maxCoeff(), 0.01) << adap.transpose();
  const Eigen::Vector3d lsq = error_of(c, o, calib::GnssArmMethod::kLsq);
  EXPECT_LT(lsq.maxCoeff(), 2e-4) << lsq.transpose();
}

// The observers on RTK noise (1 cm horizontal, 2 cm vertical), same start as above (P₀ from the
// first fix, which now carries 1–2 cm of noise that the observer removes). They follow the fix
// noise through their gains, so they are less precise than the least squares (2.6 mm): measured
// on seed 3, Luenberger 10 mm, adaptive 66 mm (mean over the second half). Bounds: Luenberger
// 2 cm (the target for the best estimator), adaptive 10 cm (the thesis' adaptive
// observer kept 1–2 cm of standard deviation without noise).
TEST(LeverarmGnss, TurningCircleObserversOnRtkNoise) {
  const ArmCase c = three_antennas(true);
  const calib::GnssArmOptions o = thesis_start(c.in, c.truth);
  const Eigen::Vector3d luen = error_of(c, o, calib::GnssArmMethod::kLuenberger);
  EXPECT_LT(luen.maxCoeff(), 0.02) << luen.transpose();
  const Eigen::Vector3d adap = error_of(c, o, calib::GnssArmMethod::kAdaptive);
  EXPECT_LT(adap.maxCoeff(), 0.10) << adap.transpose();
}

}  // namespace
}  // namespace dynpos
