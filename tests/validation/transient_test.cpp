// The failure as it happens (capability --transient) against the consequence analysis on the
// virtual 2014 Gunnerus: 36 directions × the DP numbers 3, 4, 5, the bow tunnel tripped after
// 300 s of stationkeeping on the passive observer, 300 s after it.
//
// The transient holds where the excursions stay within the footprint (5 m, 3°). The
// consequence analysis holds where the thrusters left after the failure balance the load the
// observer estimated over the minute before it (capability/consequence.hpp, λ ≥ 1). Issue
// bound: they agree on held or lost at ≥ 90 % of the 108 points.

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "../source_dir.hpp"
#include "dynpos/capability/consequence.hpp"
#include "dynpos/capability/transient.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos {
namespace {

const std::filesystem::path kSource = DYNPOS_SOURCE_DIR;

TEST(TransientAgainstConsequence, AgreeOnHeldOrLost) {
  const scenario::VesselConfig vessel =
      scenario::load_vessel_config(kSource / "data" / "vessels" / "gunnerus.toml");
  const std::string failure = "tunnel";
  capability::TransientOptions o;
  o.observer = control::ObserverKind::kPassive;
  const std::vector<capability::TransientPoint> points =
      capability::transient_footprint(vessel, failure, o);
  ASSERT_EQ(points.size(), 108u);
  const capability::FailureConsequence consequence(vessel);
  const auto& cases = consequence.cases();
  const std::size_t k =
      static_cast<std::size_t>(std::find(cases.begin(), cases.end(), failure) - cases.begin());
  ASSERT_LT(k, cases.size());
  int agree = 0, held = 0, held_quasi_static = 0;
  for (const capability::TransientPoint& p : points) {
    const double lambda = consequence.load_factor(p.runs.front().estimated_load_b, k).load_factor;
    const bool quasi_static_holds = lambda >= 1.0;
    agree += quasi_static_holds == p.holds ? 1 : 0;
    held += p.holds ? 1 : 0;
    held_quasi_static += quasi_static_holds ? 1 : 0;
    if (quasi_static_holds != p.holds) {
      std::printf("differ: %.0f° DP %d: λ %.2f, peak %.2f m, heading %.1f°\n", p.direction_deg,
                  p.dp_number, lambda, p.peak_excursion_m, p.peak_heading_deg);
    }
  }
  std::printf("agree at %d of %zu points; held: transient %d, consequence %d\n", agree,
              points.size(), held, held_quasi_static);
  EXPECT_GE(agree, 98);  // 90 % of 108, rounded up
  // Not a trivial agreement: both verdicts occur.
  EXPECT_GT(held, 0);
  EXPECT_LT(held, 108);
}

}  // namespace
}  // namespace dynpos
