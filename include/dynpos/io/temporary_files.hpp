#pragma once
/// \file
/// The temporary files of this process that an interrupted run must not leave behind:
/// AtomicFile's file before its rename, SpooledInput's copy of a pipe. The one process-wide list
/// of dynpos: a signal reaches a process, not an object, so the command line's signal thread
/// needs a list it can reach (apps/dynpos/main.cpp removes them on Ctrl-C, SIGTERM, SIGHUP).

#include <cstddef>
#include <filesystem>

namespace dynpos::io::temporary_files {

/// Lists `path` (a file, or a folder of files, this process just created).
void add(const std::filesystem::path& path);
/// Takes `path` off the list (renamed into place, or removed by its owner).
void drop(const std::filesystem::path& path);
/// Removes every listed file and folder and empties the list; returns how many were removed.
std::size_t remove_all() noexcept;

}  // namespace dynpos::io::temporary_files
