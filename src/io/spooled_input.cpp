#include "dynpos/io/spooled_input.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "dynpos/core/error.hpp"
#include "dynpos/io/csv_reader.hpp"
#include "dynpos/io/nmea_log.hpp"
#include "dynpos/io/temporary_files.hpp"

namespace dynpos::io {
namespace {

static_assert(kMaxSpoolLineBytes >= kMaxNmeaJunkBytes && kMaxSpoolLineBytes >= kMaxCsvRecordBytes,
              "a copy takes every line a reader takes");

// The problem of a failed system call: what failed, then why (errno `error`).
std::string failed(std::string_view what, int error) {
  return fmt::format("{}: {}", what, std::strerror(error));
}

// The place of an error in the file `file` as a whole.
core::InputLocation in_file(std::string file) {
  core::InputLocation where;
  where.file = std::move(file);
  return where;
}

// Writes all of [data, data + size) to fd; false with errno set on failure.
bool write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t put = ::write(fd, data, size);
    if (put < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    data += put;
    size -= static_cast<std::size_t>(put);
  }
  return true;
}

// True for a line that holds an NMEA sentence with its checksum ("…$GPGGA,…*hh", spaces
// after it aside): an address of at least four capitals or digits, a comma, and the checksum,
// which random bytes give about once in 10⁹ lines.
bool checksummed_sentence(std::string_view line) {
  while (!line.empty() && (line.back() == ' ' || line.back() == '\t')) line.remove_suffix(1);
  const std::size_t start = line.rfind('$');
  if (start == std::string_view::npos || line.size() < start + 10) return false;
  const std::string_view sentence = line.substr(start + 1);
  const std::size_t star = sentence.size() - 3;
  const std::size_t comma = sentence.find(',');
  if (sentence[star] != '*' || comma < 4 || comma > star) return false;
  const auto address = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'); };
  if (!std::all_of(sentence.begin(), sentence.begin() + comma, address)) return false;
  unsigned sum = 0;
  for (std::size_t i = 0; i < star; ++i) sum ^= static_cast<unsigned char>(sentence[i]);
  const char* hex = "0123456789ABCDEF";
  const auto upper = [](char c) { return c >= 'a' && c <= 'f' ? static_cast<char>(c - 32) : c; };
  return upper(sentence[star + 1]) == hex[sum >> 4] && upper(sentence[star + 2]) == hex[sum & 15];
}

// Tells a text log from endless binary data with line ends (/dev/urandom) in the first bytes of
// a copy: a text log soon has 100 text lines in a row (tab, printable ASCII or bytes of 0x80 and
// above; blank lines aside), a text line of 64 KiB, or an NMEA sentence with its checksum (a
// capture may hold the binary messages of another protocol between its sentences). Looks at
// each byte only until it is decided: a log costs its first hundred lines.
class TextProbe {
 public:
  bool text() const noexcept { return text_; }
  void feed(const char* data, std::size_t size) {
    for (const char* c = data; c != data + size && !text_; ++c) {
      if (*c == '\n' || *c == '\r') {
        end_line();
        continue;
      }
      const auto u = static_cast<unsigned char>(*c);
      line_text_ = line_text_ && ((u >= 0x20 && u != 0x7f) || u == '\t');
      if (head_.size() < kHeadBytes) head_.push_back(*c);
      text_ = line_text_ && ++line_bytes_ >= kLongLineBytes;
    }
  }

