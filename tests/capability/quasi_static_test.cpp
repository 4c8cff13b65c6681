// Quasi-static DP capability (DNV-ST-0111 Levels 1-2): the thrust region against analytic
// limits, and the rose's invariants — symmetry, failures never above intact, more capacity never
// worse, and the limit reported where the thrust region ends.

#include "dynpos/capability/quasi_static.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dynpos/capability/thrust_region.hpp"
#include "dynpos/model/thrust_allocation.hpp"

namespace dynpos::capability {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

model::ThrustAllocator gunnerus_allocator(const std::vector<std::string>& failed = {}) {
  const scenario::VesselConfig v;
  return model::ThrustAllocator(
      model::Thruster(v.propeller), model::Rudder(v.rudder), model::TunnelThruster(v.tunnel),
      model::ThrustConfiguration(v.layout), with_failures(v.allocation, failed));
}

// The virtual Gunnerus made port/starboard symmetric: the tunnel as strong to port as to
// starboard (its only asymmetry).
scenario::VesselConfig symmetric_vessel() {
  scenario::VesselConfig v;
  v.tunnel.kt_port = v.tunnel.kt_starboard;
  return v;
}

TEST(ThrustRegion, PureSurgeIsHeldUpToBothPropellersFullAhead) {
  const ThrustLimits limits = thrust_limits(gunnerus_allocator(), 0.0);
  const double full = limits.hi_N(0) + limits.hi_N(1);  // both propellers at rated thrust
  const Eigen::Vector3d just_held = Eigen::Vector3d::UnitX() * full * (1.0 - 1e-9);
  const auto at = attain(limits, just_held);
  ASSERT_TRUE(at.has_value());
  EXPECT_TRUE(at->at_limit[0] && at->at_limit[1]);
  const Eigen::Vector3d met = limits.B * at->forces_N;
  EXPECT_NEAR((met - just_held).norm(), 0.0, 1e-6);
  const Eigen::Vector3d too_much = Eigen::Vector3d::UnitX() * full * 1.001;
  EXPECT_FALSE(attain(limits, too_much).has_value());
}

TEST(ThrustRegion, EveryForceOfAnAllocationWithinTheLimitsIsAttainable) {
  const ThrustLimits limits = thrust_limits(gunnerus_allocator(), 0.0);
  // Half of every limit, rudders within the cone of their propeller's thrust.
  Eigen::Matrix<double, 5, 1> f;
  f << 0.5 * limits.hi_N(0), -0.5 * std::abs(limits.lo_N(1)), 0.3 * limits.cone.kappa * f(0), 0.0,
      0.5 * limits.lo_N(4);
  EXPECT_TRUE(attain(limits, limits.B * f).has_value());
  EXPECT_TRUE(attain(limits, Eigen::Vector3d::Zero()).has_value());
}

TEST(ThrustRegion, ALostActuatorGivesNothingAndTheRuddersLiftOnlyInSlipstream) {
  // Without the tunnel a side force at rest needs rudder lift, i.e. one propeller ahead (its
  // rudder in the slipstream) and the other astern to cancel the surge force.
  const ThrustLimits lost = thrust_limits(gunnerus_allocator({"tunnel"}), 0.0);
  const Eigen::Vector3d sway = Eigen::Vector3d::UnitY() * 5000.0;
  const auto a = attain(lost, sway);
  ASSERT_TRUE(a.has_value());
  EXPECT_EQ(a->forces_N(4), 0.0);
  const Eigen::Matrix<double, 5, 1> f = a->forces_N;
  for (int i = 0; i < 2; ++i) {  // a rudder's side force within its propeller's cone
    EXPECT_LE(std::abs(f(2 + i)), lost.cone.kappa * std::max(f(i), 0.0) + 1e-6);
  }
  EXPECT_GT(std::abs(f(2)) + std::abs(f(3)), 1000.0);
  EXPECT_LT(f(0) * f(1), 0.0);  // one ahead, one astern
  // With both propellers lost too, nothing pushes sideways.
  const ThrustLimits none = thrust_limits(gunnerus_allocator({"tunnel", "port", "stb"}), 0.0);
  EXPECT_FALSE(attain(none, sway).has_value());
  EXPECT_THROW(gunnerus_allocator({"bow"}), core::InputError);
}

TEST(EnvironmentTable, DnvNumbersAndTheContinuousEnvironment) {
  EXPECT_EQ(dp_number_for_wind(0.0), 0);
  EXPECT_EQ(dp_number_for_wind(10.7), 5);
  EXPECT_EQ(dp_number_for_wind(13.79), 5);
  EXPECT_EQ(dp_number_for_wind(40.0), 11);
  const Environment mid = dnv_level1_table().at(0.5 * (10.7 + 13.8));
  EXPECT_NEAR(mid.hs_m, 0.5 * (2.1 + 3.1), 1e-12);
  EXPECT_NEAR(mid.tp_s, 8.0, 1e-12);
  EXPECT_NEAR(mid.current_mps, 0.75, 1e-12);
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

TEST(QuasiStatic, TheMeanLoadOpposesTheWeather) {
  const scenario::VesselConfig v;
  const Environment e = dnv_level1_table().at(13.8);
  EXPECT_LT(mean_environment_load_b(v, e, 0.0).x(), 0.0);         // from ahead: pushed astern
  EXPECT_LT(mean_environment_load_b(v, e, 90 * kDeg).y(), 0.0);   // from starboard: to port
  EXPECT_GT(mean_environment_load_b(v, e, 270 * kDeg).y(), 0.0);  // from port: to starboard
}

}  // namespace
}  // namespace dynpos::capability
