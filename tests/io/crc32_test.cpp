#include "crc32.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include "mcap_test_writer.hpp"

namespace dynpos::io {
namespace {

// Every length up to a few folds and some long ones, at every alignment of a 16-byte lane,
// against the bit-by-bit CRC of the tests' MCAP writer; and continued over two parts; by every
// kernel this processor has, and by the best one (crc32).
TEST(Crc32, EqualsTheBitwiseCrcAtEveryLengthAndAlignment) {
  std::mt19937 engine(11);
  std::vector<std::uint8_t> bytes(70'000 + 16);
  for (std::uint8_t& b : bytes) b = static_cast<std::uint8_t>(engine());
  std::vector<detail::Crc32Kernel> kernels;
  for (const auto kernel :
       {detail::Crc32Kernel::kZlib, detail::Crc32Kernel::kClmul, detail::Crc32Kernel::kWideClmul}) {
    if (detail::crc32_has(kernel)) kernels.push_back(kernel);
  }
  ASSERT_TRUE(detail::crc32_has(detail::Crc32Kernel::kZlib));
  std::vector<std::size_t> lengths;
  for (std::size_t n = 0; n <= 300; ++n) lengths.push_back(n);
  for (const std::size_t n : {1023, 1024, 1025, 4096, 65'535, 70'000}) lengths.push_back(n);
  for (const std::size_t n : lengths) {
    for (const std::size_t shift : {0, 1, 7, 15}) {
      const testing::Bytes part(bytes.begin() + static_cast<std::ptrdiff_t>(shift),
                                bytes.begin() + static_cast<std::ptrdiff_t>(shift + n));
      const std::span<const std::uint8_t> view(bytes.data() + shift, n);
      const std::uint32_t expected = testing::test_crc32(part);
      ASSERT_EQ(detail::crc32(view), expected) << n << " at " << shift;
      const std::size_t half = n / 3;
      for (const auto kernel : kernels) {
        const auto k = static_cast<int>(kernel);
        ASSERT_EQ(detail::crc32_by(kernel, view), expected) << n << " at " << shift << " by " << k;
        ASSERT_EQ(detail::crc32_by(kernel, view.subspan(half),
                                   detail::crc32_by(kernel, view.first(half))),
                  expected)
            << n << " split at " << half << " by " << k;
      }
    }
  }
  EXPECT_EQ(detail::crc32({}), 0u);
}

}  // namespace
}  // namespace dynpos::io
