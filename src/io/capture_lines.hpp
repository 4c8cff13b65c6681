#pragma once
// The lines of an NMEA capture (private to the io module): a line ends at '\n', "\r\n" or a lone
// '\r' (as old terminals and some loggers write), a UTF-8 byte order mark before the first line
// is dropped, and a line is read up to a bound, so that a file without line ends costs bounded
// memory.

#include <cstddef>
#include <cstdint>
#include <istream>
#include <string>
#include <vector>

#include "bounded_line.hpp"

namespace dynpos::io::detail {

/// Reads the lines of a capture from a stream, in 64 KiB blocks.
class CaptureLines {
 public:
  explicit CaptureLines(std::istream& in) : in_(in), buffer_(std::size_t{1} << 16) {}

  /// The next line into `out`, without its line end: kLine; kEnd at the end of the stream; or
  /// kTooLong with the first max_bytes of the line in `out`.
  LineStatus next(std::string& out, std::size_t max_bytes);
  /// Whether the line last read had its line end (false: the stream ended inside it, or a
  /// kTooLong line goes on).
  bool ended() const noexcept { return ended_; }
  /// After a kTooLong line: reads on past its end (if not ended()); false when more than about
  /// max_bytes come before it.
  bool skip_rest(std::size_t max_bytes);
  /// Bytes taken so far, line ends included.
  std::uint64_t bytes() const noexcept { return taken_ - (end_ - pos_); }
  /// Reading the stream failed.
  bool bad() const { return in_.bad(); }

 private:
  bool fill();
  // Takes the bytes up to the next line end in the buffer (and the line end), appending at most
  // `room` of them to `out`; the number of bytes before the line end. Sets ended_.
  std::size_t take(std::string* out, std::size_t room);

  std::istream& in_;
  std::vector<char> buffer_;
  std::size_t pos_ = 0, end_ = 0;
  std::uint64_t taken_ = 0;
  bool ended_ = false;
  bool after_cr_ = false;  // the last line ended with '\r': a '\n' right after it is its end too
  bool first_ = true;
};

/// The error of a line of `file` without a line end within max_bytes: "not a text capture".
[[noreturn]] void throw_no_line_end(const std::string& file, std::size_t line,
                                    std::size_t max_bytes);

}  // namespace dynpos::io::detail
