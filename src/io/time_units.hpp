#pragma once
// Integer time units of the io readers (private to the module).

#include <cstdint>

namespace dynpos::io::detail {

inline constexpr std::int64_t kNsPerS = 1'000'000'000;       ///< nanoseconds in one second
inline constexpr std::int64_t kNsPerDay = 86'400 * kNsPerS;  ///< nanoseconds in one day

}  // namespace dynpos::io::detail
