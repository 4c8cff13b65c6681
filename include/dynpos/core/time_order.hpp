#pragma once
/// \file
/// Whether a time axis is usable: every time finite and later than the one before.

#include <cstddef>
#include <span>

namespace dynpos::core {

/// The first index i where t[i] is not finite or not later than t[i − 1]; t.size() when there is
/// none. Checked a chunk at a time without branches (vectorised), so a day at 100 Hz costs
/// about one read of the axis.
std::size_t first_unordered_time(std::span<const double> t) noexcept;

}  // namespace dynpos::core
