#pragma once
/// \file
/// A whole text file read into memory (a JSON result, a TOML vessel, scenario or column map),
/// with a cap on its size: a device without end (/dev/zero) or a huge file is an error naming
/// it, not memory that grows until the machine runs out.

#include <cstdint>
#include <filesystem>
#include <istream>
#include <string>

namespace dynpos::io {

/// The most bytes of a JSON document read whole (compare's results, montecarlo's shards,
/// truth.json): 64 MiB, far beyond any result's few MB.
inline constexpr std::uint64_t kMaxJsonBytes = std::uint64_t{64} << 20;
/// The most bytes of a TOML file (vessel, scenario, column map, site table): 16 MiB, far beyond
/// their few kB.
inline constexpr std::uint64_t kMaxTomlBytes = std::uint64_t{16} << 20;

/// All of `in`, opened on `path`, if it holds at most max_bytes. A regular file is refused by
/// its size before it is read; anything else (a device, a pipe) is read up to max_bytes and
/// refused at the next byte. Throws core::InputError naming `path` ("more than N MiB", with
/// `hint`), or when reading fails.
std::string read_capped(std::istream& in, const std::filesystem::path& path,
                        std::uint64_t max_bytes, const std::string& hint);

}  // namespace dynpos::io
