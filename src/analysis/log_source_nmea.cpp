#include "log_source_nmea.hpp"

#include "dynpos/core/error.hpp"
#include "dynpos/io/nmea_log.hpp"

namespace dynpos::analysis {

bool reads_nmea(const LogSource& source) {
  if (source.format == "nmea") return true;
  if (source.format == "csv") return false;
  if (source.format != "auto") {
    throw core::InputError::for_option(
        "format", "unknown log format '" + source.format + "'",
        "use auto (detected from the content), csv or nmea (NMEA 0183 capture)");
  }
  return io::looks_like_nmea(source.log);
}

LoadedLog load_nmea(const LogSource& source, const RoleFilter& wanted) {
  if (!source.map_file.empty() || !source.columns.empty() || !source.units.empty()) {
    throw core::InputError::for_option(
        source.map_file.empty() ? (source.columns.empty() ? "unit" : "col") : "map",
        "column maps apply to CSV logs, but " + source.log.string() + " is an NMEA capture",
        "an NMEA capture's roles come from its sentences (docs/log-format.md, \"NMEA "
        "captures\"); drop --map, --col and --unit, or give --format csv");
  }
  io::NmeaLogOptions options;
  options.strict = source.strict;
  options.wanted = wanted;
  io::NmeaLog read = io::read_nmea_log(source.log, options);
  const std::size_t sentences = read.report.records;
  io::InputReport input = describe_input(read.log, source.log.string(), std::move(read.report));
  input.files.front().records = sentences;  // sentences used, not rows of the time axis
  input.origin = read.origin;
  if (read.origin) input.origin_zone = "UTC";
  return {std::move(read.log), std::move(input)};
}

}  // namespace dynpos::analysis
