#include "dynpos/io/csv_reader.hpp"

#include <algorithm>
#include <cassert>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <utility>

#include <fmt/format.h>

#include "csv_blocks.hpp"
#include "csv_cell.hpp"
#include "dynpos/io/time_stamp.hpp"
#include "line_reader.hpp"
#include "text_util.hpp"

namespace dynpos::io {
namespace {

using core::InputError;
using core::InputLocation;
using detail::LineReader;

constexpr std::size_t kNoSlot = std::numeric_limits<std::size_t>::max();

// Roles that make the time axis rather than channels.
bool is_time_role(std::string_view role) {
  return role == "time" || role == "time.sec" || role == "time.nsec" || role == "date";
}

// One field scanned from `pos`: its text (a view into the record, or into `buffer` when a
// quoted field had "" escapes), the position after its delimiter (npos at the end), and
// whether a quoted field was closed.
struct Field {
  std::string_view text;
  std::size_t next = std::string_view::npos;
  bool closed = true;
};

Field scan_field(std::string_view record, std::size_t pos, char delimiter, std::string& buffer) {
  Field field;
  std::size_t start = pos;
  while (start < record.size() && (record[start] == ' ' || record[start] == '\t') &&
         record[start] != delimiter) {
    ++start;
  }
  if (start < record.size() && record[start] == '"') {
    // Quoted: up to the closing quote; "" is a literal quote.
    std::size_t i = start + 1;
    bool escaped = false;
    for (;;) {
      const std::size_t quote = record.find('"', i);
      if (quote == std::string_view::npos) {
        field.closed = false;
        return field;
      }
      if (quote + 1 < record.size() && record[quote + 1] == '"') {
        escaped = true;
        i = quote + 2;
        continue;
      }
      if (escaped) {
        buffer.clear();
        for (std::size_t k = start + 1; k < quote; ++k) {
          buffer += record[k];
          if (record[k] == '"') ++k;  // skip the second quote of ""
        }
        field.text = buffer;
      } else {
        field.text = record.substr(start + 1, quote - start - 1);
      }
      const std::size_t end = record.find(delimiter, quote + 1);
      field.next = end == std::string_view::npos ? end : end + 1;
      return field;
    }
  }
  const std::size_t end = record.find(delimiter, pos);
  field.text = record.substr(pos, end == std::string_view::npos ? record.size() - pos : end - pos);
  field.next = end == std::string_view::npos ? end : end + 1;
  return field;
}

char detect_delimiter(std::string_view header) {
  std::size_t counts[3] = {0, 0, 0};
  constexpr char kCandidates[3] = {',', ';', '\t'};
  bool quoted = false;
  for (const char c : header) {
    if (c == '"') quoted = !quoted;
    if (quoted) continue;
    for (int k = 0; k < 3; ++k) counts[k] += (c == kCandidates[k]) ? 1 : 0;
  }
  int best = 0;
  for (int k = 1; k < 3; ++k) {
    if (counts[k] > counts[best]) best = k;
  }
  return kCandidates[best];
}

std::string delimiter_name(char delimiter) {
  return delimiter == '\t' ? std::string("tab") : fmt::format("'{}'", delimiter);
}

using detail::CellKind;
using detail::parse_cell;
using detail::to_si;

// How one column becomes a channel.
struct ColumnPlan {
  std::size_t field = 0;  // 0-based field index in the row
  std::size_t slot = 0;   // index into the per-row cell array
  std::string header;     // header text, for messages
  std::string channel;    // channel name in the Log
  std::string unit_symbol;
  core::Interp interp = core::Interp::kLinear;
  core::Unit unit;           // converts the scaled raw value to SI
  double scale = 1.0;        // multiplies the raw value before conversion
  bool may_be_text = false;  // read_csv_all: a text column is dropped, not an error
  enum class State { kUnknown, kNumeric, kText } state = State::kUnknown;
  std::vector<double> values;
};

struct Header {
  std::vector<std::string> cells;
  std::size_t line = 0;
  char delimiter = ',';
};

std::vector<std::string> split_header(LineReader& reader, std::string& record, char delimiter) {
  std::vector<std::string> cells;
  std::string buffer;
  std::size_t pos = 0;
  for (;;) {
    const Field field = scan_field(record, pos, delimiter, buffer);
    if (!field.closed) {
      if (reader.continue_record(record)) {
        cells.clear();
        pos = 0;
        continue;
      }
      InputLocation where;
      where.file = reader.path();
      where.line = reader.line();
      throw InputError(where, "unterminated quoted field in the header",
                       "close the quote (\") or remove it");
    }
    cells.emplace_back(detail::trim(field.text));
    if (field.next == std::string_view::npos) break;
    pos = field.next;
  }
  return cells;
}

Header read_header(LineReader& reader, const CsvFormat& format) {
  Header header;
  std::string record;
  if (!reader.next(record, header.line)) {
    InputLocation where;
    where.file = reader.path();
    throw InputError(where, "the log is empty: no header line",
                     "a CSV log starts with a header line naming its columns");
  }
  header.delimiter = format.delimiter ? *format.delimiter : detect_delimiter(record);
  header.cells = split_header(reader, record, header.delimiter);
  return header;
}

// The time column and its optional companions (time.nsec, date).
struct TimePlans {
  ColumnPlan time;
  std::optional<ColumnPlan> nsec, date;
};

// Splits records into the cells of the planned fields (views into the record or `buffers_`).
class RowSplitter {
 public:
  RowSplitter(const Header& header, TimePlans& time, std::vector<ColumnPlan>& channels)
      : header_(header), slot_of_field_(header.cells.size(), kNoSlot) {
    // Field index → slot in `cells` (several roles may share a column).
    auto assign = [&](ColumnPlan& plan) {
      if (slot_of_field_[plan.field] == kNoSlot) slot_of_field_[plan.field] = slots_++;
      plan.slot = slot_of_field_[plan.field];
    };
    assign(time.time);
    if (time.nsec) assign(*time.nsec);
    if (time.date) assign(*time.date);
    for (auto& plan : channels) assign(plan);
    cells_.resize(slots_);
    buffers_.resize(slots_);
  }