 private:
  static constexpr std::size_t kHeadBytes = 128, kLongLineBytes = 64 << 10, kRunLines = 100;
  void end_line() {
    if (line_bytes_ == 0 && head_.empty()) return;  // a blank line, or the LF of a CR LF
    run_ = line_text_ ? run_ + 1 : 0;
    text_ = run_ >= kRunLines || (head_.size() < kHeadBytes && checksummed_sentence(head_));
    head_.clear();
    line_bytes_ = 0;
    line_text_ = true;
  }
  bool text_ = false;
  bool line_text_ = true;
  std::size_t line_bytes_ = 0, run_ = 0;
  std::string head_;  // the line's first kHeadBytes bytes
};

// What copy_lines() did.
struct Copied {
  std::uint64_t bytes = 0;
  int error = 0;  // errno of a failed read or write
  bool read_failed = false;
  bool endless_line = false;     // a line longer than kMaxSpoolLineBytes
  std::uint64_t line_start = 0;  // where that line starts
  bool binary = false;           // no sign of text in the first kMaxSpoolLineBytes
};

// The two ends of a copy: file descriptors open for reading and for writing.
struct CopyEnds {
  int in;
  int out;
};

// Copies `ends.in` to `ends.out` through a 1 MiB buffer, up to a line (ended by '\n' or '\r')
// longer than kMaxSpoolLineBytes, or up to kMaxSpoolLineBytes of binary data (TextProbe). Only
// the first and the last line end of each buffer are looked for: a log costs a few bytes of
// search a MiB.
//
// The verdict depends on the bytes alone, never on how a pipe splits them into reads: the probe
// sees exactly the first kMaxSpoolLineBytes (a read never crosses that mark), and binary data is
// told only once the line open at the mark has ended; if it runs past its own limit instead, the
// error is the endless line (`/dev/zero` is line 1 without an end, not "binary").
Copied copy_lines(CopyEnds ends) {
  const auto is_end = [](char c) { return c == '\n' || c == '\r'; };
  std::vector<char> buffer(std::size_t{1} << 20);
  TextProbe probe;
  Copied c;
  bool binary_start = false;  // the first kMaxSpoolLineBytes held no sign of text
  for (;;) {
    std::size_t want = buffer.size();
    if (c.bytes < kMaxSpoolLineBytes) {
      want = static_cast<std::size_t>(std::min<std::uint64_t>(want, kMaxSpoolLineBytes - c.bytes));
    }
    const ssize_t got = ::read(ends.in, buffer.data(), want);
    if (got == 0) {
      c.binary = binary_start && c.bytes > kMaxSpoolLineBytes;
      return c;
    }
    if (got < 0) {
      if (errno == EINTR) continue;
      c.error = errno;
      c.read_failed = true;
      return c;
    }
    const char* begin = buffer.data();
    const char* end = begin + got;
    const char* first = std::find_if(begin, end, is_end);
    if (c.bytes + static_cast<std::uint64_t>(first - begin) - c.line_start > kMaxSpoolLineBytes) {
      c.endless_line = true;
      return c;
    }
    if (binary_start && (first != end || c.line_start == c.bytes)) {
      c.binary = true;  // the line open at the mark has ended, or none was open
      return c;
    }
    if (first != end) {
      const char* last = end - 1;
      while (!is_end(*last)) --last;
      c.line_start = c.bytes + static_cast<std::uint64_t>(last + 1 - begin);
    }
    if (!binary_start) {
      probe.feed(begin, static_cast<std::size_t>(got));
      if (!probe.text() && c.bytes + static_cast<std::uint64_t>(got) == kMaxSpoolLineBytes) {
        binary_start = true;  // nothing after the mark is copied: the copy will be removed
      }
      if (!write_all(ends.out, begin, static_cast<std::size_t>(got))) {
        c.error = errno;
        return c;
      }
    }
    c.bytes += static_cast<std::uint64_t>(got);
  }
}

// The line of a text file at byte `offset`, its line ends '\n', "\r\n" or a lone '\r'.
std::size_t line_of(const std::filesystem::path& file, std::uint64_t offset) {
  std::ifstream in(file, std::ios::binary);
  std::vector<char> buffer(std::size_t{1} << 20);
  std::size_t line = 1;
  char previous = '\0';
  while (offset > 0 && in) {
    in.read(buffer.data(),
            static_cast<std::streamsize>(std::min<std::uint64_t>(offset, buffer.size())));
    const auto got = static_cast<std::size_t>(in.gcount());
    for (std::size_t i = 0; i < got; ++i) {
      const char c = buffer[i];
      if (c == '\r' || (c == '\n' && previous != '\r')) ++line;
      previous = c;
    }
    offset -= got;
    if (got == 0) break;
  }
  return line;
}

}  // namespace

bool needs_spool(const std::filesystem::path& path) {
  if (path == "-") return true;
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  return !ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status) &&
         !std::filesystem::is_directory(status);
}

SpooledInput::SpooledInput(const std::filesystem::path& path, std::filesystem::path dir) {
  const std::string name = path == "-" ? "standard input" : path.string();
  const int in = path == "-" ? STDIN_FILENO : ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (in < 0) {
    const int error = errno;
    throw core::InputError(in_file(name), failed("cannot open it", error),
                           "check the path and its permissions");
  }
  if (dir.empty()) dir = std::filesystem::temp_directory_path();
  // mkstemp() replaces the six X with a unique suffix and creates the file.
  std::string pattern = (dir / "dynpos-input-XXXXXX").string();
  const int out = ::mkstemp(pattern.data());
  if (out < 0) {
    const int error = errno;
    if (in != STDIN_FILENO) ::close(in);
    throw core::InputError(
        in_file(dir.string()),
        failed("cannot make a copy of " + name + " in this folder to read it", error),
        "set TMPDIR to a folder with space and write permission");
  }
  copy_ = pattern;
  temporary_files::add(copy_);
  const Copied copied = copy_lines({.in = in, .out = out});
  if (in != STDIN_FILENO) ::close(in);
  int error = copied.error;
  if (::close(out) != 0 && error == 0) error = errno;
  bytes_ = copied.bytes;
  if (error == 0 && !copied.endless_line && !copied.binary) return;
  std::size_t line = 0;
  if (copied.endless_line) line = line_of(copy_, copied.line_start);
  std::error_code ignored;
  std::filesystem::remove(copy_, ignored);
  temporary_files::drop(copy_);
  if (copied.endless_line) {
    throw core::InputError(
        {name, line, {}, {}},
        fmt::format("no line end within {} MiB: not a text log", kMaxSpoolLineBytes >> 20),
        "give a CSV log or an NMEA capture, one record a line");
  }
  if (copied.binary) {
    throw core::InputError({name, {}, {}, {}},
                           fmt::format("not a text log: its first {} MiB hold neither 100 text "
                                       "lines in a row nor an NMEA sentence with its checksum",
                                       kMaxSpoolLineBytes >> 20),
                           "give a CSV log or an NMEA capture; is this the right file?");
  }
  if (copied.read_failed) {
    throw core::InputError(in_file(name), failed("reading it failed", error),
                           "check that it is readable");
  }
  throw core::InputError(
      in_file(copy_.string()), failed("cannot copy " + name + " to read it", error),
      error == ENOSPC ? "free some space, or set TMPDIR to a folder with space"
                      : "set TMPDIR to a folder with space and write permission");
}

SpooledInput::~SpooledInput() {
  std::error_code ignored;
  std::filesystem::remove(copy_, ignored);
  temporary_files::drop(copy_);
}

}  // namespace dynpos::io
