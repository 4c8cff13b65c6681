// The tests' path to the source tree (tests/source_dir.hpp), compiled into one object of its
// own: it must name the tree the tests were built from.

#include <gtest/gtest.h>

#include <filesystem>

#include "../source_dir.hpp"

namespace {

namespace fs = std::filesystem;

TEST(SourceDir, IsTheTreeTheTestsWereBuiltFrom) {
  const fs::path dir = DYNPOS_SOURCE_DIR;
  EXPECT_TRUE(dir.is_absolute()) << dir;
  EXPECT_TRUE(fs::exists(dir / "tests" / "source_dir.hpp")) << dir;
  EXPECT_TRUE(fs::exists(dir / "data" / "scenarios" / "turning-circle.toml")) << dir;
}

}  // namespace