  const std::vector<std::string_view>& cells() const noexcept { return cells_; }

  // Splits `record` (joining the next physical lines through `reader` while a quoted field is
  // open; null for a complete record) and checks its field count.
  void split(std::string& record, std::size_t line, LineReader* reader) {
    std::size_t field_count = 0;
    std::size_t pos = 0;
    for (;;) {
      const std::size_t slot =
          field_count < slot_of_field_.size() ? slot_of_field_[field_count] : kNoSlot;
      const Field field =
          scan_field(record, pos, header_.delimiter, slot == kNoSlot ? junk_ : buffers_[slot]);
      if (!field.closed) {
        if (reader != nullptr && reader->continue_record(record)) {
          field_count = 0;
          pos = 0;
          continue;
        }
        InputLocation where;
        where.file = path_of(reader);
        where.line = line;
        where.column = field_count + 1;
        throw InputError(where, "unterminated quoted field", "close the quote (\") or remove it");
      }
      if (slot != kNoSlot) cells_[slot] = field.text;
      ++field_count;
      if (field.next == std::string_view::npos) break;
      pos = field.next;
    }
    if (field_count != header_.cells.size()) {
      InputLocation where;
      where.file = path_of(reader);
      where.line = line;
      throw InputError(where,
                       fmt::format("the row has {} fields but the header (line {}) has {}",
                                   field_count, header_.line, header_.cells.size()),
                       fmt::format("check the delimiter (using {}) and quoting",
                                   delimiter_name(header_.delimiter)));
    }
  }

  std::string path;  // the file, for messages

 private:
  std::string path_of(const LineReader* reader) const {
    return reader != nullptr ? reader->path() : path;
  }

  const Header& header_;
  std::vector<std::size_t> slot_of_field_;
  std::size_t slots_ = 0;
  std::vector<std::string_view> cells_;
  std::vector<std::string> buffers_;
  std::string junk_;
};

// Rows read so far and the time axis of the rows kept inside the window.
struct RowStream {
  std::vector<double> time_s;
  std::size_t rows = 0;
  std::optional<double> first_t;
  double last_t = 0.0;
};

// One read of a CSV log: the file, its format and the options, the header, the plans of the
// time and channel columns, the time stamps and the rows read so far. The header is read on
// construction; plan_mapped() or plan_all() plans the columns, read_rows() reads the rows.
class CsvRead {
 public:
  CsvRead(const std::filesystem::path& path, const CsvFormat& format, const CsvReadOptions& options)
      : reader_(path, format.comment_prefix), format_(format), options_(options) {
    header_ = read_header(reader_, format_);
  }
  CsvRead(const CsvRead&) = delete;
  CsvRead& operator=(const CsvRead&) = delete;

