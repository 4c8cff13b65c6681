// Feasibility of a layout (capability/feasibility.hpp): the largest multiple of a load held,
// against the exact thrust region on the 2014 Gunnerus, and its invariants on other layouts.

#include "dynpos/capability/feasibility.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "dynpos/capability/thrust_region.hpp"
#include "dynpos/capability/vessel_units.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/scenario/vessel_config.hpp"
#include "gunnerus_allocator.hpp"

namespace dynpos::capability {
namespace {

using testing::gunnerus_allocator;

// The largest λ with −λ·load attained in the exact region, by bisection to 10⁻⁹ of 100.
double exact_factor(const ThrustLimits& limits, const Eigen::Vector3d& load) {
  double lo = 0.0, hi = kMaxLoadFactor;
  while (hi - lo > 1e-7) {
    const double mid = 0.5 * (lo + hi);
    (attain(limits, -mid * load).has_value() ? lo : hi) = mid;
  }
  return lo;
}

// Loads of wind from 36 directions on the Gunnerus, intact and with the port propeller lost:
// the factor agrees with the exact region's to 0.5 % (the bisection stops within 0.01 %).
TEST(Feasibility, AgreesWithTheExactThrustRegionOnTheGunnerus) {
  const model::LayoutAllocator allocator(gunnerus_units(gunnerus_allocator()));
  for (const std::string& failure : {std::string("none"), std::string("port")}) {
    const ThrustLimits limits =
        thrust_limits(gunnerus_allocator(failure == "none" ? std::vector<std::string>{}
                                                           : std::vector<std::string>{failure}),
                      0.0);
    const FailureCase c = failure_case(allocator.units(), failure);
    for (int d = 0; d < 36; ++d) {
      const double a = d * 10.0 * std::numbers::pi / 180.0;
      const LoadCase load{d * 10.0, {-2e4 * std::cos(a), -1.5e4 * std::sin(a), 6e4 * std::sin(a)}};
      const FeasibilityPoint p = feasibility(allocator, load, c);
      const double exact = exact_factor(limits, load.load_b);
      EXPECT_NEAR(p.load_factor, exact, 5e-3 * exact + 1e-4) << failure << " at " << d * 10 << "°";
      EXPECT_FALSE(p.capped);
      if (exact > 0.01) {
        EXPECT_FALSE(p.limiting.empty()) << failure << " at " << d * 10 << "°";
      }
      EXPECT_EQ(p.failure, failure);
    }
  }
}

TEST(Feasibility, FailureCasesAreUnitsAndGroups) {
  std::vector<model::ThrusterUnit> units(3);
  const char* names[3] = {"bow", "az1", "az2"};
  for (int k = 0; k < 3; ++k) {
    units[k].name = names[k];
    units[k].max_thrust_N = 1e5;
    units[k].x_m = k == 0 ? 30.0 : -30.0;
    units[k].y_m = k == 0 ? 0.0 : (k == 1 ? -5.0 : 5.0);
    units[k].type = k == 0 ? model::UnitType::kTunnel : model::UnitType::kAzimuth;
    units[k].max_reverse_thrust_N = k == 0 ? 1e5 : 0.0;
  }
  units[0].group = "bus A";
  units[1].group = "bus A";
  units[2].group = "bus B";
  const std::vector<FailureCase> cases = failure_cases(units);
  std::vector<std::string> case_names;
  for (const FailureCase& c : cases) case_names.push_back(c.name);
  EXPECT_EQ(case_names,
            (std::vector<std::string>{"none", "bow", "az1", "az2", "group:bus A", "group:bus B"}));
  EXPECT_EQ(failure_case(units, "group:bus A").capacity, (std::vector<double>{0.0, 0.0, 1.0}));
  try {
    failure_case(units, "stern");
    FAIL();
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.option(), "failure");
    EXPECT_THAT(e.what(), ::testing::HasSubstr("group:bus B"));
  }
  // No case holds more than the intact layout; the worst case names its case.
  const model::LayoutAllocator allocator(units);
  const std::vector<LoadCase> loads = {{0.0, {-5e4, 0.0, 0.0}}, {90.0, {0.0, -4e4, -3e5}}};
  const std::vector<FeasibilityPoint> worst = worst_feasibility(allocator, loads);
  for (std::size_t r = 0; r < loads.size(); ++r) {
    const double intact = feasibility(allocator, loads[r], cases[0]).load_factor;
    for (std::size_t c = 1; c < cases.size(); ++c) {
      const FeasibilityPoint p = feasibility(allocator, loads[r], cases[c]);
      EXPECT_LE(p.load_factor, intact * (1.0 + 1e-4)) << cases[c].name;
      EXPECT_GE(p.load_factor, worst[r].load_factor);
    }
    EXPECT_NE(worst[r].failure, "none");
  }
  EXPECT_EQ(worst[1].failure, "group:bus A");  // the beam load without the bow tunnel and az1
}

// A layout symmetric about the centre line holds a mirrored load as many times.
TEST(Feasibility, ASymmetricLayoutHoldsMirroredLoadsAlike) {
  const auto unit = model::thruster_unit;
  const std::vector<model::ThrusterUnit> units = {
      unit("bow", model::UnitType::kTunnel, 30.0, 0.0, 1e5, 1e5, {}),
      unit("az_port", model::UnitType::kAzimuth, -30.0, -5.0, 3e5, 0.0, {{60.0, 120.0}}),
      unit("az_stb", model::UnitType::kAzimuth, -30.0, 5.0, 3e5, 0.0, {{240.0, 300.0}})};
  const model::LayoutAllocator allocator(units);
  const FailureCase intact = failure_case(units, "none");
  std::mt19937 rng(9);
  std::normal_distribution<double> n01(0.0, 1.0);
  for (int k = 0; k < 30; ++k) {
    const Eigen::Vector3d load{1e5 * n01(rng), 5e4 * n01(rng), 2e6 * n01(rng)};
    const double a = feasibility(allocator, {0.0, load}, intact).load_factor;
    const double b =
        feasibility(allocator, {0.0, {load(0), -load(1), -load(2)}}, intact).load_factor;
    EXPECT_NEAR(a, b, 2e-4 * a) << load.transpose();
  }
}

}  // namespace
}  // namespace dynpos::capability
