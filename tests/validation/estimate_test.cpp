// The DP observer run over a log (`dynpos estimate`) on the virtual pure DP trial, checked
// against the true environmental load of truth.csv.
//
// The observer is given what the log shows: the GNSS antenna's fixes at 1 Hz moved to the control
// origin, the gyro, and each unit's thrust from its measured shaft speed at rest (bollard) with
// the rudders' force at rest in the water (scenario/thrust_feedback.hpp). What the thrusters
// really give differs from that by what the log cannot show: the rudders' lift from the water's
// flow across them (the current, the vessel's own turning) and the propellers' thrust loss at
// the current's inflow. b̂ takes that difference in with the environment's load, so besides
// truth.csv's env_load (the load on the hull, wind, waves and current, with the bias (2.22) and
// step loads) the test builds the load the log can show: env_load + R(ψ)(τ_true − τ_log), with
// τ_true the simulator's actuator force from the true thrust, rudder angles and the
// low-frequency motion through the current (as scenario/vessel_plant.cpp makes it), and τ_log the
// feedback's force from the true shaft speeds and angles.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "../source_dir.hpp"
#include "dynpos/analysis/estimate.hpp"
#include "dynpos/core/angle.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/io/csv_reader.hpp"
#include "dynpos/model/rudder.hpp"
#include "dynpos/model/thruster.hpp"
#include "dynpos/model/tunnel_thruster.hpp"
#include "dynpos/scenario/run_files.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/thrust_feedback.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos {
namespace {

const std::filesystem::path kSource = DYNPOS_SOURCE_DIR;
constexpr double kFrom_s = 300.0, kTo_s = 900.0;  // the last 600 s of the run

scenario::VesselConfig vessel() {
  return scenario::load_vessel_config(kSource / "data" / "vessels" / "gunnerus.toml");
}

scenario::ScenarioSpec pure_dp() {
  scenario::ScenarioSpec spec =
      scenario::load_scenario(kSource / "data" / "scenarios" / "pure-dp.toml");
  spec.set_duration(kTo_s);                     // heading 0 until 430 s, 90 until 860 s, then 45
  spec.observer = control::ObserverKind::kEkf;  // the truth's env_load columns
  spec.device_files.reset();
  return spec;
}

// The pure DP run's files (seed 1), written once for every test.
const std::filesystem::path& run_dir() {
  static const std::filesystem::path dir = [] {
    const auto d = std::filesystem::temp_directory_path() / "dynpos_estimate_validation_pure_dp";
    scenario::write_scenario_run(scenario::run_scenario(pure_dp(), vessel(), 1), d);
    return d;
  }();
  return dir;
}

core::Log read_truth() { return io::read_csv_all(run_dir() / "truth.csv"); }

// The request on the log in `dir`: the DP antenna's fixes moved by its arm, mru1's attitude.
analysis::EstimateRequest request(const std::filesystem::path& dir, const std::string& observer) {
  analysis::EstimateRequest q;
  q.source.log = dir / "log.csv";
  q.source.columns = {"north=gnss1.north", "east=gnss1.east", "roll=mru1.roll", "pitch=mru1.pitch"};
  q.arm_m = vessel().sensors.gnss.front().lever_arm_b;
  q.observer = observer;
  q.tp_s = pure_dp().environment.tp_s;  // the operator enters the sea's T_p
  return q;
}

analysis::EstimateReport estimate(const std::string& observer) {
  return analysis::run_estimate(request(run_dir(), observer));
}

Eigen::Matrix3d rotation(double psi) {
  Eigen::Matrix3d R;
  R << std::cos(psi), -std::sin(psi), 0.0, std::sin(psi), std::cos(psi), 0.0, 0.0, 0.0, 1.0;
  return R;
}

// τ_true − τ_log (BODY) at truth row i (see the file comment); ν the low-frequency velocity.
Eigen::Vector3d unlogged_thrust_b(const scenario::VesselConfig& v, const core::Log& t,
                                  std::size_t i, const Eigen::Vector3d& nu_b) {
  const auto at = [&](const char* c) { return t.values(c)[i]; };
  const double psi = at("lf.heading");
  const Eigen::Vector3d current_b =
      rotation(psi).transpose() * Eigen::Vector3d(at("current.north"), at("current.east"), 0.0);
  const Eigen::Vector3d nu_r = nu_b - current_b;
  const model::Rudder rudder(v.rudder);
  const model::ThrustConfiguration layout(v.layout);
  model::ActuatorForces f;
  f.thrust_port = at("thrust.port");
  f.thrust_stb = at("thrust.stb");
  f.tunnel = at("thrust.tunnel");
  const Eigen::Vector2d vp =
      model::ThrustConfiguration::velocity_at(nu_r, layout.params().p_port_rudder_b);
  const Eigen::Vector2d vs =
      model::ThrustConfiguration::velocity_at(nu_r, layout.params().p_stb_rudder_b);
  f.rudder_port_b = rudder.force(at("rudder.port"), {vp.x(), vp.y(), f.thrust_port}).f_b;
  f.rudder_stb_b = rudder.force(at("rudder.stb"), {vs.x(), vs.y(), f.thrust_stb}).f_b;
  const model::Thruster propeller(v.propeller);
  const model::TunnelThruster tunnel(v.tunnel);
  const std::vector<double> bollard{propeller.thrust(at("rpm.port")),
                                    propeller.thrust(at("rpm.stb")),
                                    tunnel.outputs(at("rpm.tunnel"), 0.0).thrust};
  const std::vector<double> angles{at("rudder.port"), at("rudder.stb"), 0.0};
  return layout.tau(f) - scenario::ThrustFeedback(v).tau_b(bollard, angles);
}

struct Means {
  Eigen::Vector3d env_load_n = Eigen::Vector3d::Zero();    // truth.csv's
  Eigen::Vector3d observable_n = Eigen::Vector3d::Zero();  // what the log can show
};

// The means over [from_s, to_s] of the true load and of the load the log can show, the
// low-frequency velocity by central differences of lf.* (10 Hz).
Means truth_means(double from_s, double to_s) {
  const scenario::VesselConfig v = vessel();
  const core::Log t = read_truth();
  const auto& time = t.time();
  const auto& n = t.values("lf.north");
  const auto& e = t.values("lf.east");
  const auto& h = t.values("lf.heading");
  Means m;
  int count = 0;
  for (std::size_t i = 1; i + 1 < t.size(); ++i) {
    if (time[i] < from_s || time[i] > to_s) continue;
    const double dt = time[i + 1] - time[i - 1];
    const Eigen::Vector3d eta_dot((n[i + 1] - n[i - 1]) / dt, (e[i + 1] - e[i - 1]) / dt,
                                  core::angle_diff(h[i + 1], h[i - 1]) / dt);
    const Eigen::Matrix3d R = rotation(h[i]);
    const Eigen::Vector3d nu_b = R.transpose() * eta_dot;
    const Eigen::Vector3d env(t.values("env_load.north")[i], t.values("env_load.east")[i],
                              t.values("env_load.yaw")[i]);
    m.env_load_n += env;
    m.observable_n += env + R * unlogged_thrust_b(v, t, i, nu_b);
    ++count;
  }
  m.env_load_n /= count;
  m.observable_n /= count;
  return m;
}

// The error of `mean_n` against `reference_n`, per component relative to the true load's
// magnitude `scale_n`: its horizontal magnitude (N, E; observer_truth.hpp's convention) and its
// |yaw| [-].
Eigen::Vector3d relative_error(const Eigen::Vector3d& mean_n, const Eigen::Vector3d& reference_n,
                               const Eigen::Vector3d& scale_n) {
  const double horizontal = scale_n.head<2>().norm();
  const Eigen::Vector3d d = mean_n - reference_n;
  return {d.x() / horizontal, d.y() / horizontal, d.z() / std::abs(scale_n.z())};
}

// The mean of b̂ over the track's samples in [from_s, to_s].
Eigen::Vector3d mean_bias(const control::ObserverTrack& track, double from_s, double to_s) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int n = 0;
  for (std::size_t k = 0; k < track.t_s.size(); ++k) {
    if (track.t_s[k] < from_s || track.t_s[k] > to_s) continue;
    sum += track.estimate[k].bias_n;
    ++n;
  }
  return sum / n;
}

