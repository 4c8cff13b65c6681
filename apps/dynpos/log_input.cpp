#include "log_input.hpp"

#include <memory>

#include "dynpos/io/spooled_input.hpp"

namespace dynpos::cli {

namespace {

// LOG: a file, or "-" for standard input. An input that can be read only once (standard
// input, a pipe, a FIFO) is copied once to a temporary file, which the readers open as often
// as they need; the copy lives as long as the command line (the App) and is removed with it.
void add_log_argument(CLI::App& sub, analysis::LogSource& source) {
  auto copy = std::make_shared<std::unique_ptr<io::SpooledInput>>();
  sub.add_option("log", source.log,
                 "Log: CSV, an NMEA 0183 capture or a ROS 2 bag (MCAP, or a rosbag2 SQLite "
                 ".db3 file or bag folder; detected by content); - reads standard input (a "
                 "pipe, e.g. from zcat)")
      ->required()
      ->check([](const std::string& value) {
        if (value == "-") return std::string();
        std::error_code ec;  // a bag folder, or a file
        return std::filesystem::is_directory(value, ec) ? CLI::ExistingDirectory(value)
                                                        : CLI::ExistingFile(value);
      })
      ->each([&source, copy](const std::string& value) {
        if (!io::needs_spool(value)) return;
        *copy = std::make_unique<io::SpooledInput>(value);
        source.read_from = (*copy)->path();
      });
}

// --time-format, --date and --time-order, filling `source`.
void add_time_options(CLI::App& sub, analysis::LogSource& source) {
  sub.add_option("--time-format", source.time_format,
                 "Time stamps: auto (default), seconds, epoch-s|ms|us|ns, iso8601, time-of-day, "
                 "sec-nsec");
  sub.add_option("--date", source.date, "Date of time-of-day stamps, YYYY-MM-DD");
  sub.add_option("--time-order", source.time_order,
                 "Repeated or backward times: error (default), drop-duplicates, "
                 "drop-non-increasing");
}

}  // namespace

void add_log_options(CLI::App& sub, analysis::LogSource& source, const std::string& roles_help,
                     LogMode mode) {
  if (mode == LogMode::kFile) add_log_argument(sub, source);
  add_log_source_options(sub, source, roles_help);
}

void add_log_source_options(CLI::App& sub, analysis::LogSource& source,
                            const std::string& roles_help) {
  sub.add_option("--map", source.map_file, "Column map (TOML): roles → columns, units, scales")
      ->check(CLI::ExistingFile);
  sub.add_option("--col", source.columns,
                 "ROLE=COLUMN or ROLE=COLUMN@FILE for a column of another file (repeatable; "
                 "time=COLUMN@FILE names FILE's time column; a bag's column is TOPIC.FIELD, "
                 "e.g. /gps/fix.latitude). Roles: " +
                     roles_help);
  sub.add_option("--unit", source.units, "ROLE=UNIT (repeatable), e.g. thrust.port=kN");
  sub.add_option("--clock-offset", source.clock_offsets,
                 "FILE=SECONDS (repeatable): added to FILE's times to put them on LOG's clock");
  sub.add_option("--max-gap", source.max_gap_s,
                 "Largest gap [s] bridged when a role of another file is put on LOG's time "
                 "axis (default: 2.5 x that role's median spacing)")
      ->check(CLI::NonNegativeNumber);
  sub.add_option("--format", source.format,
                 "Log format: auto (by content), csv, nmea, mcap or db3 (ROS 2 bags: MCAP, "
                 "rosbag2 SQLite)")
      ->default_str("auto");
  sub.add_option("--bag-time", source.bag_time,
                 "Time of a ROS 2 bag's messages: auto (header.stamp when the message has one, "
                 "else the receive time), header or receive")
      ->default_str("auto");
  sub.add_option("--msg-path", source.msg_path,
                 "Folder of .msg files (DIR/PKG/msg/TYPE.msg or DIR/TYPE.msg; repeatable) for "
                 "message types a bag does not define, beside the built-in ones")
      ->check(CLI::ExistingDirectory);
  sub.add_flag("--strict", source.strict,
               "An NMEA line that cannot be used is an error (file:line)");
  add_time_options(sub, source);
  sub.add_option("--jobs", source.jobs,
                 "Threads for reading and for independent fits (default 0: every core); the "
                 "results do not depend on it")
      ->check(CLI::Range(0u, 256u));
}

}  // namespace dynpos::cli
