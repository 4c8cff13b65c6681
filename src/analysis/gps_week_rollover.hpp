#pragma once
// A GPS receiver whose firmware predates a week-number rollover (the last on 2019-04-06) dates
// its fixes 1024 weeks (7168 days, 19.6 years) early. Two files aligned by their absolute time
// stamps are checked for it (private to the module: the log's files, the antennas' captures).

#include <cstdint>

#include "dynpos/core/log.hpp"
#include "dynpos/io/input_report.hpp"

namespace dynpos::analysis::detail {

/// One GPS week-number cycle, 1024 weeks [ns].
inline constexpr std::int64_t kGpsWeekCycleNs = std::int64_t{1024} * 7 * 86400 * 1'000'000'000;

/// The difference of two absolute origins [s], part − main, with `cycles` GPS week cycles (at
/// most 3) added to the part's: exact in integer nanoseconds, in floating point where that would
/// overflow (origins centuries apart, which no overlap check then accepts).
double origin_offset_s(std::int64_t main_ns, std::int64_t part_ns, int cycles);

/// Two files with absolute stamps, their logs relative to their origins, that overlap only when
/// one is moved by whole GPS week cycles (1 to 3): a receiver's week-number rollover. Returns
/// the cycles to add to the part's stamps (positive: the part's dates are early; negative: the
/// main log's), noted in `part_report`, or 0 (overlapping as dated, or by no whole cycles).
/// With `strict` a rollover is a core::InputError naming part_report.path.
int gps_week_rollover_cycles(const core::Log& main, std::int64_t main_origin_ns,
                             const core::Log& part, std::int64_t part_origin_ns,
                             double user_offset_s, bool strict, io::FileReport& part_report);

}  // namespace dynpos::analysis::detail
