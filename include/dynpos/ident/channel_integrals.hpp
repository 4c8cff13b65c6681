#pragma once
/// \file
/// Time integrals and time-weighted means of one logged channel over a window, from its own
/// valid samples: the per-thruster sums of the DP 4-corner and stationkeeping tables (accumulated
/// thrust ∫|T|dt [N·s], energy ∫P dt [J], mean thrust; thesis tables 3.6–3.22).
///
/// A channel of a mixed-rate log has blank cells (NaN) between its samples (the tunnel thruster
/// at 1 Hz in a 10 Hz log). The integral runs over the channel's valid samples by the trapezoid
/// rule, the signal is held flat from the window's edges to its first and last valid sample, and
/// a stretch between two valid samples longer than `max_gap_s` is a gap: it is left out and
/// reported, never bridged silently. Coverage says how much of the window the data spans.

#include <optional>
#include <span>

namespace dynpos::ident {

/// Options for integrate_channel().
struct ChannelIntegralOptions {
  /// Longest spacing [s] between two valid samples that is still integrated across, > 0.
  double max_gap_s = 5.0;
  /// Coverage below this fraction (in (0, 1]) makes the result missing: too little data.
  double min_coverage = 0.9;
  /// Integrate |x| instead of x (accumulated thrust).
  bool absolute = false;
};

/// ∫x dt over [t_from, t_to] and the time-weighted mean of x there.
struct ChannelIntegral {
  std::optional<double> integral;  ///< [unit of x · s]; missing when coverage is too low
  std::optional<double> mean;      ///< integral / covered time [unit of x]
  double covered_s = 0.0;          ///< time spanned by valid data (gaps left out) [s]
  double coverage = 0.0;           ///< covered_s / (t_to − t_from), in [0, 1]
  double longest_gap_s = 0.0;      ///< longest gap left out [s]
  std::size_t samples = 0;         ///< valid samples inside the window
};

/// Integrates channel x (NaN = missing) sampled at t (strictly increasing, same length) over
/// [t_from_s, t_to_s]. Throws core::InputError for mismatched lengths, t_to ≤ t_from or bad
/// options.
ChannelIntegral integrate_channel(std::span<const double> t, std::span<const double> x,
                                  double t_from_s, double t_to_s,
                                  const ChannelIntegralOptions& options = {});

}  // namespace dynpos::ident
