#include "dynpos/io/temporary_files.hpp"

#include <mutex>
#include <set>
#include <shared_mutex>
#include <string>

namespace dynpos::io::temporary_files {
namespace {

struct List {
  std::mutex mutex;
  std::set<std::string> paths;
  std::shared_mutex steps;  // shared by each Hold, taken whole by the removal
};

List& list() {
  static List files;
  return files;
}

std::size_t remove_listed(List& l) noexcept {
  const std::lock_guard lock(l.mutex);
  std::size_t removed = 0;
  for (const std::string& path : l.paths) {
    std::error_code ec;
    removed += std::filesystem::remove_all(path, ec) > 0 ? 1 : 0;
  }
  l.paths.clear();
  return removed;
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
  const std::unique_lock steps(l.steps);
  return remove_listed(l);
}

std::size_t remove_all_for_exit() noexcept {
  List& l = list();
  l.steps.lock();  // never unlocked: the process ends
  return remove_listed(l);
}

Hold::Hold() { list().steps.lock_shared(); }

Hold::~Hold() { list().steps.unlock_shared(); }

}  // namespace dynpos::io::temporary_files
