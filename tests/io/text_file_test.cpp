#include "dynpos/io/text_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <thread>

#include "io_test_util.hpp"

namespace dynpos::io {
namespace {

using ::testing::HasSubstr;
using testing::input_error_message;
using testing::TempDir;

std::string read_with_cap(const std::filesystem::path& path, std::uint64_t max_bytes) {
  std::ifstream in(path, std::ios::binary);
  return read_capped(in, path, max_bytes, "give the right file");
}

TEST(TextFile, AFileUpToTheCapIsReadWhole) {
  TempDir dir;
  const std::string text(1000, 'x');
  EXPECT_EQ(read_with_cap(dir.write("a.json", text), 1000), text);
  EXPECT_EQ(read_with_cap(dir.write("empty.json", ""), 1000), "");
}

// A regular file larger than the cap is refused by its size, before a byte is read: a sparse
// file of 65 MiB costs nothing.
TEST(TextFile, ALargerFileIsRefusedByItsSize) {
  TempDir dir;
  const auto big = dir.write("big.json", "{}");
  std::filesystem::resize_file(big, kMaxJsonBytes + (1 << 20));
  EXPECT_THAT(input_error_message([&] { read_with_cap(big, kMaxJsonBytes); }),
              HasSubstr("big.json: more than 64 MiB (68157440 bytes); give the right file"));
  EXPECT_THAT(input_error_message([&] { read_with_cap(dir.write("b.toml", "12345"), 4); }),
              HasSubstr("b.toml: more than 0 MiB (5 bytes)"));
}

// A device or a pipe has no size: it is read up to the cap and one byte more, then refused.
TEST(TextFile, AnEndlessDeviceOrPipeIsReadUpToTheCap) {
  EXPECT_THAT(input_error_message([&] { read_with_cap("/dev/zero", 1 << 20); }),
              HasSubstr("/dev/zero: more than 1 MiB read without an end; give the right file"));
  TempDir dir;
  const auto fifo = dir / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer([&] { std::ofstream(fifo, std::ios::binary) << "[1, 2]"; });
  EXPECT_EQ(read_with_cap(fifo, 1 << 20), "[1, 2]");
  writer.join();
}

}  // namespace
}  // namespace dynpos::io
