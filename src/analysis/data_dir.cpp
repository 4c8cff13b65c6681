#include "dynpos/analysis/data_dir.hpp"

#include <cstdlib>

#include "dynpos/core/error.hpp"

namespace dynpos::analysis {

std::filesystem::path find_data_dir() {
  if (const char* env = std::getenv("DYNPOS_DATA_DIR"); env != nullptr && *env != '\0') {
    return env;
  }
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const std::filesystem::path installed = exe.parent_path().parent_path() / "share" / "dynpos";
    if (std::filesystem::is_directory(installed / "scenarios")) return installed;
  }
  // A binary of the build tree reads its own source tree's data, not an older installed copy;
  // an installed one found its data beside it above.
  for (const std::filesystem::path dir : {DYNPOS_SOURCE_DATA_DIR, DYNPOS_INSTALL_DATA_DIR}) {
    if (std::filesystem::is_directory(dir / "scenarios")) return dir;
  }
  throw core::InputError({}, "cannot find the dynpos data folder (vessels, scenarios)",
                         "set DYNPOS_DATA_DIR to it");
}

std::filesystem::path vessel_file_or_default(const std::filesystem::path& given) {
  return given.empty() ? find_data_dir() / "vessels" / "gunnerus.toml" : given;
}

}  // namespace dynpos::analysis
