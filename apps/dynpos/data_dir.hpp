#pragma once
// Where the built-in data (vessels, scenarios) is.

#include <cstdlib>
#include <filesystem>

#include "dynpos/core/error.hpp"

namespace dynpos::cli {

/// $DYNPOS_DATA_DIR if set; else ../share/dynpos beside an installed executable; else the
/// source tree's data/ folder the executable was built from.
inline std::filesystem::path find_data_dir() {
  if (const char* env = std::getenv("DYNPOS_DATA_DIR"); env != nullptr && *env != '\0') {
    return env;
  }
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const std::filesystem::path installed = exe.parent_path().parent_path() / "share" / "dynpos";
    if (std::filesystem::is_directory(installed / "scenarios")) return installed;
  }
  const std::filesystem::path source = DYNPOS_DATA_DIR;
  if (std::filesystem::is_directory(source / "scenarios")) return source;
  throw core::InputError({}, "cannot find the dynpos data folder (vessels, scenarios)",
                         "set DYNPOS_DATA_DIR to it");
}

}  // namespace dynpos::cli
