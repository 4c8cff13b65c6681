#include "dynpos/analysis/options.hpp"

#include <fcntl.h>
#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <random>
#include <sstream>
#include <vector>

#include "dynpos/analysis/option_spelling.hpp"
#include "dynpos/io/atomic_file.hpp"
#include "dynpos/io/temporary_files.hpp"

namespace dynpos::analysis {

core::InputError option_error(const std::string& key, const std::string& problem,
                              const std::string& hint) {
  return core::InputError::for_option(key, problem, hint);
}

core::InputError option_error_in_file(const std::filesystem::path& file, const std::string& key,
                                      const std::string& problem, const std::string& hint) {
  return core::InputError::for_option(key, problem, hint, file.string());
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

namespace {

// Throws option_error(key) unless a new file can be made in the folder `dir`: it tries (a file
// of a unique name, made and removed at once), since only the file system knows (a read-only
// mount, /proc, a folder without write permission even for root on some mounts).
void check_writable_folder(const std::string& key, const std::filesystem::path& dir) {
  const std::filesystem::path folder = dir.empty() ? std::filesystem::path(".") : dir;
  const std::filesystem::path probe =
      folder / fmt::format(".dynpos-probe-{}-{:08x}", ::getpid(), std::random_device{}());
  // Made and removed as one step that a signal's clean-up waits for: never left behind.
  const io::temporary_files::Hold hold;
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) {
    const int error = errno;
    // /proc and the like answer "No such file or directory" for a folder that is there.
    const std::string reason = error == ENOENT && std::filesystem::is_directory(folder)
                                   ? "it takes no new files"
                                   : std::strerror(error);
    throw option_error(key, fmt::format("cannot write in folder '{}': {}", folder.string(), reason),
                       "choose a writable folder");
  }
  ::close(fd);
  ::unlink(probe.c_str());
}

}  // namespace

void check_output_dir(const std::string& key, const std::filesystem::path& dir) {
  if (dir == "-") {
    throw option_error(key, "'-' (standard output) cannot hold a folder of files",
                       "name a folder (it is created if needed), e.g. ./-  for one named '-'");
  }
  if (!dir.empty() && std::filesystem::exists(dir) && !std::filesystem::is_directory(dir)) {
    throw option_error(key, "'" + dir.string() + "' exists and is not a folder",
                       "name a folder (it is created if needed)");
  }
  if (!dir.empty() && std::filesystem::is_directory(dir)) check_writable_folder(key, dir);
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
  // A device or a FIFO is written through (never a new file beside it); anything else is a new
  // file in the folder of the target (of the file a symbolic link points to).
  std::error_code error;
  const std::filesystem::path file = std::filesystem::weakly_canonical(path, error);
  const std::filesystem::file_status status = std::filesystem::status(file, error);
  if (status.type() == std::filesystem::file_type::character ||
      status.type() == std::filesystem::file_type::fifo) {
    return;
  }
  check_writable_folder(key, (error ? std::filesystem::path(path) : file).parent_path());
}

}  // namespace dynpos::analysis
