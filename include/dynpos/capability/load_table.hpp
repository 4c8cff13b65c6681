#pragma once
/// \file
/// A table of environmental loads to hold, for `capability --loads`: a CSV file with the columns
/// direction_deg, X_N, Y_N, N_Nm (in any order; BODY: X forward, Y to starboard, N clockwise
/// seen from above), one row per load. Blank lines and lines starting with '#' are skipped.

#include <string>
#include <vector>

#include "dynpos/capability/feasibility.hpp"

namespace dynpos::capability {

/// Longest line and most rows of a load table.
inline constexpr std::size_t kMaxLoadLineBytes = 64 * 1024;
inline constexpr std::size_t kMaxLoadRows = 100'000;

/// The rows of the load table at `path`. Throws core::InputError naming the file, line and
/// column of the first bad cell (not a finite number, a missing or extra field), a header
/// without the four columns, a file that is not a regular file, or no row.
std::vector<LoadCase> read_load_table(const std::string& path);

}  // namespace dynpos::capability