void print(const char* what, const Eigen::Vector3d& v_n) {
  std::printf("  %-32s %7.2f kN %7.2f kN %7.2f kN·m\n", what, v_n.x() / 1e3, v_n.y() / 1e3,
              v_n.z() / 1e3);
}

// Over the last 600 s (heading 0, turning to 90 at 430 s and to 45 at 860 s) b̂'s mean is the
// true load's in north and east. Its yaw is not: at heading 90 the current crosses the hull and
// the rudders' lift from that flow (about 12 kN·m, with the propellers' slipstream) is in the
// simulator's actuator force, not in env_load, nor in the log. Against the load the log shows
// b̂'s yaw mean holds; and where the current runs along the hull (heading 0, after the observer
// has settled) against env_load itself.
TEST(EstimateValidation, TheBiasMeanIsTheLoadOnThePureDpRun) {
  const Means last = truth_means(kFrom_s, kTo_s);
  const Means ahead = truth_means(130.0, 430.0);
  for (const std::string observer : {"ekf", "passive"}) {
    const analysis::EstimateReport r = estimate(observer);
    const Eigen::Vector3d b = mean_bias(r.track, kFrom_s, kTo_s);
    const Eigen::Vector3d to_env = relative_error(b, last.env_load_n, last.env_load_n);
    const Eigen::Vector3d to_log = relative_error(b, last.observable_n, last.env_load_n);
    const Eigen::Vector3d b_ahead = mean_bias(r.track, 130.0, 430.0);
    const Eigen::Vector3d ahead_to_env =
        relative_error(b_ahead, ahead.env_load_n, ahead.env_load_n);
    std::printf("%s, %g–%g s:\n", observer.c_str(), kFrom_s, kTo_s);
    print("b̂ mean", b);
    print("env_load mean", last.env_load_n);
    print("the load the log shows", last.observable_n);
    std::printf(
        "  error to env_load %.1f %.1f %.1f %%, to the load the log shows %.1f %.1f %.1f %%; "
        "heading 0 (130–430 s) to env_load %.1f %.1f %.1f %%\n",
        100 * to_env.x(), 100 * to_env.y(), 100 * to_env.z(), 100 * to_log.x(), 100 * to_log.y(),
        100 * to_log.z(), 100 * ahead_to_env.x(), 100 * ahead_to_env.y(), 100 * ahead_to_env.z());
    // Measured (ekf / passive): north and east to env_load −0.2 −1.2 / 0.6 −1.7 % (east to its
    // own magnitude −6.1 / −8.6 %); to the load the log shows 4.7 −1.3 / 5.5 −1.8 %, within
    // each heading hold 1 % (the rest is the observer's lag through the two turns: the
    // simulator's own EKF, on the true thrust, is 3.5 % off env_load in north here).
    EXPECT_LT(to_env.head<2>().cwiseAbs().maxCoeff(), 0.10) << observer;
    EXPECT_LT(to_log.head<2>().cwiseAbs().maxCoeff(), 0.10) << observer;
    // Yaw, in units of the true yaw load: to env_load −59.3 / −57.0 % (not asserted: see the test
    // comment), to the load the log shows −9.9 / −7.6 %, at heading 0 to env_load −4.5 / −10.4 %.
    EXPECT_LT(std::abs(to_log.z()), 0.15) << observer;
    EXPECT_LT(std::abs(ahead_to_env.z()), 0.15) << observer;
    EXPECT_LT(ahead_to_env.head<2>().cwiseAbs().maxCoeff(), 0.10) << observer;
  }
}

