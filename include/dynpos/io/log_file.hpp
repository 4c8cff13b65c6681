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
#include <vector>

#include "dynpos/core/log.hpp"
#include "dynpos/io/bag_time.hpp"
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
  /// The time [s] of the file's first row and of the last row read (CsvLog): with a window,
  /// the first row after it when the file goes on.
  double first_row_s = 0.0;
  double last_row_read_s = 0.0;
  /// A bag's other topics, each like a file of its own (io/bag_log.hpp); empty for others.
  std::vector<FileLog> more;
};

/// How read_log_file() takes a file.
struct LogFileRead {
  enum class Format { kAuto, kCsv, kNmea, kMcap, kDb3 };
  /// kAuto: a ROS 2 bag when io::looks_like_mcap or io::looks_like_db3 (a rosbag2 SQLite file
  /// or bag folder), an NMEA capture when io::looks_like_nmea, else CSV.
  Format format = Format::kAuto;
  bool strict = false;  ///< an NMEA line that cannot be used is an error
  unsigned jobs = 0;    ///< threads for reading a CSV file and describing it, 0 = every core
  /// Only the rows of a CSV file with time in [t_from_s, t_to_s] (its own axis) are read
  /// (CsvReadOptions); an NMEA capture is read whole.
  std::optional<double> t_from_s;
  std::optional<double> t_to_s;
  BagTime bag_time = BagTime::kAuto;  ///< the time of a bag's messages
  /// Folders of .msg files for the types a bag does not define (io/ros2_msg_set.hpp).
  std::vector<std::filesystem::path> msg_path;
};

/// Reads the roles of `map` (one file's map, e.g. ColumnMap::for_file) from `path`, with `time`
/// its time axis. A CSV file has its time stamps read as map.time() says (read_csv_log). An
/// NMEA 0183 capture (`how`) is read by io::read_nmea_log, strict as `how` says: its
/// time is that of its sentences (or logger stamps), a role's column names a channel of the
/// capture (lat, lon, height, heading, roll, pitch, down, r; SI, so no unit or scale), and
/// `time` is not read. A ROS 2 bag is read by io::read_bag_file (MCAP) or io::read_db3_bag
/// (SQLite), its topics in FileLog::more. Throws core::InputError naming the file, line and column.
FileLog read_log_file(const std::filesystem::path& path, const ColumnMap& map,
                      const LogFileRead& how = {});

}  // namespace dynpos::io
