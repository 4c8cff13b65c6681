#pragma once
/// \file
/// Time stamps of a log: which form a time column uses, and its cells read exactly.
///
/// Forms (TimeFormat; names as in --time-format and docs/log-format.md):
///   seconds      seconds from any origin, "12.5" (kept as logged: no origin)
///   epoch-s|ms|us|ns  Unix time, integer or decimal, e.g. 1714557600.25 or 1714557600250
///   iso8601      "2024-05-01T10:00:00.25Z": 'T' or ' ', '-' or '/', any fraction digits,
///                "Z", ±hh:mm, ±hhmm, ±hh, or no zone (then local time)
///   time-of-day  "10:00:00.25", the date from --date or a `date` column
///   sec-nsec     two columns: whole seconds (time.sec) and nanoseconds (time.nsec)
///
/// Absolute stamps are int64 nanoseconds (years 1678…2261) since 1970-01-01T00:00:00 (UTC when the
/// file gives a zone, the local wall clock otherwise), computed with integers only, so a 2024 epoch
/// in nanoseconds keeps every digit (a double holds ~16 digits: 0.2 µs at 2024). The log's time is
/// then t = (stamp − origin)·1e-9 s with origin = the first row's stamp: exact to 1 ns over
/// 104 days (2⁵³ ns). Parsing uses std::from_chars and our own digit loops: locale-independent.
///
/// Exporter bug read right: some loggers write "sec.nsec" with the nanoseconds as an integer
/// without zero padding, so 16.079441101 s appears as "16.79441101". Read as a decimal such a
/// column runs backwards within each second; detect_time_format() recognises it (fraction
/// lengths vary, the decimal reading goes back, the nanosecond reading does not) and
/// TimeStampFormat::unpadded_ns makes it read as seconds + nanoseconds.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dynpos/core/error.hpp"
#include "dynpos/io/input_report.hpp"

namespace dynpos::io {

/// The form of a time column.
enum class TimeFormat {
  kAuto,  ///< detect from the first rows
  kSeconds,
  kEpochSeconds,
  kEpochMillis,
  kEpochMicros,
  kEpochNanos,
  kIso8601,
  kTimeOfDay,
  kSecNsec,
};

/// What to do with a row whose time is not after the previous kept row's.
enum class TimeOrder {
  kError,              ///< core::InputError naming the file, line and column (default)
  kDropDuplicates,     ///< drop a row repeating the previous time; going back is an error
  kDropNonIncreasing,  ///< drop every row not after the last kept one (duplicates, jumps back)
};

/// "seconds", "epoch-s", "epoch-ms", "epoch-us", "epoch-ns", "iso8601", "time-of-day",
/// "sec-nsec"; "auto" for kAuto.
std::string_view time_format_name(TimeFormat format) noexcept;
/// The format named `name` (as time_format_name()), or nullopt.
std::optional<TimeFormat> find_time_format(std::string_view name) noexcept;
/// The accepted names, for hints: "auto, seconds, epoch-s, ...".
std::string time_format_names();

/// "error", "drop-duplicates", "drop-non-increasing".
std::string_view time_order_name(TimeOrder order) noexcept;
std::optional<TimeOrder> find_time_order(std::string_view name) noexcept;

/// How a file's time stamps are read; filled from --time-format/--date/--time-order or the
/// [time] table of a column map.
struct TimeStampOptions {
  TimeFormat format = TimeFormat::kAuto;
  /// Date of time-of-day stamps, "YYYY-MM-DD" (or "YYYY/MM/DD"); empty = none.
  std::string date;
  TimeOrder order = TimeOrder::kError;

