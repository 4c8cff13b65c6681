// The allocation for any layout (model/layout_allocator.hpp) on the 2014 Gunnerus's units
// against the exact thrust region of the capability analysis (capability/thrust_region.hpp):
// two independent answers to "how much of this force can the thrusters hold".

#include "dynpos/capability/vessel_units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "dynpos/capability/thrust_region.hpp"
#include "dynpos/model/layout_allocator.hpp"
#include "dynpos/scenario/vessel_config.hpp"
#include "gunnerus_allocator.hpp"

namespace dynpos::capability {
namespace {

using testing::gunnerus_allocator;

// The largest λ ≤ 10 with held(λ) (monotone), by bisection to 10⁻⁹ of 10.
double largest_factor(const std::function<bool(double)>& held) {
  double lo = 0.0, hi = 10.0;
  while (hi - lo > 1e-8) {
    const double mid = 0.5 * (lo + hi);
    (held(mid) ? lo : hi) = mid;
  }
  return lo;
}

// Along 200 random directions of τ (surge, sway, yaw over their scales), at rest and at 1.5 m/s
// of inflow (the rudders lift without slipstream), the largest multiple of τ the layout
// allocation meets equals the one the exact region attains, to 10⁻⁵ of it (the two methods'
// tolerances of "met", 10⁻⁶ of the force scale and 10⁻⁹ of the largest bound).
TEST(VesselUnits, TheLayoutAllocationHoldsWhatTheExactRegionHolds) {
  const model::ThrustAllocator allocator = gunnerus_allocator();
  std::mt19937 rng(17);
  std::normal_distribution<double> n01(0.0, 1.0);
  for (const double inflow : {0.0, 1.5}) {
    const ThrustLimits limits = thrust_limits(allocator, inflow);
    const model::LayoutAllocator layout(gunnerus_units(allocator, inflow));
    for (int k = 0; k < 200; ++k) {
      const Eigen::Vector3d tau{1.5e5 * n01(rng), 5e4 * n01(rng), 1e6 * n01(rng)};
      const double exact =
          largest_factor([&](double s) { return attain(limits, s * tau).has_value(); });
      const double allocated =
          largest_factor([&](double s) { return layout.allocate(s * tau).met; });
      EXPECT_NEAR(allocated, exact, 1e-5 * exact + 1e-7)
          << "inflow " << inflow << ", τ = " << tau.transpose();
    }
  }
}

}  // namespace
}  // namespace dynpos::capability
