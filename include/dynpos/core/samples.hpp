#pragma once
/// \file
/// A series' samples among its missing values (NaN, core::kMissing): whether it has one, and the
/// series held from each sample over the gaps after it.

#include <vector>

namespace dynpos::core {

/// Whether `x` has a value that is not NaN.
bool has_valid_sample(const std::vector<double>& x) noexcept;

/// A series held: at each row the last sample at or before it, and that sample's time.
struct HeldSamples {
  std::vector<double> value;      ///< NaN where the last sample is older than the hold
  std::vector<double> sampled_s;  ///< [s], NaN where value is
};

/// `x` on the time axis `t_s` [s] held for at most max_hold_s [s] after each sample.
HeldSamples hold_samples(const std::vector<double>& t_s, const std::vector<double>& x,
                         double max_hold_s);

}  // namespace dynpos::core