  /// Throws core::InputError if `date` is not empty and not a valid calendar date.
  void validate() const;
};

/// A detected or forced form.
struct TimeStampFormat {
  TimeFormat format = TimeFormat::kSeconds;
  /// seconds, epoch-s and iso8601 only: the fraction is integer nanoseconds without zero
  /// padding.
  bool unpadded_ns = false;
};

/// Days since 1970-01-01 of a proleptic Gregorian date (H. Hinnant's days_from_civil), exact
/// for any int32 year; the date is not checked (see is_valid_date()).
constexpr std::int64_t days_from_civil(std::int64_t y, unsigned m, unsigned d) noexcept {
  y -= m <= 2 ? 1 : 0;
  const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
  const auto yoe = static_cast<unsigned>(y - era * 400);                 // [0, 399]
  const unsigned doy = (153 * (m > 2 ? m - 3 : m + 9) + 2) / 5 + d - 1;  // [0, 365]
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;            // [0, 146096]
  return era * 146097 + static_cast<std::int64_t>(doe) - 719468;
}

/// A date of the proleptic Gregorian calendar as written: year, month 1…12, day 1…31.
struct CivilDate {
  std::int64_t year = 1970;
  unsigned month = 1;
  unsigned day = 1;
};

/// True for a real date of the proleptic Gregorian calendar (29 February in leap years only).
bool is_valid_date(const CivilDate& date) noexcept;

/// A stamp read from one cell: nanoseconds since 1970-01-01T00:00:00, UTC when utc_offset_min
/// is set (the cell's offset already removed), the local wall clock otherwise.
struct ParsedStamp {
  std::int64_t ns = 0;
  std::optional<int> utc_offset_min;  ///< the cell's zone: 0 for "Z", 120 for "+02:00"
  /// A leap second, "23:59:60.5Z": `ns` is then that of the next day's 00:00:00.5, the
  /// instant POSIX time gives it; TimeStampReader counts the extra second in the time axis.
  bool leap_second = false;
};

/// An ISO 8601 date-time: YYYY-MM-DD or YYYY/MM/DD, 'T' or one space, hh:mm[:ss[.f…]] (fraction
/// digits beyond 9 truncated), then nothing, "Z", ±hh:mm, ±hhmm or ±hh (optionally after one
/// space). A second 60 is a leap second: in the last minute of an hour without a zone, in the
/// last minute of the UTC day with one. nullopt if the text is not one or names an impossible
/// date or time.
std::optional<ParsedStamp> parse_iso8601(std::string_view text) noexcept;
/// Days since 1970-01-01 of "YYYY-MM-DD" or "YYYY/MM/DD"; nullopt if not a valid date.
std::optional<std::int64_t> parse_date_days(std::string_view text) noexcept;
/// Nanoseconds since midnight of "hh:mm:ss[.f…]" or "hh:mm"; nullopt otherwise.
std::optional<std::int64_t> parse_time_of_day_ns(std::string_view text) noexcept;
/// Exact nanoseconds of a decimal number of units of 10^-exponent s (exponent 0: s, 3: ms, 6:
/// µs, 9: ns), e.g. ("1714557600.25", 0) → 1714557600250000000; digits below 1 ns truncated,
/// an exponent ('e') read through a double. nullopt if not a number or out of int64 range.
std::optional<std::int64_t> parse_decimal_ns(std::string_view text, int exponent) noexcept;
/// "S.N" with N integer nanoseconds, unpadded: "16.79441101" → 16 079 441 101 ns; nullopt if
/// not that form or N ≥ 10⁹.
std::optional<std::int64_t> parse_unpadded_ns(std::string_view text) noexcept;

/// "YYYY-MM-DDThh:mm:ss[.fff[fff[fff]]]" of `ns` shown at UTC offset `offset_min` (suffix "Z"
/// for 0, "+hh:mm" otherwise, none when nullopt: a local time).
std::string format_iso8601(std::int64_t ns, std::optional<int> utc_offset_min);

/// The form of a time column from its first cells (blank cells ignored): ISO 8601, time of day
/// or a number; a number of 1e9…1e10 is epoch-s, 1e12…1e13 epoch-ms, 1e15…1e16 epoch-us,
/// 1e18…1e19 epoch-ns, anything else seconds; then the unpadded-nanosecond check for seconds
/// and epoch-s. nullopt if the first cell is none of these.
std::optional<TimeStampFormat> detect_time_format(std::span<const std::string_view> cells);
/// True on systematic evidence that the cells are "S.N" with N integer nanoseconds without
/// leading zeros: read so they never go back; read as decimals they go back, only where the
/// fraction grows longer; and the median step of the nanosecond reading is at least a tenth of
/// the decimal reading's (one row out of order among decimals fails this).
bool looks_like_unpadded_ns(std::span<const std::string_view> cells);
/// The same evidence for ISO 8601 stamps whose fraction is unpadded nanoseconds
/// ("2025/04/28 11:39:17.78903511" is 17.078903511 s).
bool looks_like_unpadded_iso8601(std::span<const std::string_view> cells);
/// parse_iso8601() with the fraction read as integer nanoseconds (at most 9 digits).
std::optional<ParsedStamp> parse_iso8601_unpadded_ns(std::string_view text) noexcept;

/// One row's time cells: the time column (time.sec for sec-nsec), and the time.nsec and date
/// columns when mapped.
struct TimeCells {
  std::string_view time;
  std::string_view nsec;
  std::string_view date;
};

/// Rows whose first time cells detect_time_format() looks at.
inline constexpr std::size_t kTimeDetectionRows = 256;

/// Where a file's time column is (for messages) and which companion columns it has.
struct TimeColumnSpec {
  std::string file;       ///< path as the user gave it
  std::string column;     ///< header text of the time (or time.sec) column
  std::size_t field = 0;  ///< 0-based field index
  bool has_nsec = false;  ///< a time.nsec column is mapped (two-column form)
  bool has_date = false;  ///< a date column is mapped (dates of time-of-day stamps)
  /// The time unit the header, the map or --unit declares ("ms"), empty when none, and its
  /// length [s] (times the map's scale). Numbers in such a column are read as epoch time by
  /// their size only when that epoch form counts the declared unit (10¹² ms is epoch-ms); any
  /// other size is a count of the unit from any origin (an uptime counter in ms passes 10⁹,
  /// the size of epoch seconds, after 11.6 days).
  std::string declared_unit;
  double declared_unit_s = 0.0;
};

/// What a file's time stamps turned out to be, for io::FileReport and io::InputReport.
struct TimeStampInfo {
  std::string format;                     ///< e.g. "iso8601", "seconds (unpadded nanoseconds)"
  std::vector<std::string> notes;         ///< e.g. how an exporter bug was read
  LineCounts skipped;                     ///< rows dropped by the order policy
  std::optional<std::int64_t> origin_ns;  ///< absolute time of t = 0 (see ParsedStamp)
  std::optional<std::string> origin;      ///< origin_ns in ISO 8601
  std::string origin_zone;                ///< "UTC", "+02:00", "local (no zone in the file)"
};

/// Reads one file's time column, row by row, into seconds: a streaming reader calls
/// start() with the first rows' cells, then time_s() for every row. Relative forms (seconds,
/// sec-nsec below 1e9 s) stay as logged; absolute ones become seconds since the first row.
class TimeStampReader {
 public:
  TimeStampReader(TimeStampOptions options, TimeColumnSpec column);

