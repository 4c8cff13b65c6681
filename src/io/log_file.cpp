#include "dynpos/io/log_file.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "dynpos/core/error.hpp"
#include "dynpos/io/bag_log.hpp"
#include "dynpos/io/csv_reader.hpp"
#include "dynpos/io/db3_log.hpp"
#include "dynpos/io/db3_reader.hpp"
#include "dynpos/io/mcap_reader.hpp"
#include "dynpos/io/nmea_log.hpp"

namespace dynpos::io {
namespace {

// The roles of `map` from the channels of an NMEA capture (named as read_nmea_log names them).
FileLog read_nmea_file(const std::filesystem::path& path, const ColumnMap& map, bool strict) {
  std::vector<std::pair<std::string, const RoleColumn*>> roles;
  for (const auto& [role, entry] : map.roles()) {
    if (role == "time") continue;  // the capture's own clock
    core::InputLocation where = entry.source;
    if (where.file.empty()) where.file = path.string();
    if (entry.unit || entry.scale != 1.0) {
      throw core::InputError(where,
                             fmt::format("role '{}' has a unit or scale, but {} is an NMEA "
                                         "capture, read in SI",
                                         role, path.string()),
                             "drop the unit and scale of roles read from an NMEA capture");
    }
    roles.emplace_back(role, &entry);
  }
  NmeaLogOptions options;
  options.strict = strict;
  options.wanted = [&roles](const std::string& channel) {
    return std::any_of(roles.begin(), roles.end(),
                       [&](const auto& r) { return r.second->column == channel; });
  };
  NmeaLog read = read_nmea_log(path, options);
  FileLog out{core::Log(read.log.time()),
              std::move(read.report),
              read.origin_ns,
              std::move(read.origin),
              read.origin_ns ? "UTC" : "",
              0.0,
              0.0,
              {}};
  if (!read.log.time().empty()) {
    out.first_row_s = read.log.time().front();
    out.last_row_read_s = read.log.time().back();
  }
  for (const auto& [role, entry] : roles) {
    if (!read.log.has(entry->column)) {
      core::InputLocation where = entry->source;
      if (where.file.empty()) where.file = path.string();
      throw core::InputError(
          where,
          fmt::format("role '{}': the capture has no '{}' (it gives {})", role, entry->column,
                      fmt::join(read.log.channel_names(), ", ")),
          "an NMEA capture's channels are lat, lon, height, heading, roll, pitch, down and r "
          "(docs/log-format.md, \"NMEA captures\")");
    }
    const core::Channel& c = read.log.channel(entry->column);
    out.log.add_channel(role, c.unit, c.values, c.interp);
  }
  out.report.path = path.string();
  return out;
}

}  // namespace

FileLog read_log_file(const std::filesystem::path& path, const ColumnMap& map,
                      const LogFileRead& how) {
  using Format = LogFileRead::Format;
  if (how.format == Format::kMcap || (how.format == Format::kAuto && looks_like_mcap(path))) {
    return read_bag_file(path, map, how.bag_time, how.jobs, Ros2MsgSet(how.msg_path));
  }
  if (how.format == Format::kDb3 || (how.format == Format::kAuto && looks_like_db3(path))) {
    return read_db3_bag(path, map, how.bag_time, Ros2MsgSet(how.msg_path));
  }
  if (how.format == Format::kNmea || (how.format == Format::kAuto && looks_like_nmea(path))) {
    return read_nmea_file(path, map, how.strict);
  }
  CsvReadOptions read;
  read.jobs = how.jobs;
  read.t_from_s = how.t_from_s;
  read.t_to_s = how.t_to_s;
  CsvLog csv = read_csv_log(path, map, read);
  FileLog out{std::move(csv.log),   {},
              csv.time.origin_ns,   csv.time.origin,
              csv.time.origin_zone, csv.first_row_s,
              csv.last_row_read_s,  {}};
  out.report.path = path.string();
  out.report.format = "csv";
  out.report.time_format = csv.time.format;
  out.report.notes = std::move(csv.time.notes);
  out.report.skipped = std::move(csv.time.skipped);
  out.report.records = out.log.size();
  return out;
}

}  // namespace dynpos::io
