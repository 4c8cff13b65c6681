// The trial logger of a run: every sensor against the truth of the same run.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>

#include "dynpos/core/angle.hpp"
#include "dynpos/core/local_ned_frame.hpp"
#include "dynpos/core/rotation.hpp"
#include "dynpos/io/csv_reader.hpp"
#include "dynpos/io/csv_writer.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/sensors/mru.hpp"

namespace dynpos::scenario {
namespace {

// Calm forces (no gusts or bias, so accelerations are smooth between ticks) but waves and a
// turn, so the hull rolls, pitches, heaves and yaws.
VesselConfig vessel(bool noise) {
  VesselConfig v;
  v.bias.std.setZero();
  v.current.speed_std_mps = v.current.dir_std_rad = 0.0;
  v.wind.gust_std_fraction = v.wind.dir_std_rad = 0.0;
  if (!noise) {
    for (sensors::GnssParams& g : v.sensors.gnss) g.horizontal_std_m = g.vertical_std_m = 0.0;
    for (sensors::MruParams& m : v.sensors.mru) {
      m.angle_std_rad = m.rate_std_rad_s = m.accel_std_mps2 = 0.0;
    }
  }
  return v;
}

ScenarioSpec turning_in_waves(double duration, double log_rate_hz) {
  ScenarioSpec s;
  s.name = "test-turn";
  s.duration_s = duration;
  s.log_rate_hz = log_rate_hz;
  s.initial_surge_mps = 3.0;
  s.rudder = {{5.0, 20.0, false}};
  s.environment.hs_m = 2.0;
  s.environment.tp_s = 7.0;
  s.environment.wave_from_deg = 30.0;
  return s;
}

struct Pose {
  Eigen::Vector3d p_n;
  Eigen::Matrix3d R_nb;
};

Pose truth_pose(const core::Log& truth, std::size_t i) {
  const auto v = [&](const char* name) { return truth.values(name)[i]; };
  return {{v("north"), v("east"), v("down")}, core::R_nb_zyx(v("roll"), v("pitch"), v("heading"))};
}

Eigen::Vector3d arm(const VesselConfig& v, const std::string& name) {
  for (const auto& g : v.sensors.gnss) {
    if (g.name == name) return g.lever_arm_b;
  }
  for (const auto& m : v.sensors.mru) {
    if (m.name == name) return m.lever_arm_b;
  }
  ADD_FAILURE() << "no sensor " << name;
  return Eigen::Vector3d::Zero();
}

TEST(SensorLog, NoiseFreeGnssReportsTheAntennaPositionGeodeticAndLocal) {
  const VesselConfig v = vessel(false);
  const ScenarioRun run = run_scenario(turning_in_waves(60.0, 10.0), v, 3);
  const core::LocalNedFrame frame(
      {v.sensors.origin.lat_deg, v.sensors.origin.lon_deg, v.sensors.origin.height_m});
  std::size_t fixes = 0;
  for (const char* name : {"gnss1", "gnss2", "gnss3"}) {
    const std::string n(name);
    const auto& lat = run.log.values(n + ".lat");
    for (std::size_t i = 0; i < run.log.size(); ++i) {
      if (core::is_missing(lat[i])) continue;
      ++fixes;
      const Pose pose = truth_pose(run.truth_log, i);
      const Eigen::Vector3d expected = pose.p_n + pose.R_nb * arm(v, n);
      const Eigen::Vector3d local(run.log.values(n + ".north")[i], run.log.values(n + ".east")[i],
                                  run.log.values(n + ".down")[i]);
      // Same doubles through the same formula (4.2): agreement to rounding.
      EXPECT_LT((local - expected).norm(), 1e-9) << n << " t = " << run.log.time()[i];
      const Eigen::Vector3d back =
          frame.to_ned({lat[i], run.log.values(n + ".lon")[i], run.log.values(n + ".height")[i]});
      // Geodetic round trip through GeographicLib: nanometres at 100 m from the origin.
      EXPECT_LT((back - expected).norm(), 1e-6) << n;
    }
  }
  EXPECT_EQ(fixes, 3u * 61u);  // 1 Hz in a 10 Hz log, t = 0 … 60 s
}

TEST(SensorLog, NoiseFreeMruAccelerationIsTheSecondDerivativeOfItsPosition) {
  // (4.65) checked along the simulated path: the MRU's kinematic acceleration equals the
  // second time difference of its position P₀ + R(Θ)l from the truth log, rotated to BODY.
  const VesselConfig v = vessel(false);
  const double rate = 100.0, h = 1.0 / rate;
  const ScenarioRun run = run_scenario(turning_in_waves(40.0, rate), v, 4);
  for (const char* name : {"mru1", "mru2"}) {
    const std::string n(name);
    const Eigen::Vector3d l = arm(v, n);
    double worst = 0.0, scale = 0.0;
    for (std::size_t i = 1; i + 1 < run.log.size(); ++i) {
      const auto point = [&](std::size_t k) {
        const Pose p = truth_pose(run.truth_log, k);
        return Eigen::Vector3d(p.p_n + p.R_nb * l);
      };
      const Eigen::Vector3d a_fd_n = (point(i + 1) - 2.0 * point(i) + point(i - 1)) / (h * h);
      const Eigen::Vector3d a_fd_b = truth_pose(run.truth_log, i).R_nb.transpose() * a_fd_n;
      const Eigen::Vector3d a_b(run.log.values(n + ".ax")[i], run.log.values(n + ".ay")[i],
                                run.log.values(n + ".az")[i]);
      worst = std::max(worst, (a_b - a_fd_b).norm());
      scale = std::max(scale, a_b.norm());
    }
    // Second differences at h = 0.01 s: truncation h²/12·|p⁗| with wave frequencies ≤ 3 rad/s
    // and accelerations ≤ 2 m/s² gives ≤ 1e-5·9·2 ≈ 2e-4 m/s²; round-off 1e-16·100 m/h² ≈ 1e-10.
    // The thruster and rudder states make ν̇ only piecewise smooth at control ticks: small.
    EXPECT_GT(scale, 0.1) << n << ": the test needs motion";
    EXPECT_LT(worst, 5e-4) << n << " (largest acceleration " << scale << " m/s²)";
  }
}

TEST(SensorLog, LatencyDelaysTheSamplesByTheOffset) {
  VesselConfig v = vessel(false);
  v.sensors.gnss[0].timing.time_offset_s = 0.2;
  const ScenarioRun run = run_scenario(turning_in_waves(30.0, 10.0), v, 5);
  const auto& north = run.log.values("gnss1.north");
  std::size_t checked = 0;
  for (std::size_t i = 2; i < run.log.size(); ++i) {
    if (core::is_missing(north[i])) continue;
    const Pose earlier = truth_pose(run.truth_log, i - 2);  // 0.2 s = 2 log periods
    const Eigen::Vector3d expected = earlier.p_n + earlier.R_nb * arm(v, "gnss1");
    EXPECT_NEAR(north[i], expected.x(), 1e-9) << "t = " << run.log.time()[i];
    ++checked;
  }
  EXPECT_EQ(checked, 30u);
}

TEST(SensorLog, EachSensorAtItsRate) {
  const ScenarioRun run = run_scenario(turning_in_waves(10.0, 100.0), VesselConfig{}, 6);
  const auto count = [&](const char* name) {
    std::size_t n = 0;
    for (double x : run.log.values(name)) n += core::is_missing(x) ? 0 : 1;
    return n;
  };
  EXPECT_EQ(run.log.size(), 1001u);
  EXPECT_EQ(count("gnss1.lat"), 11u);   // 1 Hz
  EXPECT_EQ(count("mru2.ax"), 1001u);   // 100 Hz
  EXPECT_EQ(count("heading"), 101u);    // gyro 10 Hz
  EXPECT_EQ(count("u"), 11u);           // speed log 1 Hz
  EXPECT_EQ(count("rpm.port"), 1001u);  // main propellers at the logger rate
  EXPECT_EQ(count("rpm.tunnel"), 11u);  // tunnel 1 Hz, as on Gunnerus
  EXPECT_EQ(count("wind_speed"), 11u);
  EXPECT_EQ(count("command.surge"), 1001u);
}

TEST(SensorLog, NoiseLevelsAreThoseOfTheVesselFile) {
  const VesselConfig v = vessel(true);
  const ScenarioRun run = run_scenario(turning_in_waves(600.0, 10.0), v, 7);
  double sum2_h = 0, sum2_v = 0;
  std::size_t n = 0;
  const auto& north = run.log.values("gnss2.north");
  for (std::size_t i = 0; i < run.log.size(); ++i) {
    if (core::is_missing(north[i])) continue;
    const Pose pose = truth_pose(run.truth_log, i);
    const Eigen::Vector3d err = Eigen::Vector3d(north[i], run.log.values("gnss2.east")[i],
                                                run.log.values("gnss2.down")[i]) -
                                (pose.p_n + pose.R_nb * arm(v, "gnss2"));
    sum2_h += err.x() * err.x() + err.y() * err.y();
    sum2_v += err.z() * err.z();
    ++n;
  }
  ASSERT_EQ(n, 601u);
  // Sample std from 2·601 (horizontal) and 601 (vertical) draws: relative std ≤ 3 %; 15 % is
  // 5σ.
  EXPECT_NEAR(std::sqrt(sum2_h / (2.0 * n)), v.sensors.gnss[1].horizontal_std_m, 0.15 * 0.01);
  EXPECT_NEAR(std::sqrt(sum2_v / n), v.sensors.gnss[1].vertical_std_m, 0.15 * 0.02);
}

TEST(SensorLog, SpecificForceConventionSensesGravity) {
  VesselConfig v = vessel(false);
  v.sensors.mru_acceleration = sensors::AccelerationConvention::kSpecificForce;
  const ScenarioRun run = run_scenario(turning_in_waves(60.0, 10.0), v, 8);
  double mean_az = 0;
  for (double az : run.log.values("mru1.az")) mean_az += az;
  mean_az /= static_cast<double>(run.log.size());
  // Heave accelerations average out over 60 s to ≪ 0.1 m/s²; roll/pitch of a few degrees
  // change cos φ cos θ by < 0.5 %.
  EXPECT_NEAR(mean_az, -sensors::kGravity_mps2, 0.1);
  EXPECT_EQ(run.truth.mru_acceleration, sensors::AccelerationConvention::kSpecificForce);
}

TEST(SensorLog, TrialLogReadsBackInSiWithBlanksAsMissing) {
  const ScenarioRun run = run_scenario(turning_in_waves(5.0, 10.0), VesselConfig{}, 9);
  const auto file = std::filesystem::temp_directory_path() / "dynpos_sensor_log_test.csv";
  io::write_csv(file, run.log);
  const core::Log back = io::read_csv_all(file);
  std::filesystem::remove(file);
  ASSERT_EQ(back.size(), run.log.size());
  // Logger units convert to SI on reading: deg → rad, rpm → rps, kW → W, kN → N, % → 1.
  const std::pair<const char*, double> to_si[] = {{"heading", core::deg_to_rad(1.0)},
                                                  {"mru1.p", core::deg_to_rad(1.0)},
                                                  {"rpm.port", 1.0 / 60.0},
                                                  {"power.stb", 1e3},
                                                  {"thrust.port", 1e3},
                                                  {"command.rpm.port", 1.0 / 60.0},
                                                  {"command.surge", 0.01},
                                                  {"gnss1.north", 1.0}};
  for (const auto& [name, factor] : to_si) {
    const auto& logged = run.log.values(name);
    const auto& read = back.values(name);
    for (std::size_t i = 0; i < logged.size(); ++i) {
      if (core::is_missing(logged[i])) {
        EXPECT_TRUE(core::is_missing(read[i])) << name << " row " << i;
      } else {
        // Shortest round-trip text, then one multiplication: 1 ulp-level error.
        EXPECT_NEAR(read[i], logged[i] * factor, 1e-14 * std::abs(logged[i] * factor) + 1e-300)
            << name << " row " << i;
      }
    }
  }
}

}  // namespace
}  // namespace dynpos::scenario
