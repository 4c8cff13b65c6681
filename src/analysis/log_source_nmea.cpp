#include "log_source_nmea.hpp"

#include "dynpos/core/error.hpp"
#include "dynpos/io/nmea_log.hpp"
#include "log_files.hpp"

namespace dynpos::analysis {

bool reads_nmea(const LogSource& source) {
  if (source.format == "nmea") return true;
  if (source.format == "csv") return false;
  if (source.format == "mcap" || source.format == "db3") return false;
  if (source.format != "auto") {
    throw core::InputError::for_option(
        "format", "unknown log format '" + source.format + "'",
        "use auto (detected from the content), csv, nmea (NMEA 0183 capture), mcap or db3 "
        "(ROS 2 bags: MCAP, rosbag2 SQLite)");
  }
  return io::looks_like_nmea(source.file());
}

LoadedLog load_nmea(const LogSource& source, const RoleFilter& wanted) {
  // A column map may only add roles of further files: the capture's roles are its sentences'.
  const bool more_files =
      !source.map_file.empty() || !source.columns.empty() || !source.units.empty();
  io::ColumnMap map;
  if (more_files) {
    map = source.base_map();
    for (const auto& [role, entry] : map.roles()) {
      if (role == "time" || !entry.file.empty()) continue;
      throw core::InputError::for_option(
          source.map_file.empty() ? (source.columns.empty() ? "unit" : "col") : "map",
          "role '" + role + "' is mapped to a column of " + source.log.string() +
              ", an NMEA capture",
          "an NMEA capture's roles come from its sentences (docs/log-format.md, \"NMEA "
          "captures\"); map roles of other files only (--col ROLE=COLUMN@FILE), or give "
          "--format csv");
    }
    map.validate();
  }
  io::NmeaLogOptions options;
  options.strict = source.strict;
  // A role another file gives is not also taken from the capture.
  options.wanted = [&](const std::string& channel) {
    const io::RoleColumn* other = map.find(channel);
    return wanted(channel) && (other == nullptr || other->file.empty());
  };
  io::NmeaLog read = io::read_nmea_log(source.file(), options);
  const std::size_t sentences = read.report.records;
  io::InputReport input =
      describe_input(read.log, source.log.string(), std::move(read.report), source.jobs);
  input.files.front().records = sentences;  // sentences used, not rows of the time axis
  input.origin = read.origin;
  if (read.origin) input.origin_zone = "UTC";
  LoadedLog out{std::move(read.log), std::move(input)};
  if (!out.log.time().empty()) {
    out.log_start_s = out.log.time().front();
    out.log_end_s = out.log.time().back();
  }
  if (more_files) {
    add_log_files(out, read.origin_ns, map, source.resample_options(),
                  io::LogFileRead{io::LogFileRead::Format::kAuto,
                                  source.strict,
                                  source.jobs,
                                  {},
                                  {},
                                  io::find_bag_time(source.bag_time).value_or(io::BagTime::kAuto),
                                  source.msg_path});
  }
  return out;
}

}  // namespace dynpos::analysis
