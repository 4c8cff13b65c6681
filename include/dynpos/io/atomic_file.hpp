#pragma once
/// \file
/// AtomicFile: write an output file so that it either appears complete or not at all.
///
/// Text goes to a temporary file in the target's directory (same file system, so the final
/// rename is atomic); commit() flushes, checks the stream, and renames it onto the target.
/// If the AtomicFile is destroyed without commit() (an exception, an early return) the
/// temporary file is removed and an existing target is left untouched. This guards against
/// half-written outputs, not against power loss: the data is flushed to the OS, not synced.

#include <filesystem>
#include <fstream>
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
  /// std::runtime_error with the path and the reason if writing or renaming failed (the
  /// temporary file is then removed). Calling it twice is an error (std::logic_error).
  void commit();

  bool committed() const noexcept { return committed_; }
  const std::filesystem::path& target() const noexcept { return target_; }
  const std::filesystem::path& temp_path() const noexcept { return temp_; }

 private:
  std::filesystem::path target_;
  std::filesystem::path temp_;
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace dynpos::io
