#pragma once
/// \file
/// Streaming CSV log reader: loads only the mapped columns (and an optional time window) of a
/// log that may be far larger than memory.
///
/// The file is read one line at a time (a regular file, after the first rows: in blocks on
/// several threads, any block that is not plain line by line, with the same result: see
/// src/io/csv_blocks.hpp); only the cells of mapped columns are parsed, and only rows inside the
/// window are stored. Numbers are parsed locale-independently ('.' decimal
/// point). Rules, in brief (details and examples in docs/log-format.md):
/// - the first line that is neither blank nor a comment is the header; later blank and comment
///   lines are skipped; CRLF line ends, a UTF-8 byte-order mark and quoted fields ("a,b", with
///   "" for a quote, also spanning lines) are handled;
/// - a blank cell, or one equal to a declared missing token, is missing (NaN), never zero;
/// - text in a number cell, or a literal nan/inf that is not a declared missing token, is an
///   error naming file:line:column and the header;
/// - time must be present in every row and strictly increasing (or the rows that are not are
///   dropped, as TimeStampOptions::order says); its form (seconds, epoch, ISO 8601, time of
///   day, seconds + nanoseconds) is detected from the first rows or forced (time_stamp.hpp);
/// - every row has as many fields as the header.
/// Every error is a core::InputError with file, line, column number and header name.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dynpos/core/error.hpp"
#include "dynpos/core/log.hpp"
#include "dynpos/io/column_map.hpp"
#include "dynpos/io/time_stamp.hpp"

namespace dynpos::io {

/// The longest row of a CSV log [bytes]: a line, or the lines a quoted field joins (8 MiB, e.g.
/// 200,000 cells of 40 characters). A longer one is an error naming its line, so a file without
/// line ends costs a bounded memory.
inline constexpr std::size_t kMaxCsvRecordBytes = std::size_t{8} << 20;

/// Options for read_csv() and read_csv_all().
struct CsvReadOptions {
  /// Keep only rows with t_from_s <= t [s, after unit conversion]; nullopt = from the start.
  std::optional<double> t_from_s;
  /// Keep only rows with t <= t_to_s [s]; reading stops at the first later row, so rows after
  /// the window are neither stored nor checked. nullopt = to the end.
  std::optional<double> t_to_s;
  /// Threads that parse a regular file's rows in blocks, 0 = every core. The result (values,
  /// errors, notes) is the same for any number.
  unsigned jobs = 0;

  /// Throws core::InputError if a bound is not finite or t_from_s > t_to_s.
  void validate() const;
};

/// A header cell split into its name and the unit text of a trailing "[unit]" or "(unit)";
/// unit is empty when there is none. "Speed [kn]" → {"Speed", "kn"}; "Heading (deg)" →
/// {"Heading", "deg"}; "Thrust" → {"Thrust", ""}.
struct HeaderCell {
  std::string name;
  std::string unit;
};
HeaderCell split_header_cell(std::string_view cell);

/// A CSV log as read, with what its time stamps turned out to be.
struct CsvLog {
  core::Log log;
  TimeStampInfo time;
  /// The time [s] of the file's first row, and of the last row read: with a window, the first
  /// row after it when there is one (reading stops there), so a caller knows whether the file
  /// goes on past the window without reading it.
  double first_row_s = 0.0;
  double last_row_read_s = 0.0;
};

/// No row of a CSV log lies inside the window of CsvReadOptions: an InputError naming the file,
/// with where the log is, so that a caller can say it in its own terms (e.g. of --from/--to).
class EmptyWindowError : public core::InputError {
 public:
  /// The times [s] of the log's first row and of the last row read.
  struct RowTimes {
    double first_row_s;
    double last_row_read_s;
  };
  EmptyWindowError(core::InputError error, RowTimes rows)
      : core::InputError(std::move(error)),
        first_row_s(rows.first_row_s),
        last_row_read_s(rows.last_row_read_s) {}
  double first_row_s;      ///< the log's first row [s]
  double last_row_read_s;  ///< its last row, or the first row after the window
};

/// Reads the mapped columns of a CSV log. Channels are named after their roles, in the order
/// of their columns in the file, converted to SI (unit: declared > header bracket > role
/// default) with the role's interpolation; time (or time.sec + time.nsec, with date for times
/// of day) is read as map.time() says. The window applies to the log's time axis (seconds
/// since the first row for absolute stamps). Throws core::InputError (see the file comment).
CsvLog read_csv_log(const std::filesystem::path& path, const ColumnMap& map,
                    const CsvReadOptions& options = {});

/// read_csv_log(path, map, options).log.
core::Log read_csv(const std::filesystem::path& path, const ColumnMap& map,
                   const CsvReadOptions& options = {});

/// Reads every numeric column of a CSV log, such as the ones write_csv() produces: the first
/// column is time (its form detected), each other column becomes a channel named after its header
/// name (without the unit). A known bracket unit is converted to SI; an unknown one is kept as
/// logged with its text as the channel unit; no bracket gives an empty unit. A column whose first
/// value is text is skipped as a whole; text later in a numeric column is an error. Channels whose
/// name is a role get the role's interpolation, others are linear.
core::Log read_csv_all(const std::filesystem::path& path, const CsvReadOptions& options = {},
                       const CsvFormat& format = {});

/// The header cells of a CSV log (trimmed, unquoted), e.g. to list the columns a map may use.
std::vector<std::string> read_csv_header(const std::filesystem::path& path,
                                         const CsvFormat& format = {});

}  // namespace dynpos::io