  /// read_csv_log: the columns of the map's roles.
  void plan_mapped(const ColumnMap& map);
  /// read_csv_all: time in the first column, every other column a channel.
  void plan_all();

  /// Streams the data rows into the plans' vectors; returns the time axis and the times of the
  /// first and the last row read. Throws if no row is inside the window.
  RowStream read_rows();

  std::vector<ColumnPlan>& channels() noexcept { return channels_; }
  const TimeStampInfo& stamp_info() const { return stamps_->info(); }

 private:
  ColumnPlan plan_role(const std::string& role, const RoleColumn& entry);
  std::size_t find_column(const std::string& role, const RoleColumn& entry) const;
  InputLocation header_location(std::size_t field) const;
  InputLocation cell_location(const ColumnPlan& plan, std::size_t line) const;
  [[noreturn]] void bad_cell(CellKind kind, std::string_view cell, const ColumnPlan& plan,
                             std::size_t line) const;
  [[noreturn]] void overflow(std::string_view cell, const ColumnPlan& plan, std::size_t line) const;
  [[noreturn]] void no_rows_in_window() const;
  double row_time_s(std::size_t line);
  bool store_row(std::size_t line);
  void stream_blocks();
  bool merge_block(const detail::Block& block, std::size_t line_base);
  void reserve_rows(const detail::Block& block, std::uint64_t file_size);

