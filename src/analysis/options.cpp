#include "dynpos/analysis/options.hpp"

#include <filesystem>

namespace dynpos::analysis {

core::InputError option_error(const std::string& key, const std::string& problem,
                              const std::string& hint) {
  return core::InputError::for_option(key, problem, hint);
}

core::InputError file_option_error(const std::string& file, const std::string& key,
                                   const std::string& problem, const std::string& hint) {
  return core::InputError::for_option(key, problem, hint, file);
}

void check_output_file(const std::string& key, const std::string& path) {
  if (path.empty() || path == "-") return;
  const auto parent = std::filesystem::path(path).parent_path();
  if (!parent.empty() && !std::filesystem::is_directory(parent)) {
    throw option_error(key, "folder '" + parent.string() + "' does not exist",
                       "create it first, or use --json - for stdout");
  }
}

}  // namespace dynpos::analysis
