#include "dynpos/io/csv_writer.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace dynpos::io {
namespace {

std::string quote_if_needed(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) {
    return text;
  }
  std::string out = "\"";
  for (const char c : text) {
    out += c;
    if (c == '"') out += '"';
  }
  out += '"';
  return out;
}

// Shortest round-trip text; NaN (missing) is the empty cell.
void append_number(std::string& out, double value) {
  if (std::isnan(value)) return;
  fmt::format_to(std::back_inserter(out), "{}", value);
}

// Flush the row buffer to the stream once it is this large [bytes]: few, large writes.
constexpr std::size_t kFlushBytes = 1 << 16;

}  // namespace

std::string csv_column_header(const std::string& name, const std::string& unit) {
  return quote_if_needed(unit.empty() ? name : fmt::format("{} [{}]", name, unit));
}

void write_csv(const std::filesystem::path& path, const core::Log& log) {
  std::vector<CsvColumn> columns;
  for (const auto& channel : log.channels()) columns.push_back({channel.name, channel.unit});
  CsvRowWriter writer(path, std::move(columns));
  std::vector<double> row(log.channels().size());
  for (std::size_t i = 0; i < log.size(); ++i) {
    for (std::size_t c = 0; c < row.size(); ++c) row[c] = log.channels()[c].values[i];
    writer.write_row(log.time()[i], row);
  }
  writer.commit();
}

CsvRowWriter::CsvRowWriter(const std::filesystem::path& path, std::vector<CsvColumn> columns)
    : file_(path), columns_(std::move(columns)) {
  buffer_ = csv_column_header("time", "s");
  for (const auto& column : columns_) {
    buffer_ += ',';
    buffer_ += csv_column_header(column.name, column.unit);
  }
  buffer_ += '\n';
}

void CsvRowWriter::write_row(double t_s, std::span<const double> values) {
  if (values.size() != columns_.size()) {
    throw std::invalid_argument(
        fmt::format("CsvRowWriter: {} values for {} columns", values.size(), columns_.size()));
  }
  if (!std::isfinite(t_s) || (rows_ > 0 && !(t_s > last_t_s_))) {
    throw std::invalid_argument(fmt::format(
        "CsvRowWriter: time {} s is not finite or not after the previous {} s", t_s, last_t_s_));
  }
  append_number(buffer_, t_s);
  for (const double value : values) {
    buffer_ += ',';
    append_number(buffer_, value);
  }
  buffer_ += '\n';
  last_t_s_ = t_s;
  ++rows_;
  if (buffer_.size() >= kFlushBytes) {
    file_.stream().write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }
}

void CsvRowWriter::commit() {
  file_.stream().write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  buffer_.clear();
  file_.commit();
}

}  // namespace dynpos::io
