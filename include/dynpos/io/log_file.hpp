#pragma once
/// \file
/// One file of a log: the roles a column map assigns to it, on the file's own time axis.
///
/// A log may be spread over several files (one per device or topic, each with its own rate and
/// time column). Reading one of them is this one function, whatever its format; aligning the
/// files on the main log's clock is analysis::read_log_files (analysis/log_source.hpp).

#include <filesystem>

#include "dynpos/core/log.hpp"
#include "dynpos/io/column_map.hpp"
#include "dynpos/io/input_report.hpp"

namespace dynpos::io {

/// One file as read: its roles on its own clock (no offset applied), and its report.
struct FileLog {
  core::Log log;
  FileReport report;  ///< path as given, format, time_format, records; clock_offset_s is 0
};

/// Reads the roles of `map` (one file's map, e.g. ColumnMap::for_file) from `path`, with `time`
/// its time axis. CSV for now (read_csv). Throws core::InputError naming the file, line and
/// column.
FileLog read_log_file(const std::filesystem::path& path, const ColumnMap& map);

}  // namespace dynpos::io