  /// Fixes the format from the first rows' time cells (`lines`: their line numbers), forced or
  /// detected. Throws core::InputError if nothing fits or the options contradict the columns.
  void start(std::span<const std::string_view> first_cells, std::span<const std::size_t> lines);

  /// True for plain seconds: the caller parses the number itself (unit, scale, fast path) and
  /// passes it to accept().
  bool plain_seconds() const noexcept { return plain_seconds_; }

  /// The row's time [s]; throws core::InputError naming `line` for a bad cell.
  double time_s(const TimeCells& cells, std::size_t line);

  /// Applies the order policy to time `t` [s] of `line`: true to keep the row; false to drop it
  /// (counted); throws core::InputError under TimeOrder::kError.
  bool accept(double t, std::string_view cell, std::size_t line) {
    if (kept_ > 0 && !(t > last_t_)) return out_of_order(t, cell, line);
    last_t_ = t;
    last_line_ = line;
    ++kept_;
    return true;
  }

  /// Rows whose times are strictly increasing, for accept_increasing().
  struct IncreasingRows {
    double first_t = 0.0;       ///< the first row's time [s]
    double last_t = 0.0;        ///< the last row's time [s]
    std::size_t count = 0;      ///< how many rows
    std::size_t last_line = 0;  ///< the last row's line
  };

  /// accept() for rows whose times are strictly increasing: true, all of them kept, if their
  /// first time is after the last kept time; false, nothing changed, if it is not (then
  /// accept() them one by one).
  bool accept_increasing(const IncreasingRows& rows) {
    if (kept_ > 0 && !(rows.first_t > last_t_)) return false;
    last_t_ = rows.last_t;
    last_line_ = rows.last_line;
    kept_ += rows.count;
    return true;
  }

  /// The format name, notes, dropped rows and origin.
  const TimeStampInfo& info() const noexcept { return info_; }

 private:
  bool out_of_order(double t, std::string_view cell, std::size_t line);
  std::int64_t absolute_ns(const TimeCells& cells, std::size_t line);
  [[noreturn]] void bad_cell(std::string_view cell, std::size_t line, std::string_view what,
                             std::string hint) const;
  core::InputLocation where(std::size_t line) const;
  void set_origin(std::int64_t ns, std::optional<int> utc_offset_min);
  std::int64_t leap_seconds_ns(bool leap_second, std::size_t line);

  TimeStampOptions options_;
  TimeColumnSpec column_;
  TimeStampFormat format_;
  bool plain_seconds_ = true;
  bool absolute_ = false;  // t relative to the origin, else as logged
  std::optional<std::int64_t> date_days_;
  std::optional<bool> zoned_;  // whether the first ISO stamp had a zone
  std::int64_t origin_ns_ = 0;
  std::int64_t previous_tod_ns_ = -1;
  std::int64_t rollover_days_ = 0;
  std::int64_t leap_ns_ = 0;  // leap seconds passed, added to later stamps
  bool in_leap_second_ = false;
  double last_t_ = 0.0;
  std::size_t last_line_ = 0;
  std::size_t kept_ = 0;
  TimeStampInfo info_;
};

/// A whole time column read at once (for readers that hold a file's cells): the times [s] of
/// the kept rows, `kept[i]` whether row i was kept, and the info. `lines` are the rows' line
/// numbers for messages. Throws core::InputError as TimeStampReader does.
struct TimeColumn {
  std::vector<double> t_s;
  std::vector<bool> kept;
  TimeStampInfo info;
};
TimeColumn read_time_column(std::span<const TimeCells> cells, std::span<const std::size_t> lines,
                            const TimeStampOptions& options, const TimeColumnSpec& column);

}  // namespace dynpos::io
