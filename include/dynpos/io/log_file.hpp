#pragma once
/// \file
/// One file of a log: the roles a column map assigns to it, on the file's own time axis.
///
/// A log may be spread over several files (one per device or topic, each with its own rate and
/// time column). Reading one of them is this one function, whatever its format; aligning the
/// files on the main log's clock is analysis::read_log_files (analysis/log_source.hpp).

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "dynpos/core/log.hpp"
#include "dynpos/io/column_map.hpp"
#include "dynpos/io/input_report.hpp"

namespace dynpos::io {

/// One file as read: its roles on its own clock (no offset applied), and its report.
struct FileLog {
  core::Log log;
  FileReport report;  ///< path as given, format, time_format, records; clock_offset_s is 0
  /// Absolute time of the file's t = 0 [ns since 1970-01-01 UTC] when its stamps are absolute
  /// (io/time_stamp.hpp), with its ISO 8601 text and zone; absent for relative seconds.
  std::optional<std::int64_t> origin_ns;
  std::optional<std::string> origin;
  std::string origin_zone;
};

/// Reads the roles of `map` (one file's map, e.g. ColumnMap::for_file) from `path`, with `time`
/// its time axis. CSV, with its time stamps read as map.time() says (read_csv_log). Throws
/// core::InputError naming the file, line and column.
FileLog read_log_file(const std::filesystem::path& path, const ColumnMap& map);

}  // namespace dynpos::io
