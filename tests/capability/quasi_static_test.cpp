// Quasi-static DP capability (DNV-ST-0111 Levels 1-2): the rose's invariants — symmetry,
// failures never above intact, more capacity never worse, and the limit reported where the
// thrust region ends.

#include "dynpos/capability/quasi_static.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <numbers>
#include <sstream>
#include <string>

#include "../source_dir.hpp"
#include "dynpos/capability/thrust_region.hpp"
#include "dynpos/capability/vessel_units.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/model/hull.hpp"
#include "dynpos/model/thrust_allocation.hpp"
#include "gunnerus_allocator.hpp"

namespace dynpos::capability {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

using testing::gunnerus_allocator;

// The virtual Gunnerus made port/starboard symmetric: the tunnel as strong to port as to
// starboard (its only asymmetry).
scenario::VesselConfig symmetric_vessel() {
  scenario::VesselConfig v;
  v.tunnel.kt_port = v.tunnel.kt_starboard;
  return v;
}

QuasiStaticOptions fast_options(int level = 1) {
  QuasiStaticOptions o;
  o.level = level;
  o.direction_step_deg = 30.0;
  return o;
}

TEST(QuasiStatic, ASymmetricVesselHasASymmetricRose) {
  const scenario::VesselConfig v = symmetric_vessel();
  for (int level : {1, 2}) {
    const auto rose = quasi_static_rose(v, {}, fast_options(level));
    ASSERT_EQ(rose.size(), 12u);
    for (std::size_t i = 1; i < rose.size(); ++i) {
      const auto& mirror = rose[rose.size() - i];
      EXPECT_EQ(rose[i].dp_number, mirror.dp_number) << rose[i].direction_deg;
      // Both ends of a bisection within its tolerance.
      EXPECT_NEAR(rose[i].max_wind_mps, mirror.max_wind_mps, 0.011) << rose[i].direction_deg;
    }
  }
}

// The rose of the failure case `f` is nowhere above `bound` (the intact rose, or a case it
// contains), in wind or number, and names its case.
void expect_no_more_capable(const std::vector<CapabilityPoint>& rose,
                            const std::vector<CapabilityPoint>& bound, const std::string& f) {
  ASSERT_EQ(rose.size(), bound.size());
  for (std::size_t i = 0; i < rose.size(); ++i) {
    EXPECT_LE(rose[i].max_wind_mps, bound[i].max_wind_mps + 1e-9) << f;
    EXPECT_LE(rose[i].dp_number, bound[i].dp_number) << f;
    EXPECT_EQ(rose[i].failure, f);
  }
}

TEST(QuasiStatic, NoFailureIsMoreCapableThanTheIntactVessel) {
  const scenario::VesselConfig v;
  const auto intact = quasi_static_rose(v, {}, fast_options());
  std::vector<std::vector<CapabilityPoint>> cases = {intact};
  for (const std::string& f : single_failures(v)) {
    const auto rose = quasi_static_rose(v, {f}, fast_options());
    expect_no_more_capable(rose, intact, f);
    cases.push_back(rose);
  }
  const auto worst = worst_case(cases);
  for (std::size_t i = 0; i < worst.size(); ++i) {
    for (const auto& rose : cases) EXPECT_LE(worst[i].max_wind_mps, rose[i].max_wind_mps);
  }
}

TEST(QuasiStatic, ADoubledTunnelMakesNoDirectionWorse) {
  const scenario::VesselConfig v;
  scenario::VesselConfig doubled = v;
  doubled.allocation.capacity(4) = 2.0;
  const auto base = quasi_static_rose(v, {}, fast_options());
  const auto more = quasi_static_rose(doubled, {}, fast_options());
  bool better_somewhere = false;
  for (std::size_t i = 0; i < base.size(); ++i) {
    EXPECT_GE(more[i].max_wind_mps, base[i].max_wind_mps - 1e-9) << base[i].direction_deg;
    better_somewhere |= more[i].max_wind_mps > base[i].max_wind_mps + 0.1;
  }
  EXPECT_TRUE(better_somewhere);  // the tunnel limits the beam directions
}

TEST(QuasiStatic, AtTheLimitTheThrustersSaturateAndAboveItTheyFail) {
  const scenario::VesselConfig v;
  const QuasiStaticOptions o = fast_options();
  const ThrustLimits limits = thrust_limits(gunnerus_allocator(), 0.0);
  for (const double deg : {60.0, 90.0, 150.0, 270.0}) {  // (head-on it holds the whole table)
    const CapabilityPoint p = quasi_static_point(v, {}, deg * kDeg, o);
    ASSERT_FALSE(p.beyond_table) << deg;
    EXPECT_NE(p.limiting, "none") << deg;
    const auto load = [&](double w) -> Eigen::Vector3d {
      return -kDynamicAllowance * mean_environment_load_b(v, o.environment.at(w), deg * kDeg);
    };
    EXPECT_TRUE(attain(limits, load(p.max_wind_mps)).has_value()) << deg;
    EXPECT_FALSE(attain(limits, load(p.max_wind_mps + 2.0 * o.wind_tolerance_mps)).has_value())
        << deg;
    EXPECT_EQ(p.dp_number, dp_number_for_wind(p.max_wind_mps)) << deg;
  }
}

// The option a rejected value is named by.
std::string refused_option(const std::function<void()>& check) {
  try {
    check();
  } catch (const core::InputError& e) {
    return e.option();
  }
  return "(accepted)";
}

TEST(QuasiStatic, TheWindToleranceHasARange) {
  for (const double tolerance : {1e-300, 0.0, -1.0, 9e-7, 10.5, HUGE_VAL, std::nan("")}) {
    QuasiStaticOptions o = fast_options();
    o.wind_tolerance_mps = tolerance;
    EXPECT_EQ(refused_option([&] { o.validate(); }), "wind_tolerance") << tolerance;
  }
  for (const double tolerance : {kMinWindTolerance_mps, 0.01, kMaxWindTolerance_mps}) {
    QuasiStaticOptions o = fast_options();
    o.wind_tolerance_mps = tolerance;
    EXPECT_EQ(refused_option([&] { o.validate(); }), "(accepted)") << tolerance;
  }
}

TEST(QuasiStatic, TheDirectionStepIsAFiniteDivisorOf360) {
  for (const double step : {HUGE_VAL, -HUGE_VAL, std::nan(""), 720.0, 0.0, -10.0, 7.0, 0.01}) {
    EXPECT_EQ(refused_option([&] { check_direction_step(step); }), "direction_step") << step;
  }
  for (const double step : {0.1, 10.0, 360.0}) {
    EXPECT_EQ(refused_option([&] { check_direction_step(step); }), "(accepted)") << step;
  }
}

// A tolerance below one ulp of the wind (the options' check is bypassed here) cannot narrow the
// bracket further: the bisection still ends, at most kMaxBisections halvings from the rows.
TEST(QuasiStatic, TheBisectionEndsBelowAnUlp) {
  QuasiStaticOptions o = fast_options();
  o.wind_tolerance_mps = 1e-300;
  const scenario::VesselConfig v;
  const CapabilityPoint tiny = quasi_static_point(v, {}, 90 * kDeg, o);
  o.wind_tolerance_mps = kMinWindTolerance_mps;
  const CapabilityPoint fine = quasi_static_point(v, {}, 90 * kDeg, o);
  EXPECT_EQ(tiny.dp_number, fine.dp_number);
  EXPECT_NEAR(tiny.max_wind_mps, fine.max_wind_mps, kMinWindTolerance_mps);
}

TEST(QuasiStatic, TheMeanLoadOpposesTheWeather) {
  const scenario::VesselConfig v;
  const Environment e = dnv_level1_table().at(13.8);
  EXPECT_LT(mean_environment_load_b(v, e, 0.0).x(), 0.0);         // from ahead: pushed astern
  EXPECT_LT(mean_environment_load_b(v, e, 90 * kDeg).y(), 0.0);   // from starboard: to port
  EXPECT_GT(mean_environment_load_b(v, e, 270 * kDeg).y(), 0.0);  // from port: to starboard
}

// The virtual Gunnerus's hull and weather with a layout like its 2015 retrofit: two azimuths
// aft, each barred from pushing into the other's propeller, and the bow tunnel (as strong both
// ways, so the layout is port/starboard symmetric); a switchboard per side.
scenario::VesselConfig azimuth_vessel() {
  using model::UnitType;
  scenario::VesselConfig v = symmetric_vessel();
  v.thrusters = {
      model::thruster_unit("az_port", UnitType::kAzimuth, -13.0, -2.7, 60e3, 0.0, {{75, 105}}),
      model::thruster_unit("az_stb", UnitType::kAzimuth, -13.0, 2.7, 60e3, 0.0, {{255, 285}}),
      model::thruster_unit("tunnel", UnitType::kTunnel, 12.5, 0.0, 25e3, 25e3)};
  v.thrusters[0].group = "port";
  v.thrusters[1].group = "stb";
  return v;
}

TEST(QuasiStaticLayout, ASymmetricLayoutHasASymmetricRose) {
  const scenario::VesselConfig v = azimuth_vessel();
  for (int level : {1, 2}) {
    const auto rose = quasi_static_rose(v, {}, fast_options(level));
    for (std::size_t i = 1; i < rose.size(); ++i) {
      const auto& mirror = rose[rose.size() - i];
      EXPECT_EQ(rose[i].dp_number, mirror.dp_number) << rose[i].direction_deg;
      EXPECT_NEAR(rose[i].max_wind_mps, mirror.max_wind_mps, 0.011) << rose[i].direction_deg;
    }
  }
}

// Every unit and group lost, and both sides' groups (a case of two failures): never more
// capable than intact, and a unit lost never more than the group holding it.
TEST(QuasiStaticLayout, NoFailureIsMoreCapableThanTheIntactLayout) {
  const scenario::VesselConfig v = azimuth_vessel();
  EXPECT_EQ(single_failures(v),
            (std::vector<std::string>{"az_port", "az_stb", "tunnel", "group:port", "group:stb"}));
  const auto intact = quasi_static_rose(v, {}, fast_options());
  const auto port = quasi_static_rose(v, {"az_port"}, fast_options());
  for (const std::string& f : single_failures(v)) {
    const auto rose = quasi_static_rose(v, {f}, fast_options());
    expect_no_more_capable(rose, intact, f);
    if (f == "group:port") {
      for (std::size_t i = 0; i < rose.size(); ++i) {
        EXPECT_LE(rose[i].max_wind_mps, port[i].max_wind_mps + 1e-9);
      }
    }
  }
  const auto both = quasi_static_rose(v, {"group:port", "az_stb"}, fast_options());
  for (const CapabilityPoint& p : both) EXPECT_EQ(p.limiting, "no thrust left for the weather");
}

// The model's own units written as a layout (vessel_units.hpp: the propellers with their
// rudders' cones, the tunnel) give the model's rose: the layout's rudder cone is the model's
// lift at the allocation's largest angle, a line through the origin where the model's exact
// region bends, so the layout can hold less, never more; the load grows as the wind squared,
// so 0.5 % of force (capability::feasibility's agreement) is 0.25 % of wind, and the
// bisections' 0.01 m/s comes on top.
TEST(QuasiStaticLayout, TheModelsUnitsAsALayoutGiveTheModelsRose) {
  const scenario::VesselConfig model;
  scenario::VesselConfig layout = model;
  layout.thrusters = gunnerus_units(gunnerus_allocator());
  const auto exact = quasi_static_rose(model, {}, fast_options());
  const auto units = quasi_static_rose(layout, {}, fast_options());
  for (std::size_t i = 0; i < exact.size(); ++i) {
    SCOPED_TRACE(exact[i].direction_deg);
    EXPECT_LE(units[i].max_wind_mps, exact[i].max_wind_mps + 0.011);
    EXPECT_GE(units[i].max_wind_mps, exact[i].max_wind_mps * (1.0 - 0.0025) - 0.011);
  }
}

TEST(QuasiStaticLayout, TheLimitingUnitsAreTheLayoutsAndUnknownCasesAreNamed) {
  const scenario::VesselConfig v = azimuth_vessel();
  const CapabilityPoint beam = quasi_static_point(v, {}, 90 * kDeg, fast_options());
  ASSERT_FALSE(beam.beyond_table);
  EXPECT_NE(beam.limiting.find("tunnel"), std::string::npos) << beam.limiting;
  for (const char* name : {"az_port", "group:stb"})
    EXPECT_NO_THROW(check_failure(v, name, "failure"));
  try {
    check_failure(v, "port", "worst_of");
    ADD_FAILURE() << "no error";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.option(), "worst_of");
    EXPECT_NE(std::string(e.what()).find("group:port"), std::string::npos) << e.what();
  }
}