  LineReader reader_;
  const CsvFormat& format_;
  const CsvReadOptions& options_;
  Header header_;
  TimePlans time_;
  std::vector<ColumnPlan> channels_;
  std::optional<InputError> time_unit_error_;  // thrown if the time stamps are plain seconds
  std::optional<TimeStampReader> stamps_;      // set by the plan
  std::optional<RowSplitter> splitter_;        // set by read_rows()
  std::vector<std::size_t> plan_of_;           // block channel → plan (text columns are not read)
  RowStream rows_;
  bool more_ = true;  // false once a row is past the window: reading stops
};

InputLocation CsvRead::header_location(std::size_t field) const {
  InputLocation where;
  where.file = reader_.path();
  where.line = header_.line;
  where.column = field + 1;
  where.column_name = header_.cells[field];
  return where;
}

InputLocation CsvRead::cell_location(const ColumnPlan& plan, std::size_t line) const {
  InputLocation where;
  where.file = reader_.path();
  where.line = line;
  where.column = plan.field + 1;
  where.column_name = plan.header;
  return where;
}

void CsvRead::bad_cell(CellKind kind, std::string_view cell, const ColumnPlan& plan,
                       std::size_t line) const {
  const InputLocation where = cell_location(plan, line);
  const std::string text(detail::trim(cell));
  switch (kind) {
    case CellKind::kNonFinite:
      throw InputError(where, fmt::format("'{}' is not a finite number", text),
                       fmt::format("leave the cell blank for missing data, or declare the token "
                                   "as missing (missing = [\"{}\"] in [csv] of the column map)",
                                   text));
    case CellKind::kOutOfRange:
      throw InputError(where, fmt::format("'{}' is out of the range of a double", text));
    default: {
      std::string hint =
          "numbers use '.' as the decimal point; leave the cell blank for missing data, or "
          "declare the token as missing in [csv] of the column map";
      if (text.find(',') != std::string::npos && header_.delimiter != ',') {
        hint = "decimal commas are not supported: use '.' as the decimal point";
      }
      throw InputError(where, fmt::format("'{}' is not a number", text), hint);
    }
  }
}

// A number that the column's scale and unit carry beyond the range of a double.
void CsvRead::overflow(std::string_view cell, const ColumnPlan& plan, std::size_t line) const {
  throw InputError(cell_location(plan, line),
                   fmt::format("'{}' times the column's scale {} in SI is beyond the range of a "
                               "double",
                               detail::trim(cell), plan.scale),
                   "check the scale and unit of the column in the column map");
}

// The time of the split row [s]: plain seconds parsed here (fast path, unit and scale), other
// forms by the time stamp reader.
double CsvRead::row_time_s(std::size_t line) {
  const std::vector<std::string_view>& cells = splitter_->cells();
  const ColumnPlan& plan = time_.time;
  const std::string_view time_cell = cells[plan.slot];
  if (!stamps_->plain_seconds()) {
    return stamps_->time_s({time_cell, time_.nsec ? cells[time_.nsec->slot] : std::string_view(),
                            time_.date ? cells[time_.date->slot] : std::string_view()},
                           line);
  }
  double raw = 0.0;
  const CellKind kind = parse_cell(time_cell, format_.missing_tokens, raw);
  if (kind == CellKind::kMissing) {
    throw InputError(cell_location(plan, line), "the time cell is blank",
                     "every row needs a time; remove the row or fill in its time");
  }
  if (kind != CellKind::kNumber) bad_cell(kind, time_cell, plan, line);
  const double t = to_si(plan.unit, raw * plan.scale);
  if (!std::isfinite(t)) overflow(time_cell, plan, line);
  return t;
}

// Stores the split row of `line`: its time (if the order policy keeps it and it is inside the
// window) and its channel values. False once the row is after the window: reading stops.
bool CsvRead::store_row(std::size_t line) {
  const std::vector<std::string_view>& cells = splitter_->cells();
  const double t = row_time_s(line);
  if (!stamps_->accept(t, cells[time_.time.slot], line)) return true;
  if (!rows_.first_t) rows_.first_t = t;
  rows_.last_t = t;
  ++rows_.rows;
  if (options_.t_from_s && t < *options_.t_from_s) return true;
  if (options_.t_to_s && t > *options_.t_to_s) return false;

  rows_.time_s.push_back(t);
  double raw = 0.0;
  for (auto& plan : channels_) {
    double value = core::kMissing;
    const std::string_view cell = cells[plan.slot];
    const CellKind cell_kind = parse_cell(cell, format_.missing_tokens, raw);
    if (cell_kind == CellKind::kNumber) {
      value = to_si(plan.unit, raw * plan.scale);
      if (!std::isfinite(value)) overflow(cell, plan, line);
      if (plan.state == ColumnPlan::State::kUnknown) plan.state = ColumnPlan::State::kNumeric;
    } else if (cell_kind != CellKind::kMissing) {
      if (plan.may_be_text && cell_kind == CellKind::kText &&
          plan.state != ColumnPlan::State::kNumeric) {
        plan.state = ColumnPlan::State::kText;
        plan.values.clear();
        plan.values.shrink_to_fit();
      }
      if (plan.state != ColumnPlan::State::kText) bad_cell(cell_kind, cell, plan, line);
    }
    if (plan.state != ColumnPlan::State::kText) plan.values.push_back(value);
  }
  return true;
}

// The parts of a clean block inside the window, appended as store_row() would append them row
// by row. False, nothing changed, when its first time is not after the last kept one (the caller
// then reads it row by row, where the order policy applies). Clears more_ once a row is past
// the window.
bool CsvRead::merge_block(const detail::Block& block, std::size_t line_base) {
  const std::vector<double>& t = block.time_s;
  const std::size_t n = t.size();
  if (n == 0) return true;
  const auto index = [&](std::vector<double>::const_iterator it) {
    return static_cast<std::size_t>(it - t.begin());
  };
  // Rows after the window: the first of them is kept and counted, then reading stops.
  const std::size_t k_end =
      options_.t_to_s ? index(std::upper_bound(t.begin(), t.end(), *options_.t_to_s)) : n;
  const std::size_t counted = std::min(k_end + 1, n);
  if (!stamps_->accept_increasing(
          {t.front(), t[counted - 1], counted, line_base + block.line_of_row(counted - 1) + 1})) {
    return false;
  }
  if (!rows_.first_t) rows_.first_t = t.front();
  rows_.last_t = t[counted - 1];
  rows_.rows += counted;
  const std::size_t k_from =
      options_.t_from_s
          ? std::min(index(std::lower_bound(t.begin(), t.end(), *options_.t_from_s)), k_end)
          : 0;
  const auto first = static_cast<std::ptrdiff_t>(k_from);
  const auto last = static_cast<std::ptrdiff_t>(k_end);
  rows_.time_s.insert(rows_.time_s.end(), t.begin() + first, t.begin() + last);
  for (std::size_t k = 0; k < plan_of_.size(); ++k) {
    ColumnPlan& plan = channels_[plan_of_[k]];
    const std::vector<double>& v = block.channels[k].values;
    if (plan.state == ColumnPlan::State::kUnknown &&
        std::any_of(v.begin() + first, v.begin() + last, [](double x) { return !std::isnan(x); })) {
      plan.state = ColumnPlan::State::kNumeric;
    }
    plan.values.insert(plan.values.end(), v.begin() + first, v.begin() + last);
  }
  more_ = k_end == n;
  return true;
}

// Room for the rows still to come, estimated from the first block's bytes per row (room never
// written costs no memory). Not for a window that ends early.
void CsvRead::reserve_rows(const detail::Block& block, std::uint64_t file_size) {
  if (options_.t_to_s) return;
  const std::size_t rows = block.time_s.size();
  const std::uint64_t bytes = block.end - block.begin;
  if (rows == 0 || bytes == 0) return;
  const double left = static_cast<double>(file_size - block.begin);
  const auto more = static_cast<std::size_t>(1.02 * left * static_cast<double>(rows) /
                                             static_cast<double>(bytes)) +
                    4096;
  rows_.time_s.reserve(rows_.time_s.size() + more);
  for (const std::size_t p : plan_of_) {
    channels_[p].values.reserve(channels_[p].values.size() + more);
  }
}

// The rows after the first ones, of a regular file with plain-seconds time: by the block parser
// (csv_blocks.hpp), each block that is not clean row by row. Returns once the file or the
// window ends (more_ false for the window).
void CsvRead::stream_blocks() {
  detail::BlockLayout layout;
  layout.delimiter = header_.delimiter;
  layout.field_count = header_.cells.size();
  layout.comment_prefix = format_.comment_prefix;
  layout.missing_tokens = format_.missing_tokens;
  layout.time = {time_.time.field, time_.time.unit, time_.time.scale};
  for (std::size_t p = 0; p < channels_.size(); ++p) {
    if (channels_[p].state == ColumnPlan::State::kText) continue;
    plan_of_.push_back(p);
    layout.channels.push_back({channels_[p].field, channels_[p].unit, channels_[p].scale});
  }
  detail::BlockReader blocks(reader_.path(), std::move(layout), options_.jobs);
  detail::LinePosition at = reader_.position();
  bool first_block = true;
  while (more_ && at.offset < blocks.file_size()) {
    // Blocks are merged in file order while the next ones are parsed; the first that is not
    // clean stops them.
    std::optional<std::pair<std::uint64_t, std::uint64_t>> by_rows;  // its [begin, end)
    blocks.stream(at.offset, [&](const detail::Block& block) {
      if (first_block) reserve_rows(block, blocks.file_size());
      first_block = false;
      if (block.clean && merge_block(block, at.line)) {
        at.offset = block.end;
        at.line += block.lines;
        return more_;
      }
      by_rows.emplace(block.begin, block.end);
      return false;
    });
    if (!by_rows) return;  // the end of the file or of the window
    // Row by row, exactly as without blocks; then blocks again from where that ended.
    reader_.seek({by_rows->first, at.line});
    std::string record;
    std::size_t record_line = 0;
    while (more_ && reader_.position().offset < by_rows->second &&
           reader_.next(record, record_line)) {
      splitter_->split(record, record_line, &reader_);
      more_ = store_row(record_line);
    }
    at = reader_.position();
  }
}

// The first kTimeDetectionRows rows are held back until their time cells have fixed the
// format; the rest of a regular file with plain-seconds time goes through stream_blocks().
RowStream CsvRead::read_rows() {
  splitter_.emplace(header_, time_, channels_);
  splitter_->path = reader_.path();
  std::vector<std::pair<std::string, std::size_t>> held;  // record, line
  std::vector<std::string> held_time;
  // Fixes the time format from the held rows, then stores them.
  auto release = [&] {
    std::vector<std::string_view> cells(held_time.begin(), held_time.end());
    std::vector<std::size_t> lines;
    for (const auto& row : held) lines.push_back(row.second);
    stamps_->start(cells, lines);
    if (stamps_->plain_seconds() && time_unit_error_) throw *time_unit_error_;
    for (auto& [held_record, held_line] : held) {
      splitter_->split(held_record, held_line, nullptr);
      if (!(more_ = store_row(held_line))) break;
    }
    held.clear();
    held.shrink_to_fit();
  };

  std::string record;
  std::size_t line = 0;
  bool started = false;
  while (more_ && reader_.next(record, line)) {
    splitter_->split(record, line, &reader_);
    if (started) {
      more_ = store_row(line);
      continue;
    }
    held.emplace_back(record, line);
    held_time.emplace_back(splitter_->cells()[time_.time.slot]);
    if (held.size() == kTimeDetectionRows) {
      release();
      started = true;
      if (more_ && stamps_->plain_seconds() && reader_.regular()) {
        stream_blocks();
        break;
      }
    }
  }
  if (!started && !held.empty()) release();
  if (rows_.time_s.empty()) no_rows_in_window();
  return std::move(rows_);
}

void CsvRead::no_rows_in_window() const {
  InputLocation where;
  where.file = reader_.path();
  if (rows_.rows == 0) {
    throw InputError(where, "the log has a header but no data rows");
  }
  const double t_from = options_.t_from_s.value_or(-std::numeric_limits<double>::infinity());
  const double t_to = options_.t_to_s.value_or(std::numeric_limits<double>::infinity());
  throw EmptyWindowError(
      InputError(where, fmt::format("no rows inside the window [{}, {}] s", t_from, t_to),
                 fmt::format("the log starts at {} s{}", *rows_.first_t,
                             rows_.last_t > t_to ? std::string()
                                                 : fmt::format(" and ends at {} s", rows_.last_t))),
      {.first_row_s = *rows_.first_t, .last_row_read_s = rows_.last_t});
}

// Index of the header cell for the role's column: the full header text first, then the name
// without a bracketed unit. Throws if it is absent or ambiguous.
std::size_t CsvRead::find_column(const std::string& role, const RoleColumn& entry) const {
  const std::string& column = entry.column;
  const std::vector<std::string>& cells = header_.cells;
  InputLocation where;
  where.file = reader_.path();
  where.line = header_.line;
  where.column_name = role;
  for (const bool by_name : {false, true}) {
    std::vector<std::size_t> hits;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if ((by_name ? split_header_cell(cells[i]).name : cells[i]) == column) hits.push_back(i);
    }
    if (hits.size() == 1) return hits.front();
    if (hits.size() > 1) {
      throw InputError(where,
                       fmt::format("column '{}' for role '{}' appears more than once in the "
                                   "header (columns {} and {})",
                                   column, role, hits[0] + 1, hits[1] + 1),
                       "rename one of them in the file, or map the full header text");
    }
  }
  std::string hint = fmt::format("the columns are: {}", detail::join(cells));
  // Compare with the names without units too, so "Heading" finds "HEADING [deg]".
  std::string near = detail::closest_match(column, cells);
  if (near.empty()) {
    std::vector<std::string> names;
    for (const auto& cell : cells) names.push_back(split_header_cell(cell).name);
    const std::string name = detail::closest_match(column, names);
    if (!name.empty()) {
      near = cells[static_cast<std::size_t>(std::find(names.begin(), names.end(), name) -
                                            names.begin())];
    }
  }
  if (!near.empty()) hint = fmt::format("did you mean '{}'? {}", near, hint);
  if (!entry.source.file.empty()) {
    hint += fmt::format(" (mapped in {}{})", entry.source.file,
                        entry.source.line ? fmt::format(":{}", *entry.source.line) : "");
  } else if (!entry.source.column_name.empty()) {
    hint += fmt::format(" (mapped by {})", entry.source.column_name);
  }
  throw InputError(
      where, fmt::format("column '{}' for role '{}' is not in the header", column, role), hint);
}

// The plan of a mapped role's column: unit declared > header bracket > role default.
ColumnPlan CsvRead::plan_role(const std::string& role, const RoleColumn& entry) {
  const std::optional<RoleSpec> spec = find_role(role);
  assert(spec && "ColumnMap only holds known roles");
  ColumnPlan plan;
  plan.field = find_column(role, entry);
  plan.header = header_.cells[plan.field];
  plan.channel = role;
  plan.interp = spec->interp;
  plan.scale = entry.scale;
  if (entry.unit) {
    plan.unit = unit_for_role(*spec, *entry.unit, entry.source);
  } else if (const HeaderCell cell = split_header_cell(plan.header);
             !cell.unit.empty() && (!is_time_role(role) || role == "time")) {
    try {
      plan.unit = unit_for_role(*spec, cell.unit, header_location(plan.field));
    } catch (const InputError& e) {
      InputError error(e.where(), e.problem() + " (from the header)",
                       e.hint() + fmt::format("; or declare the unit with --unit {}=UNIT or "
                                              "unit = \"...\" in the column map",
                                              role));
      if (role != "time") throw error;
      // "Time (UTC)" names no unit, but matters only if the stamps are plain seconds.
      time_unit_error_ = std::move(error);
      plan.unit = core::si_unit(core::Quantity::kTime);
    }
  } else {
    const auto unit = core::find_unit(spec->default_unit);
    assert(unit && "every role default is a known unit");
    plan.unit = *unit;
  }
  plan.unit_symbol = core::si_unit(plan.unit.quantity).symbol;
  return plan;
}

void CsvRead::plan_mapped(const ColumnMap& map) {
  std::string declared_time_unit;  // a unit or scale the map or the header gives the time
  double declared_time_unit_s = 0.0;
  for (const auto& [role, entry] : map.roles()) {
    ColumnPlan plan = plan_role(role, entry);
    if (role == "time" && !time_unit_error_ &&
        (entry.unit || entry.scale != 1.0 || !split_header_cell(plan.header).unit.empty())) {
      declared_time_unit = entry.scale != 1.0
                               ? fmt::format("{} × {}", entry.scale, plan.unit.symbol)
                               : plan.unit.symbol;
      declared_time_unit_s = plan.unit.scale * entry.scale;
    }
    if (role == "time" || role == "time.sec") {
      time_.time = std::move(plan);
    } else if (role == "time.nsec") {
      time_.nsec = std::move(plan);
    } else if (role == "date") {
      time_.date = std::move(plan);
    } else {
      channels_.push_back(std::move(plan));
    }
  }
  std::stable_sort(channels_.begin(), channels_.end(),
                   [](const ColumnPlan& a, const ColumnPlan& b) { return a.field < b.field; });
  stamps_.emplace(map.time(), TimeColumnSpec{reader_.path(), time_.time.header, time_.time.field,
                                             time_.nsec.has_value(), time_.date.has_value(),
                                             declared_time_unit, declared_time_unit_s});
}

void CsvRead::plan_all() {
  std::map<std::string, std::size_t> seen;
  for (std::size_t i = 0; i < header_.cells.size(); ++i) {
    const HeaderCell cell = split_header_cell(header_.cells[i]);
    if (cell.name.empty()) {
      throw InputError(header_location(i), "empty column name in the header",
                       "name every column (a trailing delimiter makes an empty last column)");
    }
    ColumnPlan plan;
    plan.field = i;
    plan.header = header_.cells[i];
    plan.channel = cell.name;
    const std::optional<core::Unit> unit = core::find_unit(cell.unit.empty() ? "1" : cell.unit);
    if (i == 0) {
      const std::optional<core::Unit> time_unit =
          cell.unit.empty() ? core::si_unit(core::Quantity::kTime) : unit;
      if (!time_unit || time_unit->quantity != core::Quantity::kTime) {
        throw InputError(header_location(i),
                         fmt::format("the first column is time, but its unit '{}' is not a time "
                                     "unit",
                                     cell.unit),
                         fmt::format("use one of: {}",
                                     detail::join(core::unit_spellings(core::Quantity::kTime))));
      }
      plan.unit = *time_unit;
      time_.time = std::move(plan);
      continue;
    }
    if (const auto [it, inserted] = seen.emplace(cell.name, i); !inserted) {
      throw InputError(header_location(i),
                       fmt::format("channel '{}' appears twice (columns {} and {})", cell.name,
                                   it->second + 1, i + 1),
                       "give every column a distinct name");
    }
    if (cell.unit.empty()) {
      plan.unit = core::Unit{"", core::Quantity::kDimensionless, 1.0, 0.0};
      plan.unit_symbol = "";
    } else if (unit) {
      plan.unit = *unit;
      plan.unit_symbol = core::si_unit(unit->quantity).symbol;
    } else {
      plan.unit = core::Unit{cell.unit, core::Quantity::kDimensionless, 1.0, 0.0};
      plan.unit_symbol = cell.unit;  // unknown unit: kept as logged
    }
    if (const auto role = find_role(cell.name)) plan.interp = role->interp;
    plan.may_be_text = true;
    channels_.push_back(std::move(plan));
  }
  const bool time_unit_declared = !split_header_cell(time_.time.header).unit.empty();
  stamps_.emplace(TimeStampOptions{},
                  TimeColumnSpec{reader_.path(), time_.time.header, 0, false, false,
                                 time_unit_declared ? time_.time.unit.symbol : std::string(),
                                 time_unit_declared ? time_.time.unit.scale : 0.0});
}

}  // namespace