TEST(EstimateValidation, TheObserverCorrectsOnEachFixOrHoldsIt) {
  const analysis::EstimateReport ekf = estimate("ekf");
  EXPECT_EQ(ekf.track.coasting_steps, 9u * ekf.track.position_steps);  // GNSS 1 Hz, EKF 10 Hz
  const analysis::EstimateReport passive = estimate("passive");
  EXPECT_EQ(passive.track.coasting_steps, 0u);  // the fix held for 1 s < max_hold_s
  EXPECT_EQ(ekf.track.stale_thrust_steps, 0u);  // the tunnel's 1 Hz feedback held
}

// A GNSS dropout in the log (250–280 s of a 400 s pure DP run, seed 1): the observer over the log
// bridged on the logged MRU (the default --mru auto: mru1's 10 Hz samples, its lever arm and
// noise from the vessel file) against coasting on its model (--mru none). The LF position error
// at the last estimate before the fix returns, against truth.csv's lf.*: measured bridged
// 0.15 m (EKF) and 0.10 m (passive), coasting 0.91 m and 1.25 m. Bound 0.4 m, the DP loop's
// guard for its bridge (observer_test.cpp: 0.29–0.30 m worst of 20 seeds at 45° in H_s 2.5 m),
// and at most half the coast's error.
TEST(EstimateValidation, AGnssDropoutIsBridgedOnTheLoggedMru) {
  scenario::ScenarioSpec spec = pure_dp();
  spec.set_duration(400.0);
  spec.gnss_dropouts = {{250.0, 30.0}};
  const auto dir = std::filesystem::temp_directory_path() / "dynpos_estimate_validation_dropout";
  scenario::write_scenario_run(scenario::run_scenario(spec, vessel(), 1), dir);
  const core::Log truth = io::read_csv_all(dir / "truth.csv");
  const auto lf_error_m = [&](const analysis::EstimateReport& r) {
    // The last estimate before 280 s, against the truth row at its time.
    std::size_t k = 0;
    while (k + 1 < r.track.t_s.size() && r.track.t_s[k + 1] < 280.0 - 1e-9) ++k;
    const auto& tt = truth.time();
    const std::size_t j = static_cast<std::size_t>(
        std::lower_bound(tt.begin(), tt.end(), r.track.t_s[k] - 1e-6) - tt.begin());
    const Eigen::Vector3d& eta = r.track.estimate[k].eta_n;
    return std::hypot(eta.x() - truth.values("lf.north")[j], eta.y() - truth.values("lf.east")[j]);
  };
  for (const std::string observer : {"ekf", "passive"}) {
    analysis::EstimateRequest q = request(dir, observer);
    const analysis::EstimateReport bridged = analysis::run_estimate(q);
    q.mru = "none";
    const analysis::EstimateReport coasting = analysis::run_estimate(q);
    EXPECT_EQ(bridged.bridge_mru, "mru1");
    EXPECT_EQ(bridged.bridged_rows, 309u);  // 249.1 … 279.9 s: the gap is over the 5 s hold
    EXPECT_TRUE(coasting.bridge_mru.empty());
    const double e_bridged = lf_error_m(bridged), e_coasting = lf_error_m(coasting);
    EXPECT_LE(e_bridged, 0.4) << observer;
    EXPECT_LT(e_bridged, 0.5 * e_coasting) << observer;
    std::printf(
        "%s: LF position error at the end of a 30 s GNSS dropout in the log: bridged "
        "%.2f m, coasting %.2f m\n",
        observer.c_str(), e_bridged, e_coasting);
  }
}

