#include "dynpos/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

namespace dynpos::io {
namespace {

std::string reason(int error) { return error != 0 ? std::strerror(error) : "unknown error"; }

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)) {
  if (target_.filename().empty()) {
    throw std::runtime_error(fmt::format("cannot write '{}': not a file name", target_.string()));
  }
  const std::filesystem::path dir = target_.parent_path();
  // A random suffix only makes the name unique; O_EXCL guarantees we never reuse a file.
  std::random_device entropy;
  for (int attempt = 0;; ++attempt) {
    const std::string name =
        fmt::format(".{}.tmp-{}-{:08x}", target_.filename().string(), ::getpid(), entropy());
    temp_ = dir.empty() ? std::filesystem::path(name) : dir / name;
    // 0666 minus the umask: the same permissions a plain new file would get.
    const int fd = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      break;
    }
    const int error = errno;
    if (error != EEXIST || attempt >= 100) {
      throw std::runtime_error(fmt::format("cannot create a temporary file for '{}' in '{}': {}",
                                           target_.string(), dir.empty() ? "." : dir.string(),
                                           reason(error)));
    }
  }
  out_.open(temp_, std::ios::binary | std::ios::trunc);
  if (!out_) {
    const int error = errno;
    std::error_code ignored;
    std::filesystem::remove(temp_, ignored);
    throw std::runtime_error(
        fmt::format("cannot open '{}' for writing: {}", temp_.string(), reason(error)));
  }
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  if (out_.is_open()) out_.close();
  std::error_code ignored;
  std::filesystem::remove(temp_, ignored);
}

void AtomicFile::commit() {
  if (committed_) throw std::logic_error("AtomicFile::commit() called twice");
  errno = 0;
  out_.flush();
  const bool written = static_cast<bool>(out_);
  int error = errno;
  out_.close();
  if (!written || out_.fail()) {
    if (error == 0) error = errno;
    std::error_code ignored;
    std::filesystem::remove(temp_, ignored);
    throw std::runtime_error(
        fmt::format("writing '{}' failed: {}", target_.string(), reason(error)));
  }
  if (std::rename(temp_.c_str(), target_.c_str()) != 0) {
    error = errno;
    std::error_code ignored;
    std::filesystem::remove(temp_, ignored);
    throw std::runtime_error(fmt::format("cannot rename '{}' to '{}': {}", temp_.string(),
                                         target_.string(), reason(error)));
  }
  committed_ = true;
}

}  // namespace dynpos::io
