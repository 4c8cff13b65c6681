#pragma once
/// \file
/// Where an analysis reads its log from: a CSV file, a column map file, and ROLE=COLUMN /
/// ROLE=UNIT overrides; for logs whose header already uses role names (dynpos' own logs), the
/// roles found by name. Roles may come from other files (ROLE=COLUMN@FILE), each with its own
/// time column and clock offset, aligned on the main log's time axis (read_log_files).

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dynpos/core/log.hpp"
#include "dynpos/core/parallel_for.hpp"
#include "dynpos/ident/local_position.hpp"
#include "dynpos/ident/station_keeping.hpp"
#include "dynpos/io/column_map.hpp"
#include "dynpos/io/input_report.hpp"
#include "dynpos/io/log_file.hpp"

namespace dynpos::analysis {

/// Accepts the roles an analysis wants to pick up by name from the log's header.
using RoleFilter = std::function<bool(const std::string& role)>;

/// A log as read, and what was read to make it.
struct LoadedLog {
  core::Log log;
  io::InputReport input;
  /// The main log's first row and its last row [s] on the log's axis. When only a window was
  /// read (LogSource::window_from_s/window_to_s), `log` holds the rows inside it, while these
  /// still tell how far the file reaches: log_end_s is then the first row after the window.
  double log_start_s = 0.0;
  double log_end_s = 0.0;
};

struct LogSource {
  std::filesystem::path log;  ///< the CSV log (NMEA capture, ROS 2 bag), as the user named it
  /// Where the bytes of `log` are read from when `log` can be read only once (standard input
  /// "-", a pipe, a FIFO): a copy made once (io::SpooledInput). Empty: `log` itself. Messages
  /// and reports name `log` either way.
  std::filesystem::path read_from;
  std::filesystem::path map_file;    ///< column map (TOML), or empty
  std::vector<std::string> columns;  ///< ROLE=COLUMN
  std::vector<std::string> units;    ///< ROLE=UNIT
  /// FILE=SECONDS, added to the times of FILE (named by a ROLE=COLUMN@FILE).
  std::vector<std::string> clock_offsets;
  /// Largest gap [s] between two samples of a role from another file that is bridged when it
  /// is put on the main log's time axis; 0 = automatic (2.5 × that role's median spacing).
  double max_gap_s = 0.0;
  /// "auto" (by content), "csv", "nmea" (NMEA 0183 capture), "mcap" or "db3" (ROS 2 bags, MCAP
  /// or rosbag2 SQLite: a role's column is TOPIC.FIELD, io/bag_log.hpp, io/db3_log.hpp).
  std::string format = "auto";
  /// The time of a bag's messages: "auto" (header.stamp when the type has one, else the
  /// receive time), "header" or "receive" (io/bag_time.hpp).
  std::string bag_time = "auto";
  /// Folders of .msg files for message types a bag does not define (io/ros2_msg_set.hpp).
  std::vector<std::filesystem::path> msg_path;
  /// An NMEA line that cannot be used is an error, and so are files whose absolute stamps are
  /// whole GPS week cycles apart (a receiver's week-number rollover; else aligned and noted).
  bool strict = false;
  std::string time_format = {};  ///< --time-format; empty = the map's (auto)
  std::string date = {};         ///< --date YYYY-MM-DD; empty = the map's (none)
  std::string time_order = {};   ///< --time-order; empty = the map's (error)
  /// Only the main log's rows with time in [window_from_s, window_to_s] are read (a CSV file:
  /// rows before it are skipped, reading stops after it), so memory and time follow the window,
  /// not the file; roles from other files are put on those rows. Unset: the whole log. An NMEA
  /// capture or a log in memory is taken whole.
  std::optional<double> window_from_s;
  std::optional<double> window_to_s;
  /// Threads for reading the log and for an analysis' independent pieces (one fit per step);
  /// 0 = every core. Results do not depend on it.
  unsigned jobs = core::kEveryCore;
  /// A log already in memory (SI, channels named by role), used instead of the file `log`:
  /// what a program or the Python API built from arrays. Every channel is taken, by its name
  /// or as `columns` renames it (ROLE=CHANNEL); units, maps and time options do not apply.
  /// `log` names it in reports.
  std::shared_ptr<const core::Log> memory;

  /// The map from map_file, then columns/units and the time options; `time` defaults to the
  /// column "time" unless time.sec is mapped.
  io::ColumnMap base_map() const;

