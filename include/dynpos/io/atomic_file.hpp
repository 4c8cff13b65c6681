#pragma once
/// \file
/// AtomicFile: write an output file so that it either appears complete or not at all.
///
/// Text goes to a temporary file in the target's directory (same file system, so the final
/// rename is atomic); commit() flushes, checks the stream, syncs the data to the disk and renames
/// it onto the target. If the AtomicFile is destroyed without commit() (an exception, an early
/// return) the temporary file is removed and an existing target is left untouched.
///
/// What is at the target decides how it is written (docs/reliability.md, "Outputs"):
/// - nothing, or a regular file: replaced atomically; an existing file keeps its mode (and, for
///   root, its owner); a file without any write permission is refused, even for root;
/// - a symbolic link: the file it points to is written by these rules, the link is kept; a link
///   to nothing is refused;
/// - a character device or a FIFO (/dev/null, /dev/stdout, a named pipe): written through,
///   never replaced; such an output is not atomic;
/// - a directory, a block device or a socket: refused.
/// Refusals and failures throw std::runtime_error naming the path, the reason (the system's
/// errno text, kept from the write that failed) and what to do; a write the user can make
/// succeed (no space: ENOSPC, EDQUOT; a file over the size limit: EFBIG) throws
/// core::InputError (the CLI's exit 2).

#include <filesystem>
#include <memory>
#include <ostream>

namespace dynpos::io {

class AtomicFile {
 public:
  /// Creates the temporary file "<dir>/.<name>.tmp-<unique>" beside `target`.
  /// Throws std::runtime_error with the path and the system's reason if it cannot.
  explicit AtomicFile(std::filesystem::path target);
  /// Removes the temporary file unless committed; never throws.
  ~AtomicFile();

  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  AtomicFile(AtomicFile&&) = delete;
  AtomicFile& operator=(AtomicFile&&) = delete;

  /// The stream to write to (until commit()).
  std::ostream& stream() noexcept { return out_; }

  /// Flushes and closes the temporary file and renames it onto the target. Throws
  /// std::runtime_error (core::InputError for no space or a file too large) with the path and
  /// the reason if writing or renaming failed (the temporary file is then removed). Calling it
  /// twice is an error (std::logic_error).
  void commit();

  bool committed() const noexcept { return committed_; }
  const std::filesystem::path& target() const noexcept { return target_; }
  /// The temporary file; empty when the target is written through (a device or a FIFO).
  const std::filesystem::path& temp_path() const noexcept { return temp_; }

 private:
  class Buffer;  // a stream buffer on a file descriptor that keeps the errno of a failed write

  void create_temp();
  /// Removes the temporary file and takes it off temporary_files' list.
  void discard_temp();

  std::filesystem::path target_;  // as given, for messages
  std::filesystem::path file_;    // what is written: the target, or what its link points to
  std::filesystem::path temp_;
  std::unique_ptr<Buffer> buffer_;
  std::ostream out_;
  int keep_mode_ = -1;  // mode of a replaced file
  int keep_uid_ = -1, keep_gid_ = -1;
  bool committed_ = false;
};

/// Throws std::runtime_error if `target` cannot be written by AtomicFile's rules (a directory,
/// a read-only file, a block device, a dangling link), before any work is done.
void check_output_target(const std::filesystem::path& target);

}  // namespace dynpos::io
