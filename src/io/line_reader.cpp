#include "line_reader.hpp"

#include <cerrno>
#include <cstring>
#include <utility>

#include <fmt/format.h>

#include "bounded_line.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/io/csv_reader.hpp"
#include "text_util.hpp"

namespace dynpos::io::detail {

using core::InputError;
using core::InputLocation;

LineReader::LineReader(const std::filesystem::path& path, std::string comment_prefix)
    : path_(path.string()), comment_prefix_(std::move(comment_prefix)) {
  in_.open(path, std::ios::binary);
  if (!in_) {
    InputLocation where;
    where.file = path_;
    throw InputError(where, fmt::format("cannot open the log: {}", std::strerror(errno)),
                     "check the path");
  }
}

bool LineReader::next(std::string& record, std::size_t& record_line) {
  while (read_physical(record)) {
    const std::string_view text = trim(record);
    if (text.empty()) continue;
    if (!comment_prefix_.empty() && text.substr(0, comment_prefix_.size()) == comment_prefix_) {
      continue;
    }
    record_line = position_.line;
    record_line_ = position_.line;
    return true;
  }
  return false;
}

bool LineReader::continue_record(std::string& record) {
  std::string more;
  if (!read_physical(more)) return false;
  if (record.size() + 1 + more.size() > kMaxCsvRecordBytes) too_long("record");
  record += '\n';
  record += more;
  return true;
}

void LineReader::seek(LinePosition at) {
  in_.clear();
  in_.seekg(static_cast<std::streamoff>(at.offset));
  position_ = at;
}

bool LineReader::read_physical(std::string& out) {
  bool ended = false;
  const LineStatus status = read_bounded_line(in_, out, kMaxCsvRecordBytes, ended);
  if (in_.bad()) {
    InputLocation where;
    where.file = path_;
    where.line = position_.line + 1;
    throw InputError(where, fmt::format("read error: {}", std::strerror(errno)));
  }
  if (status == LineStatus::kEnd) return false;
  const std::size_t line = ++position_.line;
  if (!out.empty() && out.back() == '\r' && status != LineStatus::kTooLong) {
    out.pop_back();
    position_.offset += 1;
  }
  if (line == 1) refuse_cr_line_ends(out);
  if (status == LineStatus::kTooLong) too_long("line");
  position_.offset += out.size() + (ended ? 1 : 0);
  if (line == 1 && out.compare(0, 3, "\xEF\xBB\xBF") == 0) out.erase(0, 3);
  return true;
}

// A carriage return within the first line: lines that end with CR alone (classic Mac OS) would
// be read as one line, the whole file a header.
void LineReader::refuse_cr_line_ends(std::string_view first_line) const {
  const std::size_t cr = first_line.find('\r');
  if (cr == std::string_view::npos) return;
  InputLocation where;
  where.file = path_;
  where.line = 1;
  where.column = cr + 1;
  throw InputError(where,
                   "a carriage return (CR) within the first line: the file's lines seem to end "
                   "with CR alone",
                   "convert the line ends to LF or CR LF, e.g. tr '\\r' '\\n' < IN > OUT");
}

// A line (or a record of lines joined by a quoted field) beyond kMaxCsvRecordBytes.
void LineReader::too_long(std::string_view what) const {
  InputLocation where;
  where.file = path_;
  where.line = what == "line" ? position_.line : record_line_;
  throw InputError(where,
                   fmt::format("a {} longer than {} MiB: the limit of one row of a CSV log", what,
                               kMaxCsvRecordBytes >> 20),
                   what == "line" ? "is this a text log? a binary file or one without line "
                                    "ends is not read"
                                  : "a quote opened in this row is not closed: check the "
                                    "quoting");
}

}  // namespace dynpos::io::detail
