#pragma once
// The steps of the failure-test analysis after detection (private): a trip per unit, the events
// they make, and each event's redistribution and excursion (dynpos/ident/failure_test.hpp).

#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

#include "dynpos/ident/failure_test.hpp"

namespace dynpos::ident::detail {

/// A unit's feedback as the detection sees it.
struct UnitProfile {
  std::vector<double> abs;     ///< |feedback|
  std::vector<double> smooth;  ///< its running median
  UnitScale scale;
};

/// One unit's fall to near zero.
struct Trip {
  std::size_t unit = 0;  ///< index into the input's units
  double t_f = 0.0;      ///< failure instant [s]
  double t_z = 0.0;      ///< first sample near zero [s]
  double level = 0.0;    ///< L, the level before (SI)
  OnsetMethod onset = OnsetMethod::kLastLevel;
  std::optional<double> time_constant_s;
};

/// The failure instants of the events before and after one [s]; ±∞ when there is none.
struct Neighbours {
  double previous_s = -std::numeric_limits<double>::infinity();
  double next_s = std::numeric_limits<double>::infinity();
};

/// The first index with t ≥ from (t increasing).
std::size_t first_at(const std::vector<double>& t, double from);

/// The valid samples of x with t in [from, to].
std::vector<double> valid_in(const std::vector<double>& t, const std::vector<double>& x,
                             double from, double to);

/// The centered running median of x over [t − w/2, t + w/2], from its valid samples; NaN where
/// x is NaN. w ≤ 0 returns x.
std::vector<double> running_median(const std::vector<double>& t, const std::vector<double>& x,
                                   double w);

/// The neighbours of events[k] (in time order).
Neighbours neighbours(const std::vector<FailureEvent>& events, std::size_t k);

/// The event of trips starting together (in time order): named after the first.
FailureEvent event_of(const FailureTestInput& in, const std::vector<Trip>& trips);

/// Sets e.redistribution: the units that did not trip, their means before and after.
void redistribute(const FailureTestInput& in, const std::vector<UnitProfile>& profiles,
                  const Neighbours& around, const FailureTestOptions& o, FailureEvent& e);

/// Sets the pre-failure window, the position and heading figures and the recovery of e.
void excursion(const FailureTestInput& in, const Neighbours& around, const FailureTestOptions& o,
               FailureEvent& e);

}  // namespace dynpos::ident::detail
