#pragma once
// The lines of a CSV log and the records they make (private to the io module): physical lines
// read with a bound, CR LF and LF line ends, a UTF-8 byte-order mark dropped, blank and comment
// lines skipped, and a record joined from several lines while a quoted field is open.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace dynpos::io::detail {

/// A line start: its byte offset in the file and the physical lines before it.
struct LinePosition {
  std::uint64_t offset = 0;
  std::size_t line = 0;
};

/// Reads the records of a CSV log. Throws core::InputError naming the file and line when the
/// file cannot be opened or read, when its first line holds a CR (lines ended by CR alone),
/// and for a line or record longer than kMaxCsvRecordBytes.
class LineReader {
 public:
  LineReader(const std::filesystem::path& path, std::string comment_prefix);

  const std::string& path() const noexcept { return path_; }

  /// The next record that is not blank or a comment, without its line end, and the line it
  /// starts on (1-based); false at the end of the file.
  bool next(std::string& record, std::size_t& record_line);

  /// Appends '\n' and the next physical line to a record whose quoted field is still open;
  /// false at the end of the file.
  bool continue_record(std::string& record);

  /// The physical lines read so far.
  std::size_t line() const noexcept { return position_.line; }
  /// Where the next physical line starts.
  LinePosition position() const noexcept { return position_; }
  /// Whether the log is a regular file (the block parser reads it at offsets).
  bool regular() const { return std::filesystem::is_regular_file(path_); }

  /// Continues at `at`, a line start (from position()).
  void seek(LinePosition at);

 private:
  bool read_physical(std::string& out);
  void refuse_cr_line_ends(std::string_view first_line) const;
  [[noreturn]] void too_long(std::string_view what) const;

  std::ifstream in_;
  std::string path_;
  std::string comment_prefix_;
  LinePosition position_;
  std::size_t record_line_ = 0;  // the first line of the record being read
};

}  // namespace dynpos::io::detail
