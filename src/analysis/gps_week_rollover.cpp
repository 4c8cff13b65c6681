#include "gps_week_rollover.hpp"

#include <cstdlib>
#include <string>

#include <fmt/format.h>

#include "dynpos/core/error.hpp"

namespace dynpos::analysis::detail {
namespace {

bool overlaps(const core::Log& main, const core::Log& part, double offset_s) {
  return !main.time().empty() && !part.time().empty() &&
         part.time().back() + offset_s >= main.time().front() &&
         part.time().front() + offset_s <= main.time().back();
}

}  // namespace

double origin_offset_s(std::int64_t main_ns, std::int64_t part_ns, int cycles) {
  std::int64_t ns = 0;
  if (__builtin_sub_overflow(part_ns, main_ns, &ns) ||
      __builtin_add_overflow(ns, cycles * kGpsWeekCycleNs, &ns)) {
    return (static_cast<double>(part_ns) - static_cast<double>(main_ns)) * 1e-9 +
           cycles * static_cast<double>(kGpsWeekCycleNs) * 1e-9;
  }
  return static_cast<double>(ns) * 1e-9;
}

int gps_week_rollover_cycles(const core::Log& main, std::int64_t main_origin_ns,
                             const core::Log& part, std::int64_t part_origin_ns,
                             double user_offset_s, bool strict, io::FileReport& part_report) {
  const auto fits = [&](int cycles) {
    return overlaps(main, part,
                    origin_offset_s(main_origin_ns, part_origin_ns, cycles) + user_offset_s);
  };
  if (fits(0)) return 0;
  for (const int cycles : {1, -1, 2, -2, 3, -3}) {
    if (!fits(cycles)) continue;
    const int weeks = 1024 * std::abs(cycles);
    const std::string what = fmt::format(
        "its absolute time stamps are {} weeks ({:.1f} years) {} the main log's: {} those of a "
        "GPS receiver after a week-number rollover",
        weeks, weeks * 7 / 365.25, cycles > 0 ? "before" : "after",
        cycles > 0 ? "its dates are" : "the main log's dates are");
    if (strict) {
      core::InputLocation where;
      where.file = part_report.path;
      throw core::InputError(where, what + "; refused with --strict",
                             "correct the receiver's dates, or read without --strict to align "
                             "the files by the whole weeks");
    }
    part_report.notes.push_back(
        fmt::format("{}; aligned {} weeks {}", what, weeks, cycles > 0 ? "later" : "earlier"));
    return cycles;
  }
  return 0;
}

}  // namespace dynpos::analysis::detail
