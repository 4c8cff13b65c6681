#include "dynpos/io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>
#include <stdexcept>
#include <streambuf>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "dynpos/core/error.hpp"
#include "dynpos/io/temporary_files.hpp"

namespace dynpos::io {
namespace {

std::string reason(int error) { return error != 0 ? std::strerror(error) : "unknown error"; }

enum class TargetKind { kNew, kRegular, kThrough };

// How `target` is written, by the rules of the header; `file` receives what is written (the
// target, or the file a symbolic link points to). Throws for what is refused.
TargetKind classify(const std::filesystem::path& target, std::filesystem::path& file,
                    struct stat& info) {
  if (target.filename().empty()) {
    throw std::runtime_error(fmt::format("cannot write '{}': not a file name", target.string()));
  }
  file = target;
  struct stat link {};
  if (::lstat(target.c_str(), &link) != 0) {
    if (errno == ENOENT) return TargetKind::kNew;
    throw std::runtime_error(fmt::format("cannot write '{}': {}", target.string(), reason(errno)));
  }
  if (S_ISLNK(link.st_mode)) {
    std::error_code error;
    file = std::filesystem::canonical(target, error);
    if (error) {
      throw std::runtime_error(
          fmt::format("cannot write '{}': it is a symbolic link to a missing file or folder ({})",
                      target.string(), error.message()));
    }
  }
  if (::stat(file.c_str(), &info) != 0) {
    throw std::runtime_error(fmt::format("cannot write '{}': {}", target.string(), reason(errno)));
  }
  if (S_ISCHR(info.st_mode) || S_ISFIFO(info.st_mode)) return TargetKind::kThrough;
  const char* what = S_ISDIR(info.st_mode)    ? "a folder"
                     : S_ISBLK(info.st_mode)  ? "a block device"
                     : S_ISSOCK(info.st_mode) ? "a socket"
                                              : nullptr;
  if (what != nullptr) {
    throw std::runtime_error(
        fmt::format("cannot write '{}': it is {}, not a file", target.string(), what));
  }
  if ((info.st_mode & 0222) == 0) {
    throw std::runtime_error(fmt::format(
        "cannot write '{}': the file is read-only (mode {:04o}); remove it or make it writable "
        "first, or choose another name",
        target.string(), info.st_mode & 07777));
  }
  return TargetKind::kRegular;
}

// Syncs the file or folder at `path` to the disk; returns errno, 0 on success.
int sync_path(const std::filesystem::path& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
  if (fd < 0) return errno;
  const int result = ::fsync(fd) == 0 ? 0 : errno;
  ::close(fd);
  return result;
}

// What to do about a write that failed with `error`, after the system's text.
std::string write_hint(int error) {
  switch (error) {
    case ENOSPC:
    case EDQUOT:
      return "free some space or write elsewhere";
    case EFBIG:
      return "the file is larger than the file system or the process's limit (ulimit -f) "
             "allows; raise the limit or write elsewhere";
    default:
      return "check the disk and the path";
  }
}

}  // namespace

// Writes to a file descriptor through a 64 KiB buffer; the first failed write's errno is kept
// (a std::ofstream loses it: by commit() errno says nothing or something else) and every later
// write is refused, so the stream fails at once.
class AtomicFile::Buffer : public std::streambuf {
 public:
  explicit Buffer(int fd) : fd_(fd), data_(std::size_t{1} << 16) {
    setp(data_.data(), data_.data() + data_.size());
  }
  ~Buffer() override { (void)close(); }
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  int error() const noexcept { return error_; }
  // Writes what is buffered, syncs it to the disk if asked and closes; returns the errno of the
  // first failure, 0 if none.
  int finish(bool to_disk) {
    (void)drain();
    if (error_ == 0 && to_disk && fd_ >= 0 && ::fsync(fd_) != 0) error_ = errno;
    if (close() != 0 && error_ == 0) error_ = errno;
    return error_;
  }

 protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    *pptr() = traits_type::to_char_type(c);
    pbump(1);
    return c;
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  bool drain() {
    const char* at = pbase();
    while (error_ == 0 && at < pptr()) {
      const ssize_t put = ::write(fd_, at, static_cast<std::size_t>(pptr() - at));
      if (put < 0 && errno == EINTR) continue;
      if (put <= 0) {
        error_ = put < 0 ? errno : EIO;
        break;
      }
      at += put;
    }
    setp(data_.data(), data_.data() + data_.size());
    return error_ == 0;
  }
  int close() {
    if (fd_ < 0) return 0;
    const int result = ::close(fd_);
    fd_ = -1;
    return result;
  }

