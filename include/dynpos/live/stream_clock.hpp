#pragma once
/// \file
/// The stream time of a live log, read from its lines as they arrive, so that a live session
/// re-runs its analysis by the log's clock and not by the wall clock (a replay at 20× real time
/// then does the work of the trial itself): the UTC of an NMEA sentence (GGA, RMC, ZDA, GLL) or
/// the logger stamp before it, or the time column of a CSV log. It is only a schedule: the
/// analyses read the times themselves.

#include <optional>
#include <string>
#include <string_view>

namespace dynpos::live {

class StreamClock {
 public:
  /// `csv_time_column`: the header name of a CSV log's time column (a header cell equal to it,
  /// or to it followed by " [unit]").
  explicit StreamClock(std::string csv_time_column) : time_column_(std::move(csv_time_column)) {}

  /// The time [s] `line` carries (seconds on the log's own scale: relative seconds, seconds
  /// since 1970, or UTC seconds of the day, continued past midnight), or nullopt for a line
  /// without one (a header, an untimed sentence, a time that cannot be read).
  std::optional<double> read(std::string_view line);

 private:
  std::optional<double> read_nmea(std::string_view line, std::size_t dollar);
  std::optional<double> read_csv(std::string_view line);

  std::string time_column_;
  char delimiter_ = ',';
  std::optional<std::size_t> column_index_;  // set once the CSV header is seen
  double day_offset_s_ = 0.0;                // NMEA: 86400 per midnight passed
  std::optional<double> last_utc_s_;
};

/// "hhmmss[.ss]" → seconds since 00:00; nullopt for another text.
std::optional<double> nmea_time_of_day(std::string_view field) noexcept;

}  // namespace dynpos::live