// The bridge refuses readings the logged attitude does not fit: an MRU logging specific force
// with another channel mapped as its roll (here the heading, 45°) turns gravity off the down
// axis, and a bridge on it would drift by metres. An input error naming roll/pitch (exit 2).
TEST(EstimateValidation, TheBridgeRefusesAnAttitudeThatDoesNotFitTheReadings) {
  scenario::VesselConfig v = vessel();
  v.sensors.mru_acceleration = sensors::AccelerationConvention::kSpecificForce;
  scenario::ScenarioSpec spec = pure_dp();
  spec.set_duration(200.0);
  spec.initial_heading_deg = 45.0;
  spec.setpoints = {{0.0, 0.0, 0.0, 45.0, "hold"}};
  const auto dir = std::filesystem::temp_directory_path() / "dynpos_estimate_validation_sf";
  scenario::write_scenario_run(scenario::run_scenario(spec, v, 1), dir);
  analysis::EstimateRequest q = request(dir, "ekf");
  const analysis::EstimateReport ok = analysis::run_estimate(q);  // its own roll: bridged
  EXPECT_EQ(ok.bridge_mru, "mru1");
  q.source.columns = {"north=gnss1.north", "east=gnss1.east", "heading=heading", "roll=heading",
                      "pitch=mru1.pitch"};
  try {
    analysis::run_estimate(q);
    ADD_FAILURE() << "no error";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the attitude does not fit the readings"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace dynpos
