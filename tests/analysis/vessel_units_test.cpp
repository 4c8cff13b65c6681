// The units of identify vessel: the combination of estimates over logs, and the units' values
// from synthetic logs of a tunnel thruster, and of a layout's tunnel and azimuth, whose true
// dead time, time constant, thrust map and slew rate differ from the starting file's.

#include "vessel_units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "dynpos/model/tunnel_thruster.hpp"
#include "dynpos/model/unit_drive.hpp"

namespace dynpos::analysis::vessel_units {
namespace {

const VesselParameter& find(const UnitResult& r, const std::string& key) {
  for (const VesselParameter& p : r.parameters) {
    if (p.key == key) return p;
  }
  throw std::runtime_error("no " + key);
}

// The parameter `key` of r, expected determined, within 3σ and `rel` of `value`.
const VesselParameter& expect_determined(const UnitResult& r, const std::string& key, double value,
                                         double rel) {
  const VesselParameter& v = find(r, key);
  EXPECT_TRUE(v.determined) << key << ": " << v.note;
  EXPECT_LE(std::abs(v.value - value), 3.0 * v.sigma) << key << " " << v.value;
  EXPECT_LE(std::abs(v.value - value), rel * value) << key << " " << v.value;
  return v;
}

TEST(VesselUnitsCombine, InverseVarianceMeanWithItsSigma) {
  // Weights 1 and 1/4: (0·1 + 1·0.25)/1.25 = 0.2; σ = 1/√1.25. χ² = 0.2²/1 + 0.8²/4 = 0.2 < 1:
  // the scatter is within the σ, so σ is not widened.
  const auto c = combine({{0.0, 1.0, "a"}, {1.0, 2.0, "b"}});
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->value, 0.2, 1e-12);
  EXPECT_NEAR(c->sigma, 1.0 / std::sqrt(1.25), 1e-12);
  EXPECT_EQ(c->count, 2U);
  EXPECT_EQ(c->sources, (std::vector<std::string>{"a", "b"}));
}

TEST(VesselUnitsCombine, ScatterBeyondTheSigmaWidensIt) {
  // 1 ± 0.1 and 3 ± 0.1: mean 2, σ 0.1/√2, χ² = 200 over 1 degree of freedom: σ × √200 = 1,
  // the half-difference of the two.
  const auto c = combine({{1.0, 0.1, "a"}, {3.0, 0.1, "a"}});
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->value, 2.0, 1e-12);
  EXPECT_NEAR(c->sigma, 1.0, 1e-12);
  EXPECT_EQ(c->sources, (std::vector<std::string>{"a"}));
}

TEST(VesselUnitsCombine, EstimatesWithoutAFiniteSigmaAreLeftOut) {
  EXPECT_FALSE(combine({}));
  EXPECT_FALSE(combine({{1.0, 0.0, "a"}, {2.0, std::nan(""), "b"}}));
  const auto c = combine({{1.0, 0.0, "a"}, {5.0, 0.5, "b"}});
  ASSERT_TRUE(c);
  EXPECT_DOUBLE_EQ(c->value, 5.0);
  EXPECT_DOUBLE_EQ(c->sigma, 0.5);
}

// A 10 Hz log of the tunnel's order steps and the response of `truth`, with white shaft-speed
// noise of 0.5 rpm and the thrust of its map at the noisy speed (as the DP system computes it).
LogUnits tunnel_log(const model::TunnelThruster& truth, std::uint32_t seed) {
  const std::vector<double> levels{0.0, 0.5, 1.0, 0.2, -0.5, -1.2, -0.3, 0.0};  // [rps]
  constexpr double kPlateau = 40.0, kDt = 0.1;
  LogUnits log{"tunnel.csv", {}, {{"tunnel", {}, {}, {}, {}, {}}}};
  UnitColumns& u = log.units[0];
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.5 / 60.0);
  for (std::size_t k = 1; k < levels.size(); ++k) {
    const model::StepResponse r = model::tunnel_step_response(truth, levels[k - 1], levels[k]);
    for (double t = 0.0; t < kPlateau - 1e-9; t += kDt) {
      log.time_s.push_back(static_cast<double>(k - 1) * kPlateau + t);
      u.order_rps.push_back(levels[k]);
      const double n = r.at(t) + noise(rng);
      u.shaft_speed_rps.push_back(n);
      u.thrust_N.push_back(truth.thrust(n));
    }
  }
  return log;
}

