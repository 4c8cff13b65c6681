#pragma once
/// \file
/// What the machine has to give a run: memory that can be allocated without swapping, and free
/// space on the disk of a folder. For checks of a run's size before it starts; nullopt where
/// the system does not say.

#include <cstdint>
#include <filesystem>
#include <optional>

namespace dynpos::core {

/// MemAvailable of /proc/meminfo [bytes]: memory a new allocation can get without swapping.
std::optional<std::uint64_t> available_memory_bytes();

/// Free bytes for an unprivileged user on the file system of `path`, or of its nearest existing
/// parent folder when it does not exist yet (a folder about to be created).
std::optional<std::uint64_t> free_disk_bytes(const std::filesystem::path& path);

}  // namespace dynpos::core