void CsvReadOptions::validate() const {
  const bool from_ok = !t_from_s || std::isfinite(*t_from_s);
  const bool to_ok = !t_to_s || std::isfinite(*t_to_s);
  if (!from_ok || !to_ok) throw InputError({}, "the time window bounds must be finite");
  if (t_from_s && t_to_s && *t_from_s > *t_to_s) {
    throw InputError({}, fmt::format("the time window [{}, {}] s is empty", *t_from_s, *t_to_s),
                     "the start must not be after the end");
  }
}

HeaderCell split_header_cell(std::string_view cell) {
  const std::string_view text = detail::trim(cell);
  HeaderCell out{std::string(text), {}};
  if (text.size() < 3) return out;
  const char close = text.back();
  const char open = close == ']' ? '[' : close == ')' ? '(' : '\0';
  if (open == '\0') return out;
  const std::size_t at = text.rfind(open);
  if (at == std::string_view::npos) return out;
  const std::string_view name = detail::trim(text.substr(0, at));
  if (name.empty()) return out;
  out.name = std::string(name);
  out.unit = std::string(detail::trim(text.substr(at + 1, text.size() - at - 2)));
  return out;
}

std::vector<std::string> read_csv_header(const std::filesystem::path& path,
                                         const CsvFormat& format) {
  format.validate();
  LineReader reader(path, format.comment_prefix);
  return read_header(reader, format).cells;
}

