#pragma once
/// \file
/// An input that can be read only once (standard input "-", a pipe, a FIFO, a character
/// device), copied once to a temporary file so that readers may open it as often as they need
/// (the header, the format sniff, the rows in blocks). The copy streams through a small
/// buffer: memory does not grow with the input, the disk holds it.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

namespace dynpos::io {

/// The longest line a copy takes [bytes], its line end '\n' or '\r': the most a reader skips
/// without a line end (an NMEA capture's 16 MiB of binary data, io::kMaxNmeaJunkBytes; a CSV
/// record's 8 MiB). A longer one (/dev/zero, a binary stream) stops the copy with an error: a
/// log of any length is copied, an input without line ends costs 16 MiB of disk, not all of it.
inline constexpr std::size_t kMaxSpoolLineBytes = std::size_t{16} << 20;

/// True when `path` must be spooled to be read more than once: "-" (standard input) or an
/// existing file that is not a regular file (a FIFO, a character device, /dev/stdin on a pipe).
bool needs_spool(const std::filesystem::path& path);

/// The copy of one such input, removed with the object.
class SpooledInput {
 public:
  /// Copies `path` ("-": standard input) into a new file in `dir` (default: the temporary
  /// folder). Throws core::InputError naming `path` if it cannot be read or holds a line longer
  /// than kMaxSpoolLineBytes (naming the line), or naming the copy with the system's reason if
  /// it cannot be written (e.g. no space left). No copy is left after an error.
  explicit SpooledInput(const std::filesystem::path& path, std::filesystem::path dir = {});
  ~SpooledInput();
  SpooledInput(const SpooledInput&) = delete;
  SpooledInput& operator=(const SpooledInput&) = delete;

  /// The copy, a regular file.
  const std::filesystem::path& path() const noexcept { return copy_; }
  /// Bytes copied.
  std::uint64_t bytes() const noexcept { return bytes_; }

 private:
  std::filesystem::path copy_;
  std::uint64_t bytes_ = 0;
};

}  // namespace dynpos::io
