#pragma once
/// \file
/// The temporary files of this process that an interrupted run must not leave behind:
/// AtomicFile's file before its rename, SpooledInput's copy of a pipe. The one process-wide list
/// of dynpos: a signal reaches a process, not an object, so the command line's signal thread
/// needs a list it can reach (apps/dynpos/main.cpp removes them on Ctrl-C, SIGTERM, SIGHUP).
///
/// The signal's thread runs beside the threads that write, so two kinds of steps must not be
/// cut by it, and hold a Hold while they run: making a temporary file or folder and listing it
/// (else a file made just before the removal and listed just after is left), and placing a
/// run's files (else a signal between two renames leaves the new log.csv beside the truth.json
/// of another run). remove_all_for_exit() waits until no Hold is held, and none can be taken
/// after it: the signal waits for the step, never the other way round.

#include <cstddef>
#include <filesystem>

namespace dynpos::io::temporary_files {

/// Lists `path` (a file, or a folder of files, this process just created).
void add(const std::filesystem::path& path);
/// Takes `path` off the list (renamed into place, or removed by its owner).
void drop(const std::filesystem::path& path);
/// Removes every listed file and folder and empties the list; returns how many were removed.
/// Waits until no Hold is held.
std::size_t remove_all() noexcept;
/// remove_all(), and no Hold can be taken afterwards (a thread that tries waits for ever): for
/// a process about to end, so that no thread makes a file the removal no longer sees.
std::size_t remove_all_for_exit() noexcept;

/// While it lives, remove_all() waits: a short step of file-system work (no waiting for other
/// threads inside) that a signal must not cut. Holds of several threads run at once.
class Hold {
 public:
  Hold();
  ~Hold();
  Hold(const Hold&) = delete;
  Hold& operator=(const Hold&) = delete;
};

}  // namespace dynpos::io::temporary_files