TEST(VesselUnitsIdentify, TheTunnelsDeadTimeTimeConstantAndMapFromItsSteps) {
  scenario::VesselConfig start;  // the built-in Gunnerus: dead time 1 s, T_n 1 s
  model::TunnelThrusterParams p = start.tunnel;
  p.dead_time = 1.5;
  p.time_constant = 1.3;
  p.kt_starboard = 0.45;
  p.kt_port = 0.30;
  const model::TunnelThruster truth(p);
  const UnitResult r = identify_units(start, {tunnel_log(truth, 1), tunnel_log(truth, 2)}, 0.033);
  // 12 steps (the first level is the log's start) of 0.3-0.9 rps against noise of 0.008 rps.
  const std::pair<const char*, double> expected[] = {{"tunnel.dead_time_s", 1.5},
                                                     {"tunnel.time_constant_s", 1.3},
                                                     {"tunnel.kt_starboard", 0.45},
                                                     {"tunnel.kt_port", 0.30}};
  for (const auto& [key, value] : expected) {
    const VesselParameter& v = expect_determined(r, key, value, 0.03);
    EXPECT_NE(v.note.find("tunnel.csv"), std::string::npos) << v.note;
  }
  EXPECT_FALSE(find(r, "tunnel.rate_limit_rps_per_s").determined);
  ASSERT_EQ(r.units.size(), 3U);
  EXPECT_EQ(r.units[2].unit, "tunnel");
  EXPECT_EQ(r.units[2].steps, 12U);
  // The steps are first order: the fits' T and δ are the truth's.
  EXPECT_NEAR(r.units[2].time_constant_s, 1.3, 3.0 * r.units[2].time_constant_sigma_s);
  EXPECT_NEAR(r.units[2].model_dead_time_s, 1.0, 0.02);

  // Applied, the determined values are the vessel's.
  scenario::VesselConfig applied = start;
  apply(applied, r.parameters);
  EXPECT_DOUBLE_EQ(applied.tunnel.dead_time, find(r, "tunnel.dead_time_s").value);
  EXPECT_DOUBLE_EQ(applied.propeller.dead_time, start.propeller.dead_time);
}

TEST(VesselUnitsIdentify, AUnitTheLogsDoNotExciteIsNotDeterminedWithTheExcitationNeeded) {
  scenario::VesselConfig start;
  const model::TunnelThruster truth(start.tunnel);
  const UnitResult r = identify_units(start, {tunnel_log(truth, 3)}, 0.033);
  // No port or stb columns: the propellers' values are the start's, with what would determine
  // them.
  for (const char* key :
       {"propeller.dead_time_s", "propeller.kt_forward", "propeller.kt_reverse"}) {
    const VesselParameter& v = find(r, key);
    EXPECT_FALSE(v.determined) << key;
    EXPECT_FALSE(v.fitted) << key;
    EXPECT_EQ(v.value, v.start) << key;
    EXPECT_TRUE(std::isnan(v.sigma)) << key;
    EXPECT_NE(v.note.find("to determine it:"), std::string::npos) << v.note;
  }
  EXPECT_NE(find(r, "propeller.dead_time_s").note.find("steps of the main propellers"),
            std::string::npos);
  EXPECT_EQ(r.units[0].steps, 0U);
  EXPECT_TRUE(std::isnan(r.units[0].dead_time_s));

  // A σ over the bound: determined at 3.3 %, not at 0.01 % of the value.
  const UnitResult strict = identify_units(start, {tunnel_log(truth, 3)}, 1e-4);
  const VesselParameter& dead = find(strict, "tunnel.dead_time_s");
  EXPECT_FALSE(dead.determined);
  EXPECT_EQ(dead.value, start.tunnel.dead_time);
  EXPECT_NE(dead.note.find("is not determined"), std::string::npos) << dead.note;
  EXPECT_NE(dead.note.find("to determine it:"), std::string::npos) << dead.note;
}