  /// base_map(). Then every
  /// header column whose name is a role accepted by `wanted` and not yet mapped is mapped to
  /// itself (so "thrust.port [kN]" in a dynpos log needs no --col).
  io::ColumnMap column_map(const RoleFilter& wanted) const;

  /// Reads the log with column_map(wanted) and read_log_files() (an NMEA capture: its default
  /// role mapping, io/nmea_log.hpp), and reports the files, formats, time stamps (form, notes,
  /// origin), skipped lines and each role's origin and rate. With a window, only its rows:
  /// a CSV file is read within it, a capture or a log in memory is cut to it. The one place a
  /// window is judged: an empty window (to ≤ from) or one without a row of the log is an
  /// error of the request key "from/to" in the log, naming the log's time span.
  LoadedLog load(const RoleFilter& wanted) const;

  /// Whether a window is set (either end).
  bool has_window() const noexcept { return window_from_s || window_to_s; }

  /// `e` as an error of this log: a location without a file is given `log` (as the user named
  /// it), the copy read_from is renamed to it; line, column and option are kept. Every
  /// analysis names its log in errors through this.
  core::InputError in_log(const core::InputError& e) const;

  /// An error about the log's role or column `column` (e.g. "north/east", "col:output" for a
  /// mapping the user should give): the file is `log`.
  core::InputError error(const std::string& column, const std::string& problem,
                         const std::string& hint = {}) const;

  /// load(wanted).log.
  core::Log read(const RoleFilter& wanted) const;

  /// Whether load(wanted) gives `role`: a column mapped to it (or, for a file, a header column
  /// of that name that `wanted` accepts); for a log in memory, a channel of that name or one
  /// renamed to it. Reads only the header of a file.
  bool gives(const std::string& role, const RoleFilter& wanted) const;

  /// {max_gap_s}, checked: throws option_error("max_gap") if it is negative or NaN.
  core::ResampleOptions resample_options() const;

  /// The file to open for `log`: read_from when set, else log.
  const std::filesystem::path& file() const noexcept { return read_from.empty() ? log : read_from; }
};

/// Reads the roles `map` assigns to the main log (time axis of the result) and to each other
/// file (ColumnMap::other_files), each on its own time column + clock offset, resampled onto
/// the main log's times by the role's Interp (angles along the shorter arc, commands held, the
/// rest linear; NaN outside a file's range and across gaps wider than options.max_gap_s). The
/// report lists every file (the main log first) and each role's file and rate on its own clock.
/// Throws core::InputError naming the file for a missing file or column, and for a file whose
/// times do not overlap the main log's; a partial overlap, or a role with no sample on the
/// main log's axis, is a note in the file's report. Any of the files may be an NMEA 0183
/// capture (io::read_log_file: the main log as `how` says, the others detected by content);
/// how.strict makes any unusable line of a capture an error.
LoadedLog read_log_files(const std::filesystem::path& main_log, const io::ColumnMap& map,
                         const core::ResampleOptions& options = {},
                         const io::LogFileRead& how = {});

/// The InputReport of a log read from one file: `file_report` completed with the path and the
/// record count, and every channel as a role from that file with its median rate. The passes
/// over a long log run on `jobs` threads (0 = every core); the report does not depend on it.
io::InputReport describe_input(const core::Log& log, const std::string& file,
                               io::FileReport file_report, unsigned jobs);

/// `input` with each file path below `base` made relative to it, e.g. for a report folder that
/// moves with its logs; other paths stay as they are.
io::InputReport relative_to(io::InputReport input, const std::filesystem::path& base);

/// Thruster names NAME of the channels "PREFIX.NAME" of a log, in channel order, unique.
std::vector<std::string> thruster_names(const core::Log& log, const std::string& prefix);

/// The channel's values, or empty when the log does not have it (missing, never zero).
std::vector<double> values_or_empty(const core::Log& log, const std::string& name);

/// The position [m]: north/east as logged (any offset), else lat/lon made local about their
/// first fix; nullopt when the log has neither pair.
std::optional<ident::LocalPositions> local_position(const core::Log& log);

/// The thrusters with a thrust.NAME or power.NAME channel: thrust names first, then power-only
/// ones.
std::vector<std::string> thrust_power_names(const core::Log& log);

/// Each thruster of thrust_power_names() with both series, empty where the log lacks one.
std::vector<ident::ThrusterChannels> thrust_power_channels(const core::Log& log);

}  // namespace dynpos::analysis
