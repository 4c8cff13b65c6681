#pragma once
// The start of a unit's fall to zero, timed between its feedback samples (private; the rules
// are in dynpos/ident/failure_test.hpp and docs/theory.md, "Failure test").
//
// Model of a shaft speed s after a trip at t_f: a level line before (the DP's own swing), then
// the unit's speed control decaying to zero from L = line(t_f) with its time constant T and an
// acceleration limit r: s = L − r·(t − t_f) while r·T < s, then first order, s ∝ e^{−t/T}.
// With the unit's order logged, the samples before the onset may instead follow the order
// (a dead time and a first-order lag, fitted on the minute before the search, at a gain fitted
// per onset), whichever fits them better: a DP loop that ramps a unit down just before it trips
// has the feedback falling with the order, which a level line takes for the start of the decay.
// T and r are not known: the onset is the one that fits best over a grid of them.

#include <optional>
#include <span>
#include <vector>

namespace dynpos::ident::detail {

/// Where to look for the onset and how noisy the samples are.
struct FallSearch {
  double from_s = 0.0;       ///< earliest onset [s]
  double to_s = 0.0;         ///< latest onset [s] (the first sample clearly fallen)
  double level_s = 2.0;      ///< the level line: the samples this long before from_s [s]
  double fall_s = 6.0;       ///< the fall: the samples up to this long after to_s [s]
  double noise_sigma = 0.0;  ///< of the samples (their unit); floored at 10⁻⁶ of the level
  double step_s = 0.02;      ///< resolution of the onset [s]
  /// With the order: the search reaches on to the first sample below this share of what
  /// following the order gives (the failure test's fall_from_fraction, on the shaft speed).
  double fallen_fraction = 0.775;
  /// … while following the order would keep the unit above this share of its speed at from_s
  /// (an order dropped to a third of its level is a stop: the failure test's rule, on the speed).
  double still_ordered = 0.577;
};

struct FallOnset {
  double t_s = 0.0;              ///< the onset: middle of the onsets that fit as well [s]
  double earliest_s = 0.0;       ///< … the first of them [s]
  double latest_s = 0.0;         ///< … the last [s]
  double time_constant_s = 0.0;  ///< T of the best fit [s]
  double level = 0.0;            ///< L of the best fit (the samples' unit)
};

/// The onset of the fall of s (≥ 0, NaN = missing) on the time axis t: the grid of onsets in
/// [from_s, to_s] (step_s), each with its best T (0.05–5 s) and r (0.05–50 L/s); the onsets
/// whose residual sum of squares is within 4σ² of the least are those that fit as well (a rate
/// limit no sample shows leaves the onset between the last sample at the level and the first
/// fallen one). nullopt without a sample before from_s or two after to_s in the windows, when
/// an onset at from_s fits as well (the fall may have begun before the search) and when the
/// onsets that fit as well span more than 1.5 sample intervals (a fall slower than the search
/// was set for, which the line before it takes for a swing): the onset is not determined.
/// `order`: the unit's ordered shaft speed on t (NaN = none), or empty.
std::optional<FallOnset> fit_fall_onset(const std::vector<double>& t, const std::vector<double>& s,
                                        const FallSearch& search,
                                        std::span<const double> order = {});

}  // namespace dynpos::ident::detail
