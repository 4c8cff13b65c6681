// The consequence of a single failure (capability/consequence.hpp): the worst case's factor of
// a load, and its sign flipping between a load just inside and just outside that case's region.

#include "dynpos/capability/consequence.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "../source_dir.hpp"
#include "dynpos/model/thrust_allocation.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::capability {
namespace {

// A load of 20 kN (and its moment) from `deg` off the bow on a 30–40 m vessel.
Eigen::Vector3d load_from(double deg) {
  const double a = deg * std::numbers::pi / 180.0;
  return {-2e4 * std::cos(a), -2e4 * std::sin(a), 5e4 * std::sin(a)};
}

// Whether the thrusters left after `failure` hold the load itself (λ = 1), asked of the model's
// exact region directly.
bool model_holds(const scenario::VesselConfig& v, const std::string& failure,
                 const Eigen::Vector3d& load_b) {
  const model::ThrustAllocator allocator(
      model::Thruster(v.propeller), model::Rudder(v.rudder), model::TunnelThruster(v.tunnel),
      model::ThrustConfiguration(v.layout), model::with_failures(v.allocation, {failure}));
  return attain(thrust_limits(allocator, 0.0), -load_b).has_value();
}

// The same of a layout's allocation.
bool layout_holds(const scenario::VesselConfig& v, const std::string& failure,
                  const Eigen::Vector3d& load_b) {
  const model::LayoutAllocator allocator(v.thrusters);
  return allocator.allocate(-load_b, failure_case(v.thrusters, failure).capacity).met;
}

scenario::VesselConfig gunnerus_2015() {
  return scenario::load_vessel_config(std::filesystem::path(DYNPOS_SOURCE_DIR) / "data" /
                                      "vessels" / "gunnerus-2015.toml");
}

TEST(FailureConsequence, TheCasesAreTheSingleFailures) {
  EXPECT_THAT(FailureConsequence(scenario::VesselConfig{}).cases(),
              ::testing::ElementsAre("port", "stb", "rudder.port", "rudder.stb", "tunnel"));
  EXPECT_THAT(FailureConsequence(gunnerus_2015()).cases(),
              ::testing::ElementsAre("pod_port", "pod_stb", "tunnel", "group:port", "group:stb"));
}

// Scaled to just inside (λ·(1 − 10⁻³)) and just outside (λ·(1 + 10⁻³)) a case's factor, the
// load is held by that case and then not, asked of the region directly; and the worst case's
// margin λ − 1 flips sign.
TEST(FailureConsequence, ALoadJustInsideOrOutsideACaseFlipsTheMargin) {
  const auto check = [](const scenario::VesselConfig& vessel, auto holds) {
    const FailureConsequence consequence(vessel);
    int flipped = 0;
    for (int deg = 0; deg < 360; deg += 30) {
      const Eigen::Vector3d load = load_from(deg);
      const std::vector<FeasibilityPoint> all = consequence.load_factors(load);
      for (std::size_t k = 0; k < all.size(); ++k) {
        const FeasibilityPoint& p = all[k];
        if (p.capped || p.load_factor == 0.0) continue;  // no edge to cross
        for (const double s : {1.0 - 1e-3, 1.0 + 1e-3}) {
          const Eigen::Vector3d scaled = load * p.load_factor * s;
          const bool inside = s < 1.0;
          EXPECT_EQ(consequence.load_factor(scaled, k).load_factor - 1.0 >= 0.0, inside)
              << p.failure << " at " << deg << "° ×" << s;
          EXPECT_EQ(holds(vessel, p.failure, scaled), inside) << p.failure << " at " << deg << "°";
        }
        ++flipped;
      }
      const FeasibilityPoint w = consequence.worst(load);
      for (const FeasibilityPoint& p : all) EXPECT_GE(p.load_factor, w.load_factor) << p.failure;
      EXPECT_GE(consequence.intact(load).load_factor, w.load_factor * (1 - 1e-4)) << deg;
      if (w.load_factor == 0.0) continue;
      for (const double s : {1.0 - 1e-3, 1.0 + 1e-3}) {
        EXPECT_EQ(consequence.worst(load * w.load_factor * s).load_factor >= 1.0, s < 1.0) << deg;
      }
    }
    EXPECT_GT(flipped, 20);
  };
  check(scenario::VesselConfig{}, model_holds);
  check(gunnerus_2015(), layout_holds);
}

// The 2014 Gunnerus with a propeller lost holds no load off the bow at rest (its rudder has
// no slipstream astern, and ahead its cone is too narrow for the moment: `capability --failure
// port` holds only head-on); head-on the two propellers' cases are equal, the first named.
TEST(FailureConsequence, NamesTheWorstCaseAndTheLimitingActuators) {
  const FailureConsequence consequence(scenario::VesselConfig{});
  const FeasibilityPoint ahead = consequence.worst(load_from(0.0));
  EXPECT_EQ(ahead.failure, "port");
  EXPECT_GT(ahead.load_factor, 1.0);
  EXPECT_THAT(ahead.limiting, ::testing::Contains("stb"));
  EXPECT_DOUBLE_EQ(consequence.load_factor(load_from(0.0), 1).load_factor, ahead.load_factor);
  const FeasibilityPoint beam = consequence.worst(load_from(90.0));
  EXPECT_EQ(beam.load_factor, 0.0);
  EXPECT_EQ(beam.failure, "port");
  EXPECT_GT(consequence.load_factor(load_from(90.0), 4).load_factor, 1.0);  // the tunnel lost
  EXPECT_EQ(consequence.intact(load_from(90.0)).failure, "none");
}

TEST(FailureConsequence, AZeroLoadIsHeldAtAnyFactor) {
  for (const scenario::VesselConfig& v : {scenario::VesselConfig{}, gunnerus_2015()}) {
    const FeasibilityPoint w = FailureConsequence(v).worst(Eigen::Vector3d::Zero());
    EXPECT_TRUE(w.capped);
    EXPECT_EQ(w.load_factor, kMaxLoadFactor);
  }
}

TEST(FailureConsequence, RejectsACaseOutOfRange) {
  const FailureConsequence consequence(scenario::VesselConfig{});
  EXPECT_THROW((void)consequence.load_factor(load_from(0.0), 5), std::out_of_range);
}

}  // namespace
}  // namespace dynpos::capability