TEST(VesselUnitsIdentify, AValueIsWrittenFinerThanItsSigma) {
  // A thrust map the DP system's own feedback gives to rounding: σ 4.4·10⁻¹³ of the value.
  VesselIdReport report;
  report.vessel_text = "[propeller]\nkt_forward = 0.5\ndead_time_s = 1.3\n";
  report.parameters.push_back(
      {"propeller.kt_forward", "1", 0.5, 0.49573170731707317, 2.2e-13, true, true, "maps"});
  report.parameters.push_back(
      {"propeller.dead_time_s", "s", 1.3, 1.2950512, 0.0039, true, true, "steps"});
  const std::string text = identified_vessel_text(report);
  const std::size_t kt = text.find("kt_forward = ");
  ASSERT_NE(kt, std::string::npos) << text;
  EXPECT_LE(std::abs(std::stod(text.substr(kt + 13)) - 0.49573170731707317), 0.1 * 2.2e-13) << text;
  // σ of 0.3 %: the usual 6 significant digits.
  EXPECT_NE(text.find("dead_time_s = 1.29505  # identified"), std::string::npos) << text;
}

// A 10 Hz log of a layout unit driven by `truth`: its shaft speed order steps through `levels`
// [rps] every 40 s and (an azimuth) its direction order between 0 and ±90° every 20 s, the
// drive integrated at 1 ms through its dead time; shaft speed noise 0.2 rpm, direction noise
// 0.1°.
LogUnits layout_log(const model::ThrusterUnit& truth, const std::vector<double>& levels,
                    std::uint32_t seed) {
  const model::UnitDrive drive(truth);
  constexpr double kDt = 0.001, kLogDt = 0.1;
  LogUnits log{"layout.csv", {}, {{truth.name, {}, {}, {}, {}, {}}}};
  UnitColumns& u = log.units[0];
  std::mt19937 rng(seed);
  std::normal_distribution<double> rpm_noise(0.0, 0.2 / 60.0), deg_noise(0.0, 0.1);
  const bool azimuth = truth.type == model::UnitType::kAzimuth;
  const auto order_n = [&](double t) {
    const auto k = static_cast<std::size_t>(std::max(0.0, t) / 40.0);
    return levels[std::min(k, levels.size() - 1)];
  };
  const auto order_angle = [&](double t) {
    const int k = static_cast<int>(std::max(0.0, t) / 20.0) % 4;
    return (k == 1 ? 0.5 : k == 3 ? -0.5 : 0.0) * M_PI;
  };
  double n = order_n(0.0), angle = 0.0;
  const double end = 40.0 * static_cast<double>(levels.size());
  const auto steps = static_cast<long>(std::lround(end / kDt));
  const long every = std::lround(kLogDt / kDt);
  for (long i = 0; i <= steps; ++i) {
    const double t = static_cast<double>(i) * kDt;
    if (i % every == 0) {
      log.time_s.push_back(t);
      u.order_rps.push_back(order_n(t));
      u.shaft_speed_rps.push_back(n + rpm_noise(rng));
      if (azimuth) {
        u.azimuth_order_rad.push_back(order_angle(t));
        u.azimuth_rad.push_back(std::remainder(angle + deg_noise(rng) * M_PI / 180.0, 2 * M_PI));
      }
    }
    n += kDt * drive.shaft_acceleration(n, order_n(t - truth.dead_time_s));
    angle += kDt * drive.angle_rate(angle, order_angle(t - truth.dead_time_s));
  }
  return log;
}

