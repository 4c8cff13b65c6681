#include "dynpos/io/spooled_input.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <sstream>
#include <thread>

#include "io_test_util.hpp"

namespace dynpos::io {
namespace {

using ::testing::HasSubstr;
using testing::input_error_message;
using testing::TempDir;

std::string content_of(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(SpooledInput, OnlyInputsReadOnceAreSpooled) {
  TempDir dir;
  EXPECT_TRUE(needs_spool("-"));
  EXPECT_FALSE(needs_spool(dir.write("log.csv", "time\n0\n")));
  EXPECT_FALSE(needs_spool(dir.path()));           // a folder: the reader's own error
  EXPECT_FALSE(needs_spool(dir / "missing.csv"));  // likewise
  ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
  EXPECT_TRUE(needs_spool(dir / "fifo"));
  EXPECT_TRUE(needs_spool("/dev/null"));  // a character device
}

// A FIFO holds its bytes once; the copy holds all of them (more than the 1 MiB buffer), as
// often as it is opened, and goes with the object.
TEST(SpooledInput, AFifoIsCopiedWholeAndTheCopyRemoved) {
  TempDir dir;
  const auto fifo = dir / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string text = "time,x\n";
  for (int i = 0; i < 200000; ++i) text += std::to_string(i) + ",1.5\n";
  std::thread writer([&] { std::ofstream(fifo, std::ios::binary) << text; });
  std::filesystem::path copy;
  {
    const SpooledInput spooled(fifo, dir.path());
    writer.join();
    copy = spooled.path();
    EXPECT_EQ(spooled.bytes(), text.size());
    EXPECT_EQ(content_of(copy), text);
    EXPECT_EQ(content_of(copy), text);  // read again: the same
    EXPECT_TRUE(std::filesystem::is_regular_file(copy));
  }
  EXPECT_FALSE(std::filesystem::exists(copy));
}

TEST(SpooledInput, ErrorsNameTheInputOrTheCopy) {
  TempDir dir;
  const auto log = dir.write("log.csv", "time\n0\n");
  EXPECT_THAT(input_error_message([&] { SpooledInput(log, dir / "no-such-folder"); }),
              HasSubstr("no-such-folder: cannot make a copy of"));
  EXPECT_THAT(input_error_message([&] { SpooledInput(dir / "missing.csv", dir.path()); }),
              HasSubstr("missing.csv: cannot open it: No such file or directory"));
}

}  // namespace
}  // namespace dynpos::io
