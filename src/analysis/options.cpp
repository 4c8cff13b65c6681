#include "dynpos/analysis/options.hpp"

#include "dynpos/io/atomic_file.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <vector>

#include "dynpos/analysis/option_spelling.hpp"
#include "dynpos/io/atomic_file.hpp"

namespace dynpos::analysis {

core::InputError option_error(const std::string& key, const std::string& problem,
                              const std::string& hint) {
  return core::InputError::for_option(key, problem, hint);
}

core::InputError option_error_in_file(const std::filesystem::path& file, const std::string& key,
                                      const std::string& problem, const std::string& hint) {
  return core::InputError::for_option(key, problem, hint, file.string());
}

core::InputError with_file(const core::InputError& e, const std::string& file) {
  core::InputLocation where = e.where();
  if (where.file.empty()) where.file = file;
  return core::InputError(where, e.problem(), e.hint());
}

Eigen::Vector3d parse_vec3(const std::string& text, const std::string& key,
                           const std::string& example) {
  std::stringstream ss(text);
  std::string item;
  std::vector<double> v;
  while (std::getline(ss, item, ',')) {
    try {
      std::size_t used = 0;
      v.push_back(std::stod(item, &used));
      if (used != item.size()) v.push_back(NAN);
    } catch (const std::exception&) {
      v.push_back(NAN);
    }
  }
  if (v.size() != 3 ||
      !std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); })) {
    throw option_error(key, "'" + text + "' is not three numbers X,Y,Z",
                       "for example " + option_spelling(key) + " " + example);
  }
  return {v[0], v[1], v[2]};
}

void check_output_dir(const std::string& key, const std::filesystem::path& dir) {
  if (dir == "-") {
    throw option_error(key, "'-' (standard output) cannot hold a folder of files",
                       "name a folder (it is created if needed), e.g. ./-  for one named '-'");
  }
  if (!dir.empty() && std::filesystem::exists(dir) && !std::filesystem::is_directory(dir)) {
    throw option_error(key, "'" + dir.string() + "' exists and is not a folder",
                       "name a folder (it is created if needed)");
  }
}

void check_output_file(const std::string& key, const std::string& path) {
  if (path.empty() || path == "-") return;
  const auto parent = std::filesystem::path(path).parent_path();
  if (!parent.empty() && !std::filesystem::is_directory(parent)) {
    throw option_error(key, "folder '" + parent.string() + "' does not exist",
                       "create it first, or use --json - for stdout");
  }
  try {
    io::check_output_target(path);
  } catch (const std::runtime_error& e) {
    throw option_error(key, e.what(), "see \"Outputs\" in docs/reliability.md");
  }
}

}  // namespace dynpos::analysis
