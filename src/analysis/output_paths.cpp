#include "dynpos/analysis/output_paths.hpp"

#include <fmt/core.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>

#include "dynpos/analysis/options.hpp"

namespace dynpos::analysis {
namespace {

bool same_file(const struct stat& a, const std::string& path) {
  struct stat b {};
  return ::stat(path.c_str(), &b) == 0 && S_ISREG(b.st_mode) && a.st_dev == b.st_dev &&
         a.st_ino == b.st_ino;
}

// A file in an output folder not made yet (--out D --json D/r.json): nothing is there.
bool in_new_folder(const std::string& file, const std::vector<NamedPath>& folders) {
  const auto parent = std::filesystem::path(file).parent_path().lexically_normal();
  return !parent.empty() && !std::filesystem::exists(parent) &&
         std::any_of(folders.begin(), folders.end(), [&](const NamedPath& d) {
           return std::filesystem::path(d.path).lexically_normal() == parent;
         });
}

}  // namespace

std::vector<std::string> paths_in(const std::string& value) {
  std::vector<std::string> out{value};
  if (const auto at = value.rfind('@'); at != std::string::npos)
    out.push_back(value.substr(at + 1));
  if (const auto eq = value.find('='); eq != std::string::npos) out.push_back(value.substr(0, eq));
  return out;
}

void check_command_paths(const CommandPaths& paths) {
  for (const NamedPath& f : paths.output_folders) check_output_dir(f.role, f.path);
  for (const NamedPath& f : paths.output_files) {
    if (in_new_folder(f.path, paths.output_folders)) continue;
    check_output_file(f.role, f.path);
    struct stat out {};
    if (f.path.empty() || f.path == "-" || ::stat(f.path.c_str(), &out) != 0 ||
        !S_ISREG(out.st_mode)) {
      continue;  // nothing there yet, or a device or FIFO written through
    }
    for (const NamedPath& in : paths.inputs) {
      if (!same_file(out, in.path)) continue;
      throw option_error(f.role,
                         fmt::format("'{}' is the input '{}' ({}): writing it would destroy the "
                                     "input",
                                     f.path, in.path, in.role),
                         "write the output to another file");
    }
  }
}

}  // namespace dynpos::analysis
