#pragma once
// The file a live session's lines accumulate in (private to the live module): the one the user
// named, or a temporary file listed for removal on a signal and removed with its owner.

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string_view>

namespace dynpos::live::detail {

class CaptureFile {
 public:
  /// Creates (truncates) `path`, or a temporary file when it is empty. Throws
  /// analysis::option_error("capture") when it cannot be created.
  explicit CaptureFile(const std::filesystem::path& path);
  ~CaptureFile();
  CaptureFile(const CaptureFile&) = delete;
  CaptureFile& operator=(const CaptureFile&) = delete;

  void append(std::string_view bytes);
  /// Flushes what was appended, so that a reader of path() sees it. Throws on a write error.
  void flush();
  const std::filesystem::path& path() const noexcept { return path_; }
  std::uint64_t bytes() const noexcept { return bytes_; }

 private:
  std::filesystem::path path_;
  std::FILE* file_ = nullptr;
  bool temporary_ = false;
  std::uint64_t bytes_ = 0;
};

}  // namespace dynpos::live::detail
