// Quasi-static DP capability (DNV-ST-0111 Levels 1-2): the rose's invariants — symmetry,
// failures never above intact, more capacity never worse, and the limit reported where the
// thrust region ends.

#include "dynpos/capability/quasi_static.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <string>

#include "dynpos/capability/thrust_region.hpp"
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

TEST(QuasiStatic, NoFailureIsMoreCapableThanTheIntactVessel) {
  const scenario::VesselConfig v;
  const auto intact = quasi_static_rose(v, {}, fast_options());
  std::vector<std::vector<CapabilityPoint>> cases = {intact};
  for (const std::string& f : single_failures()) {
    const auto rose = quasi_static_rose(v, {f}, fast_options());
    for (std::size_t i = 0; i < rose.size(); ++i) {
      EXPECT_LE(rose[i].max_wind_mps, intact[i].max_wind_mps + 1e-9) << f;
      EXPECT_LE(rose[i].dp_number, intact[i].dp_number) << f;
      EXPECT_EQ(rose[i].failure, f);
    }
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

}  // namespace
}  // namespace dynpos::capability
