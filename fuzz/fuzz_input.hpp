#pragma once
// What every fuzz target shares. The readers under test take paths, as the CLI gives them, so
// each input is written to a file of this process first: in /dev/shm when the machine has it
// (memory, not disk), else in the temporary folder. The rule checked on every input is the
// product's own: bad input ends in core::InputError (exit 2, with file and line), never in a
// crash, a hang, a sanitizer report or any other exception (libFuzzer reports an escaping
// exception as a crash).

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace dynpos::fuzz {

/// A file of this process that holds the current input; removed with the process' last target.
class InputFile {
 public:
  explicit InputFile(std::string_view name) {
    std::error_code ec;
    std::filesystem::path dir = "/dev/shm";
    if (!std::filesystem::is_directory(dir, ec)) dir = std::filesystem::temp_directory_path();
    path_ = dir / ("dynpos-fuzz-" + std::to_string(::getpid()) + "-" + std::string(name));
  }
  ~InputFile() {
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  }
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  /// Replaces the file's content with `bytes`; returns its path.
  const std::filesystem::path& write(std::string_view bytes) {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return path_;
  }

 private:
  std::filesystem::path path_;
};

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// Splits an input at its first line "%%": the part before (e.g. a column map) and after (the
/// log). Without such a line, `first` is empty and `second` is the whole input.
struct Parts {
  std::string_view first;
  std::string_view second;
};
inline Parts split_at_marker(std::string_view text) {
  constexpr std::string_view kMarker = "\n%%\n";
  if (text.starts_with("%%\n")) return {{}, text.substr(3)};
  const auto at = text.find(kMarker);
  if (at == std::string_view::npos) return {{}, text};
  return {text.substr(0, at + 1), text.substr(at + kMarker.size())};
}

}  // namespace dynpos::fuzz
