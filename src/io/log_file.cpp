#include "dynpos/io/log_file.hpp"

#include "dynpos/io/csv_reader.hpp"

namespace dynpos::io {

FileLog read_log_file(const std::filesystem::path& path, const ColumnMap& map) {
  FileLog out{read_csv(path, map), {}};
  out.report.path = path.string();
  out.report.format = "csv";
  out.report.time_format = "seconds";
  out.report.records = out.log.size();
  return out;
}

}  // namespace dynpos::io
