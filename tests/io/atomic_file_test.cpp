#include "dynpos/io/atomic_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "io_test_util.hpp"

namespace dynpos::io {
namespace {

using ::testing::HasSubstr;
using testing::TempDir;

std::vector<std::string> entries(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string contents(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(AtomicFile, CommitLeavesOnlyTheTarget) {
  TempDir dir;
  {
    AtomicFile file(dir / "out.csv");
    EXPECT_EQ(file.temp_path().parent_path(), dir.path());
    EXPECT_TRUE(std::filesystem::exists(file.temp_path()));
    EXPECT_FALSE(std::filesystem::exists(dir / "out.csv"));  // nothing visible before commit
    file.stream() << "a,b\n1,2\n";
    file.commit();
    EXPECT_TRUE(file.committed());
  }
  EXPECT_EQ(entries(dir.path()), (std::vector<std::string>{"out.csv"}));
  EXPECT_EQ(contents(dir / "out.csv"), "a,b\n1,2\n");
}

TEST(AtomicFile, NoCommitLeavesNoFile) {
  TempDir dir;
  {
    AtomicFile file(dir / "out.csv");
    file.stream() << "half a row,";
  }
  EXPECT_TRUE(entries(dir.path()).empty());
}

TEST(AtomicFile, AnExceptionBeforeCommitKeepsTheOldTarget) {
  TempDir dir;
  dir.write("out.json", "old\n");
  try {
    AtomicFile file(dir / "out.json");
    file.stream() << "new, but incomplete";
    throw std::runtime_error("analysis failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(entries(dir.path()), (std::vector<std::string>{"out.json"}));
  EXPECT_EQ(contents(dir / "out.json"), "old\n");
}

TEST(AtomicFile, CommitReplacesAnExistingTarget) {
  TempDir dir;
  dir.write("out.json", "old\n");
  AtomicFile file(dir / "out.json");
  file.stream() << "new\n";
  file.commit();
  EXPECT_EQ(contents(dir / "out.json"), "new\n");
  EXPECT_THROW(file.commit(), std::logic_error);
}

TEST(AtomicFile, MissingDirectoryNamesThePathAndReason) {
  TempDir dir;
  try {
    AtomicFile file(dir / "no" / "such" / "out.csv");
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("out.csv"));
    EXPECT_THAT(e.what(), HasSubstr("No such file or directory"));
  }
}

TEST(AtomicFile, RenameOntoADirectoryFailsAndCleansUp) {
  TempDir dir;
  std::filesystem::create_directory(dir / "taken");
  std::filesystem::path temp;
  try {
    AtomicFile file(dir / "taken");
    temp = file.temp_path();
    file.stream() << "x";
    file.commit();
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("cannot rename"));
    EXPECT_THAT(e.what(), HasSubstr("taken"));
  }
  EXPECT_FALSE(std::filesystem::exists(temp));
  EXPECT_EQ(entries(dir.path()), (std::vector<std::string>{"taken"}));
}

}  // namespace
}  // namespace dynpos::io
