#pragma once
/// \file
/// Whether a time axis is usable: every time finite and later than the one before.

#include <cstddef>
#include <span>

namespace dynpos::core {

/// The first index i where t[i] is not finite or not later than t[i − 1]; t.size() when there is
/// none. One read of the axis: a day at 100 Hz (69 MB) takes about 17 ms, the memory's speed.
std::size_t first_unordered_time(std::span<const double> t) noexcept;

/// first_unordered_time(), the axis checked in pieces on `jobs` threads (0 = every core).
std::size_t first_unordered_time(std::span<const double> t, unsigned jobs);

}  // namespace dynpos::core