TEST(VesselUnitsIdentify, ALayoutUnitsDynamicsFromItsSteps) {
  scenario::VesselConfig start;
  model::ThrusterUnit tunnel;
  tunnel.name = "bow";
  tunnel.type = model::UnitType::kTunnel;
  tunnel.max_thrust_N = 100e3;
  tunnel.max_reverse_thrust_N = 90e3;
  model::ThrusterUnit azimuth = tunnel;
  azimuth.name = "main";
  azimuth.type = model::UnitType::kAzimuth;
  azimuth.max_reverse_thrust_N = 0.0;
  start.thrusters = {tunnel, azimuth};  // dead time 1 s, T_n and slew rate the defaults
  // The truth: dead times 1.4 s, time constants 30 % over the defaults, a 15°/s slew.
  model::ThrusterUnit true_tunnel = tunnel, true_azimuth = azimuth;
  for (model::ThrusterUnit* u : {&true_tunnel, &true_azimuth}) {
    u->dead_time_s = 1.4;
    u->time_constant_s = 1.3 * model::drive_params(*u).time_constant_s;
  }
  true_azimuth.rate_deg_per_s = 15.0;
  const double n_max = model::drive_params(tunnel).max_shaft_speed_rps;
  // Steps under and over the rate limit (n_max/4 in T_n), either way.
  const std::vector<double> tunnel_levels{0.0, 0.2, 0.5, 0.1, -0.4, -0.9, 0.3, 0.0};
  const std::vector<double> azimuth_levels{0.1, 0.3, 0.6, 0.2, 0.9, 0.4, 0.1};
  std::vector<LogUnits> logs;
  for (std::uint32_t seed : {1U, 2U}) {
    std::vector<double> levels = tunnel_levels;
    for (double& l : levels) l *= n_max;
    logs.push_back(layout_log(true_tunnel, levels, seed));
    levels = azimuth_levels;
    for (double& l : levels) l *= model::drive_params(azimuth).max_shaft_speed_rps;
    logs.push_back(layout_log(true_azimuth, levels, seed + 10));
  }
  const UnitResult r = identify_units(start, logs, 0.033, 2);
  const std::pair<const char*, double> expected[] = {
      {"thruster.bow.dead_time_s", 1.4},
      {"thruster.bow.time_constant_s", *true_tunnel.time_constant_s},
      {"thruster.main.dead_time_s", 1.4},
      {"thruster.main.time_constant_s", *true_azimuth.time_constant_s},
      {"thruster.main.rate_deg_per_s", 15.0}};
  for (const auto& [key, value] : expected) expect_determined(r, key, value, 0.02);
  // A tunnel has no slew rate; each unit is reported, in layout order.
  EXPECT_THROW(find(r, "thruster.bow.rate_deg_per_s"), std::runtime_error);
  ASSERT_EQ(r.units.size(), 2U);
  EXPECT_EQ(r.units[0].unit, "bow");
  EXPECT_GE(r.units[0].steps, 10U);
  EXPECT_TRUE(std::isnan(r.units[0].slew_rate_deg_per_s));
  EXPECT_GE(r.units[1].turns, 4U);
  // The same on one thread.
  const UnitResult one = identify_units(start, logs, 0.033, 1);
  for (std::size_t k = 0; k < r.parameters.size(); ++k) {
    EXPECT_EQ(one.parameters[k].value, r.parameters[k].value) << r.parameters[k].key;
  }

  // Applied, the determined values are the units'.
  scenario::VesselConfig applied = start;
  apply(applied, r.parameters);
  EXPECT_DOUBLE_EQ(applied.thrusters[0].dead_time_s, find(r, "thruster.bow.dead_time_s").value);
  EXPECT_DOUBLE_EQ(*applied.thrusters[1].time_constant_s,
                   find(r, "thruster.main.time_constant_s").value);
  EXPECT_DOUBLE_EQ(applied.thrusters[1].rate_deg_per_s,
                   find(r, "thruster.main.rate_deg_per_s").value);
}

}  // namespace
}  // namespace dynpos::analysis::vessel_units
