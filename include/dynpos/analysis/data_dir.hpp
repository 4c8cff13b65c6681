#pragma once
/// \file
/// Where the built-in data (vessels, scenarios) is.

#include <filesystem>

namespace dynpos::analysis {

/// $DYNPOS_DATA_DIR if set; else ../share/dynpos beside the running executable (an installed
/// dynpos); else the source tree's data/ folder it was built from (a build-tree binary reads its
/// own data, not an older installed copy); else the configured prefix's share/dynpos.
/// InputError if none holds a scenarios/ folder.
std::filesystem::path find_data_dir();

/// `given`, or the built-in vessel (the virtual R/V Gunnerus, vessels/gunnerus.toml of
/// find_data_dir()) when it is empty.
std::filesystem::path vessel_file_or_default(const std::filesystem::path& given = {});

}  // namespace dynpos::analysis
