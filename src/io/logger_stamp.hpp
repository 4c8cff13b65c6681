#pragma once
// The time stamp a logger writes before each captured NMEA line (private to the module; a
// general time-stamp parser can replace it).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "time_units.hpp"

namespace dynpos::io::detail {

/// Nanoseconds in one day.
inline constexpr std::int64_t kDay_ns = kNsPerDay;

/// A logger time stamp read as an instant.
struct LoggerStamp {
  std::int64_t unix_ns = 0;  ///< [ns] since 1970-01-01T00:00:00Z
  std::string form;          ///< "iso8601" or "epoch seconds"
  bool zone_given = true;    ///< false for an ISO 8601 stamp without Z or ±hh:mm (read as UTC)
};

/// "YYYY-MM-DDTHH:MM:SS[.f…][Z|±hh:mm]" (a space may replace the T) or epoch seconds with up to
/// nine decimals ("1714557600.123"); nullopt for any other text or an impossible date or time.
std::optional<LoggerStamp> parse_logger_stamp(std::string_view text);

/// The stamp at the end of `prefix` (the text before a sentence's '$'): its last
/// whitespace-, comma- or semicolon-separated token, or its last two joined by a space
/// ("2024-05-01 10:00:00.123"); words before it (a logger or channel name) are ignored.
std::optional<LoggerStamp> find_logger_stamp(std::string_view prefix);

/// `unix_ns` as "YYYY-MM-DDTHH:MM:SS.fffZ" (more decimals when the instant has them).
std::string iso8601_utc(std::int64_t unix_ns);

}  // namespace dynpos::io::detail