scenario::VesselConfig shipped(const char* file) {
  return scenario::load_vessel_config(std::filesystem::path(DYNPOS_SOURCE_DIR) / "data" /
                                      "vessels" / file);
}

// The supply vessel's hull is its source's (Fossen, Sagatun and Sørensen 1996, the bis-system
// matrices M'' and D'' with m = 6000 t, L = 76.2 m): its inertia matrix and linear damping at
// rest, to the file's 7 significant digits.
TEST(ShippedVessels, TheSupplyVesselsHullIsItsSources) {
  const scenario::VesselConfig v = shipped("osv-80m.toml");
  const double m = 6.0e6, L = 76.2, root_g_over_L = std::sqrt(9.8 / L);
  const model::Hull hull(v.hull);
  const Eigen::Matrix3d& M = hull.mass_matrix();
  EXPECT_NEAR(M(0, 0), 1.1274 * m, 1e-7 * M(0, 0));
  EXPECT_NEAR(M(1, 1), 1.8902 * m, 1e-7 * M(1, 1));
  EXPECT_NEAR(M(1, 2), -0.0744 * m * L, 1e-7 * std::abs(M(1, 2)));
  EXPECT_NEAR(M(2, 1), M(1, 2), 0.0);
  EXPECT_NEAR(M(2, 2), 0.1278 * m * L * L, 1e-7 * M(2, 2));
  EXPECT_NEAR(v.hull.x_u_Ns_m, 0.0358 * m * root_g_over_L, 1e-6 * v.hull.x_u_Ns_m);
  EXPECT_NEAR(v.hull.y_v_Ns_m, 0.1183 * m * root_g_over_L, 1e-6 * v.hull.y_v_Ns_m);
  EXPECT_NEAR(v.hull.n_r_Nms, 0.0308 * m * L * L * root_g_over_L, 1e-6 * v.hull.n_r_Nms);
}