CsvLog read_csv_log(const std::filesystem::path& path, const ColumnMap& map,
                    const CsvReadOptions& options) {
  map.validate();
  options.validate();
  for (const auto& [role, entry] : map.roles()) {
    if (!entry.file.empty()) {
      throw InputError(entry.source,
                       fmt::format("role '{}' is mapped to another file, {}", role, entry.file),
                       "this reads a single file: map the role to one of its columns");
    }
  }
  CsvRead read(path, map.format(), options);
  read.plan_mapped(map);
  RowStream rows = read.read_rows();
  CsvLog out{core::Log(std::move(rows.time_s), options.jobs), read.stamp_info(), *rows.first_t,
             rows.last_t};
  for (auto& plan : read.channels()) {
    out.log.add_channel(plan.channel, plan.unit_symbol, std::move(plan.values), plan.interp);
  }
  return out;
}

core::Log read_csv(const std::filesystem::path& path, const ColumnMap& map,
                   const CsvReadOptions& options) {
  return read_csv_log(path, map, options).log;
}

core::Log read_csv_all(const std::filesystem::path& path, const CsvReadOptions& options,
                       const CsvFormat& format) {
  format.validate();
  options.validate();
  CsvRead read(path, format, options);
  read.plan_all();
  core::Log log(read.read_rows().time_s);
  for (auto& plan : read.channels()) {
    if (plan.state == ColumnPlan::State::kText) continue;
    log.add_channel(plan.channel, plan.unit_symbol, std::move(plan.values), plan.interp);
  }
  return log;
}

}  // namespace dynpos::io