  int fd_;
  std::vector<char> data_;
  int error_ = 0;
};

void check_output_target(const std::filesystem::path& target) {
  std::filesystem::path file;
  struct stat info {};
  classify(target, file, info);
}

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)), out_(nullptr) {
  struct stat info {};
  const TargetKind kind = classify(target_, file_, info);
  if (kind == TargetKind::kThrough) {
    const int fd = ::open(file_.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) {
      throw std::runtime_error(
          fmt::format("cannot open '{}' for writing: {}", target_.string(), reason(errno)));
    }
    buffer_ = std::make_unique<Buffer>(fd);
    out_.rdbuf(buffer_.get());
    return;
  }
  if (kind == TargetKind::kRegular) {
    keep_mode_ = static_cast<int>(info.st_mode & 07777);
    keep_uid_ = static_cast<int>(info.st_uid);
    keep_gid_ = static_cast<int>(info.st_gid);
  }
  create_temp();
}

void AtomicFile::create_temp() {
  const std::filesystem::path dir = file_.parent_path();
  // A random suffix only makes the name unique; O_EXCL guarantees we never reuse a file.
  std::random_device entropy;
  for (int attempt = 0;; ++attempt) {
    const std::string name =
        fmt::format(".{}.tmp-{}-{:08x}", file_.filename().string(), ::getpid(), entropy());
    temp_ = dir.empty() ? std::filesystem::path(name) : dir / name;
    // 0666 minus the umask: the same permissions a plain new file would get. Made and listed
    // as one step, which a signal's removal waits for.
    const temporary_files::Hold hold;
    const int fd = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      temporary_files::add(temp_);
      if (keep_mode_ >= 0) {
        if (::geteuid() == 0) (void)::fchown(fd, keep_uid_, keep_gid_);
        (void)::fchmod(fd, static_cast<mode_t>(keep_mode_));
      }
      buffer_ = std::make_unique<Buffer>(fd);
      out_.rdbuf(buffer_.get());
      return;
    }
    const int error = errno;
    if (error != EEXIST || attempt >= 100) {
      temp_.clear();
      throw std::runtime_error(fmt::format(
          "cannot create a temporary file for '{}' in '{}': {}; check that the folder exists "
          "and is writable",
          target_.string(), dir.empty() ? "." : dir.string(), reason(error)));
    }
  }
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  out_.rdbuf(nullptr);
  buffer_.reset();  // closes the file
  if (!temp_.empty()) discard_temp();
}

void AtomicFile::discard_temp() {
  const temporary_files::Hold hold;  // removed and taken off the list as one step
  std::error_code ignored;
  std::filesystem::remove(temp_, ignored);
  temporary_files::drop(temp_);
}

void AtomicFile::commit() {
  if (committed_) throw std::logic_error("AtomicFile::commit() called twice");
  const bool stream_ok = static_cast<bool>(out_);
  int error = buffer_->finish(!temp_.empty());  // a temporary file is synced before its rename
  out_.rdbuf(nullptr);
  if (error == 0 && !stream_ok) error = EIO;  // not the file's: a formatting failure
  if (error != 0) {
    if (!temp_.empty()) discard_temp();
    const std::string problem = fmt::format("writing it failed: {}", reason(error));
    if (error == ENOSPC || error == EDQUOT || error == EFBIG) {
      throw core::InputError({target_.string(), {}, {}, {}}, problem, write_hint(error));
    }
    throw std::runtime_error(fmt::format("writing '{}' failed: {}; {}", target_.string(),
                                         reason(error), write_hint(error)));
  }
  if (temp_.empty()) {  // written through
    committed_ = true;
    return;
  }
  {
    // Renamed and taken off the list as one step: a signal's removal of the folder the file is
    // in (a run's hidden folder) does not meet a file that vanishes under it.
    const temporary_files::Hold hold;
    if (std::rename(temp_.c_str(), file_.c_str()) != 0) error = errno;
    if (error == 0) temporary_files::drop(temp_);
  }
  if (error != 0) {
    discard_temp();
    throw std::runtime_error(fmt::format("cannot rename '{}' to '{}': {}", temp_.string(),
                                         target_.string(), reason(error)));
  }
  const std::filesystem::path dir = file_.parent_path();
  (void)sync_path(dir.empty() ? std::filesystem::path(".") : dir, O_RDONLY | O_DIRECTORY);
  committed_ = true;
}

}  // namespace dynpos::io
