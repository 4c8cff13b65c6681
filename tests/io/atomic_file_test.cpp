#include "dynpos/io/atomic_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <fstream>
#include <sstream>
#include <thread>

#include "dynpos/core/error.hpp"
#include "dynpos/io/temporary_files.hpp"
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

// The temporary file is listed for the command line's signal thread until it is renamed or
// removed: remove_all() (what a Ctrl-C does) leaves no temporary file and the old target.
TEST(AtomicFile, ASignalsCleanupRemovesTheTemporaryFileOnly) {
  TempDir dir;
  const auto target = dir.write("out.json", "old");
  temporary_files::remove_all();  // whatever earlier tests left listed
  {
    AtomicFile committed(dir / "done.json");
    committed.stream() << "done";
    committed.commit();
  }
  AtomicFile file(target);
  file.stream() << "new";
  ASSERT_TRUE(std::filesystem::exists(file.temp_path()));
  EXPECT_EQ(temporary_files::remove_all(), 1u);  // the one not yet renamed
  EXPECT_FALSE(std::filesystem::exists(file.temp_path()));
  EXPECT_TRUE(std::filesystem::exists(dir / "done.json"));
  std::ifstream in(target);
  std::string text;
  in >> text;
  EXPECT_EQ(text, "old");
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

TEST(AtomicFile, ADirectoryIsRefusedBeforeAnythingIsWritten) {
  TempDir dir;
  std::filesystem::create_directory(dir / "taken");
  try {
    AtomicFile file(dir / "taken");
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("taken"));
    EXPECT_THAT(e.what(), HasSubstr("it is a folder"));
  }
  EXPECT_EQ(entries(dir.path()), (std::vector<std::string>{"taken"}));
}

TEST(AtomicFile, AReadOnlyFileIsRefusedAndKept) {
  TempDir dir;
  { std::ofstream(dir / "keep.json") << "old"; }
  std::filesystem::permissions(
      dir / "keep.json", std::filesystem::perms::owner_read | std::filesystem::perms::group_read);
  EXPECT_THROW(
      {
        try {
          AtomicFile file(dir / "keep.json");
        } catch (const std::runtime_error& e) {
          EXPECT_THAT(e.what(), HasSubstr("read-only (mode 0440)"));
          throw;
        }
      },
      std::runtime_error);
  EXPECT_EQ(contents(dir / "keep.json"), "old");
  EXPECT_EQ(entries(dir.path()), (std::vector<std::string>{"keep.json"}));
}

TEST(AtomicFile, AReplacedFileKeepsItsMode) {
  TempDir dir;
  { std::ofstream(dir / "out.json") << "old"; }
  const auto mode = std::filesystem::perms::owner_read | std::filesystem::perms::owner_write;
  std::filesystem::permissions(dir / "out.json", mode);
  AtomicFile file(dir / "out.json");
  file.stream() << "new";
  file.commit();
  EXPECT_EQ(contents(dir / "out.json"), "new");
  EXPECT_EQ(std::filesystem::status(dir / "out.json").permissions(), mode);
}

TEST(AtomicFile, ASymlinkIsWrittenThroughAndKept) {
  TempDir dir;
  { std::ofstream(dir / "real.json") << "old"; }
  std::filesystem::create_symlink(dir / "real.json", dir / "link.json");
  AtomicFile file(dir / "link.json");
  file.stream() << "new";
  file.commit();
  EXPECT_TRUE(std::filesystem::is_symlink(dir / "link.json"));
  EXPECT_EQ(contents(dir / "real.json"), "new");
  EXPECT_EQ(entries(dir.path()), (std::vector<std::string>{"link.json", "real.json"}));
}

TEST(AtomicFile, ADanglingSymlinkIsRefused) {
  TempDir dir;
  std::filesystem::create_symlink(dir / "missing.json", dir / "link.json");
  try {
    AtomicFile file(dir / "link.json");
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("symbolic link to a missing file"));
  }
  EXPECT_TRUE(std::filesystem::is_symlink(dir / "link.json"));
}

TEST(AtomicFile, ACharacterDeviceIsWrittenThroughNeverReplaced) {
  TempDir dir;
  AtomicFile file("/dev/null");
  EXPECT_TRUE(file.temp_path().empty());
  file.stream() << "discarded";
  file.commit();
  EXPECT_TRUE(std::filesystem::is_character_file("/dev/null"));
}

TEST(AtomicFile, AFifoIsWrittenThroughToItsReader) {
  TempDir dir;
  const auto fifo = dir / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] {
    std::ifstream in(fifo, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    received = text.str();
  });
  {
    AtomicFile file(fifo);
    file.stream() << "through the pipe";
    file.commit();
  }
  reader.join();
  EXPECT_EQ(received, "through the pipe");
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));
  EXPECT_EQ(entries(dir.path()), (std::vector<std::string>{"pipe"}));
}

// A full disk: /dev/full fails every write with ENOSPC. The failure names the path and the
// reason with what to do, as bad input the user can fix (core::InputError, exit 2), not
// "unknown error": the write's errno is kept when it happens, not looked up at commit.
TEST(AtomicFile, AFullDiskNamesThePathAndTheReason) {
  AtomicFile file("/dev/full");
  const std::string block(1 << 20, 'x');  // more than any stream buffer
  file.stream() << block << block;
  try {
    file.commit();
    FAIL() << "writing /dev/full succeeded";
  } catch (const core::InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("/dev/full"));
    EXPECT_THAT(e.what(), HasSubstr("No space left on device"));
    EXPECT_THAT(e.what(), HasSubstr("free some space or write elsewhere"));
  }
}

// A file larger than the process may write (ulimit -f): with SIGXFSZ ignored, as the command
// line does, the write fails with EFBIG, named as such. In a child process, whose limit does
// not reach the other tests; the child reports the message through a pipe.
TEST(AtomicFile, AFileSizeLimitNamesThePathAndTheReason) {
  TempDir dir;
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::close(fds[0]);
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{64 * 1024, 64 * 1024};
    std::string message = "no error";
    if (::setrlimit(RLIMIT_FSIZE, &limit) == 0) {
      try {
        AtomicFile file(dir / "big.csv");
        file.stream() << std::string(1 << 20, 'x');
        file.commit();
      } catch (const core::InputError& e) {
        message = std::string("InputError: ") + e.what();
      } catch (const std::exception& e) {
        message = std::string("other: ") + e.what();
      }
    }
    (void)!::write(fds[1], message.data(), message.size());
    ::_exit(0);
  }
  ::close(fds[1]);
  std::string message;
  char buffer[4096];
  for (ssize_t got; (got = ::read(fds[0], buffer, sizeof buffer)) > 0;) message.append(buffer, got);
  ::close(fds[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_THAT(message, HasSubstr("InputError: "));
  EXPECT_THAT(message, HasSubstr("big.csv"));
  EXPECT_THAT(message, HasSubstr("File too large"));
  EXPECT_EQ(entries(dir.path()), std::vector<std::string>{});  // no temporary file left
}

}  // namespace
}  // namespace dynpos::io
