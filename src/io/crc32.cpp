#include "crc32.hpp"

#include <zlib.h>

namespace dynpos::io::detail {

std::uint32_t crc32(std::span<const std::uint8_t> bytes, std::uint32_t crc) noexcept {
  // zlib's braided CRC-32: several bytes per cycle, the same polynomial and conventions.
  return static_cast<std::uint32_t>(::crc32_z(crc, bytes.data(), bytes.size()));
}

}  // namespace dynpos::io::detail
