#pragma once
// Shared by the io tests: a self-removing temporary directory, file writing, and
// catching an InputError's message for regex matching.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <string>
#include <string_view>

#include "../source_dir.hpp"
#include "dynpos/core/error.hpp"

namespace dynpos::io::testing {

/// A fresh directory under the system temp dir, removed with its contents at scope exit.
class TempDir {
 public:
  TempDir() {
    std::random_device entropy;
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string test = info != nullptr ? info->name() : "io";
    path_ = std::filesystem::temp_directory_path() /
            ("dynpos-io-" + test + "-" + std::to_string(entropy()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(std::string_view name) const { return path_ / name; }

  /// Writes `text` byte for byte to `name` in the directory and returns its path.
  std::filesystem::path write(std::string_view name, std::string_view text) const {
    const auto file = path_ / name;
    std::ofstream out(file, std::ios::binary);
    out << text;
    EXPECT_TRUE(out.good()) << file;
    return file;
  }

 private:
  std::filesystem::path path_;
};

/// The core::InputError `f` throws; a test failure (and none) if it throws none.
template <class F>
std::optional<core::InputError> caught_input_error(F&& f) {
  try {
    f();
  } catch (const core::InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected a core::InputError";
  return std::nullopt;
}

/// The what() of the core::InputError `f` throws; "" (and a test failure) if it throws none.
template <class F>
std::string input_error_message(F&& f) {
  const auto e = caught_input_error(std::forward<F>(f));
  return e ? e->what() : std::string();
}

/// The option key of the core::InputError `f` throws ("" for an error of a file); "(no error)"
/// (and a test failure) if it throws none.
template <class F>
std::string input_error_option(F&& f) {
  const auto e = caught_input_error(std::forward<F>(f));
  return e ? e->option() : std::string("(no error)");
}

/// Path of a fixture under tests/data/io.
inline std::filesystem::path fixture(std::string_view name) {
  return std::filesystem::path(DYNPOS_SOURCE_DIR) / "tests" / "data" / "io" / name;
}

}  // namespace dynpos::io::testing
