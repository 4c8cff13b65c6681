#pragma once
/// \file
/// CSV log writers: a whole core::Log at once, or row by row for long simulations.
///
/// The format (docs/log-format.md) is the one read_csv_all() reads back exactly:
/// - comma-delimited, "\n" line ends, one header line;
/// - first column "time [s]", then "name [unit]" per channel (just "name" if the unit is
///   empty); names with a comma, quote or line break are quoted;
/// - numbers in the shortest form that reads back to the same double ("0.1", "1e-07");
/// - a missing value (NaN) is an empty cell; ±infinity is written "inf"/"-inf" (and is then
///   rejected by the reader, so a diverged simulation is noticed, not hidden).
/// Output goes through AtomicFile: a failure leaves no half-written file.

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "dynpos/core/log.hpp"
#include "dynpos/io/atomic_file.hpp"

namespace dynpos::io {

/// Writes `log` to `path` atomically. Throws std::runtime_error if the file cannot be written.
void write_csv(const std::filesystem::path& path, const core::Log& log);

/// The header text of a column: "name [unit]", or "name" when unit is empty.
std::string csv_column_header(const std::string& name, const std::string& unit);

/// A column of a CsvRowWriter.
struct CsvColumn {
  std::string name;
  std::string unit;  ///< e.g. "m", "rad"; empty = none written
};

/// Writes a log row by row without holding it in memory; nothing appears at `path` until
/// commit() succeeds.
class CsvRowWriter {
 public:
  /// Opens the temporary file and writes the header ("time [s]", then the columns).
  /// Throws std::runtime_error if the file cannot be created.
  CsvRowWriter(const std::filesystem::path& path, std::vector<CsvColumn> columns);

  /// Writes one row. Throws std::invalid_argument if the number of values differs from the
  /// number of columns, or t_s is not finite or not after the previous row's time.
  void write_row(double t_s, std::span<const double> values);

  /// Finishes the file and renames it onto the path. Throws std::runtime_error on failure.
  void commit();

  std::size_t rows() const noexcept { return rows_; }

 private:
  AtomicFile file_;
  std::vector<CsvColumn> columns_;
  std::string buffer_;
  std::size_t rows_ = 0;
  double last_t_s_ = 0.0;
};

}  // namespace dynpos::io
