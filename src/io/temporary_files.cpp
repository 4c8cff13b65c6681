#include "dynpos/io/temporary_files.hpp"

#include <mutex>
#include <set>
#include <string>

namespace dynpos::io::temporary_files {
namespace {

struct List {
  std::mutex mutex;
  std::set<std::string> paths;
};

List& list() {
  static List files;
  return files;
}

}  // namespace

void add(const std::filesystem::path& path) {
  List& l = list();
  const std::lock_guard lock(l.mutex);
  l.paths.insert(path.string());
}

void drop(const std::filesystem::path& path) {
  List& l = list();
  const std::lock_guard lock(l.mutex);
  l.paths.erase(path.string());
}

std::size_t remove_all() noexcept {
  List& l = list();
  const std::lock_guard lock(l.mutex);
  std::size_t removed = 0;
  for (const std::string& path : l.paths) {
    std::error_code ec;
    removed += std::filesystem::remove_all(path, ec) > 0 ? 1 : 0;
  }
  l.paths.clear();
  return removed;
}

}  // namespace dynpos::io::temporary_files
