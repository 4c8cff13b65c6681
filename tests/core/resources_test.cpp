#include "dynpos/core/resources.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace dynpos::core {
namespace {

TEST(Resources, MemoryAndDiskAreKnownOnLinux) {
  const auto memory = available_memory_bytes();
  ASSERT_TRUE(memory.has_value());
  EXPECT_GT(*memory, std::uint64_t{1} << 20);
  const auto tmp = std::filesystem::temp_directory_path();
  const auto here = free_disk_bytes(tmp);
  ASSERT_TRUE(here.has_value());
  // A folder about to be created is on its parent's disk: the same free space, give or take
  // what other processes write meanwhile (1 GB).
  const auto planned = free_disk_bytes(tmp / "not-yet" / "made");
  ASSERT_TRUE(planned.has_value());
  EXPECT_NEAR(static_cast<double>(*planned), static_cast<double>(*here), 1e9);
}

}  // namespace
}  // namespace dynpos::core