// Both shipped azimuth vessels are graded with their own units: no failure above intact, the
// worst case names one of the vessel's cases, and every direction between the calm and the
// table's end names the units that limit it.
TEST(ShippedVessels, TheAzimuthVesselsAreGradedWithTheirUnits) {
  for (const char* file : {"gunnerus-2015.toml", "osv-80m.toml"}) {
    SCOPED_TRACE(file);
    const scenario::VesselConfig v = shipped(file);
    ASSERT_FALSE(v.thrusters.empty());
    QuasiStaticOptions o = fast_options();
    o.direction_step_deg = 20.0;
    const auto intact = quasi_static_rose(v, {}, o);
    std::vector<std::vector<CapabilityPoint>> cases;
    for (const std::string& f : single_failures(v)) cases.push_back(quasi_static_rose(v, {f}, o));
    const auto worst = worst_case(cases);
    const std::vector<std::string> names = single_failures(v);
    for (std::size_t i = 0; i < intact.size(); ++i) {
      EXPECT_LE(worst[i].max_wind_mps, intact[i].max_wind_mps + 1e-9);
      EXPECT_NE(std::find(names.begin(), names.end(), worst[i].failure), names.end());
      for (const CapabilityPoint& p : {intact[i], worst[i]}) {
        if (p.beyond_table || p.max_wind_mps == 0.0) continue;
        ASSERT_NE(p.limiting, "none") << p.direction_deg << " deg, " << p.failure;
        std::stringstream parts(p.limiting);
        for (std::string unit; std::getline(parts, unit, '+');) {
          EXPECT_TRUE(std::any_of(v.thrusters.begin(), v.thrusters.end(),
                                  [&](const model::ThrusterUnit& u) { return u.name == unit; }))
              << unit;
        }
      }
    }
  }
}

}  // namespace
}  // namespace dynpos::capability
