#include "dynpos/io/spooled_input.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>

#include <fmt/format.h>

#include "dynpos/core/error.hpp"
#include "dynpos/io/temporary_files.hpp"

namespace dynpos::io {
namespace {

[[noreturn]] void fail(const std::string& file, const std::string& what, int error,
                       const std::string& hint) {
  core::InputLocation where;
  where.file = file;
  throw core::InputError(where, fmt::format("{}: {}", what, std::strerror(error)), hint);
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
  if (in < 0) fail(name, "cannot open it", errno, "check the path and its permissions");
  if (dir.empty()) dir = std::filesystem::temp_directory_path();
  // mkstemp() replaces the six X with a unique suffix and creates the file.
  std::string pattern = (dir / "dynpos-input-XXXXXX").string();
  const int out = ::mkstemp(pattern.data());
  if (out < 0) {
    const int error = errno;
    if (in != STDIN_FILENO) ::close(in);
    fail(dir.string(), "cannot make a copy of " + name + " in this folder to read it", error,
         "set TMPDIR to a folder with space and write permission");
  }
  copy_ = pattern;
  temporary_files::add(copy_);
  std::vector<char> buffer(std::size_t{1} << 20);
  int error = 0;
  bool read_failed = false;
  for (;;) {
    const ssize_t got = ::read(in, buffer.data(), buffer.size());
    if (got == 0) break;
    if (got < 0) {
      if (errno == EINTR) continue;
      error = errno;
      read_failed = true;
      break;
    }
    if (!write_all(out, buffer.data(), static_cast<std::size_t>(got))) {
      error = errno;
      break;
    }
    bytes_ += static_cast<std::uint64_t>(got);
  }
  if (in != STDIN_FILENO) ::close(in);
  if (::close(out) != 0 && error == 0) error = errno;
  if (error != 0) {
    std::error_code ignored;
    std::filesystem::remove(copy_, ignored);
    temporary_files::drop(copy_);
    if (read_failed) fail(name, "reading it failed", error, "check that it is readable");
    fail(copy_.string(), "cannot copy " + name + " to read it", error,
         error == ENOSPC ? "free some space, or set TMPDIR to a folder with space"
                         : "set TMPDIR to a folder with space and write permission");
  }
}

SpooledInput::~SpooledInput() {
  std::error_code ignored;
  std::filesystem::remove(copy_, ignored);
  temporary_files::drop(copy_);
}

}  // namespace dynpos::io
