#pragma once
/// \file
/// Trace: the time series a case study keeps for plots.
///
/// Unlike core::Log, time here is non-decreasing rather than strictly increasing: at a jump the
/// trace holds two rows at the same instant, the state just before and just after, so a plot
/// draws the jump as a vertical step instead of a slope across the logging interval.

#include <string>
#include <string_view>
#include <vector>

#include "dynpos/core/log.hpp"

namespace dynpos::hybrid {

/// Named channels on a shared, non-decreasing time axis.
struct Trace {
  std::vector<double> t;                ///< [s], non-decreasing
  std::vector<core::Channel> channels;  ///< each with one value per time

  /// The channel called `name`. Throws std::out_of_range naming it if there is none.
  const core::Channel& channel(std::string_view name) const;
  /// Shorthand for channel(name).values.
  const std::vector<double>& values(std::string_view name) const { return channel(name).values; }
  bool has(std::string_view name) const noexcept;
  std::size_t size() const noexcept { return t.size(); }
};

}  // namespace dynpos::hybrid
