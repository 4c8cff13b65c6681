#include "dynpos/io/log_file.hpp"

#include "dynpos/io/csv_reader.hpp"

namespace dynpos::io {

FileLog read_log_file(const std::filesystem::path& path, const ColumnMap& map) {
  CsvLog csv = read_csv_log(path, map);
  FileLog out{std::move(csv.log), {}, csv.time.origin_ns, csv.time.origin, csv.time.origin_zone};
  out.report.path = path.string();
  out.report.format = "csv";
  out.report.time_format = csv.time.format;
  out.report.notes = std::move(csv.time.notes);
  out.report.skipped = std::move(csv.time.skipped);
  out.report.records = out.log.size();
  return out;
}

}  // namespace dynpos::io
