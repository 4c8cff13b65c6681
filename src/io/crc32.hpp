#pragma once
// CRC-32 (IEEE 802.3, the one of zlib and MCAP) of bytes (private to the module).

#include <cstdint>
#include <span>

namespace dynpos::io::detail {

/// The CRC-32 of `bytes`, continued from `crc` (0 for the first part): folded by carry-less
/// multiplication where the processor has it (x86-64 PCLMULQDQ), else zlib's.
std::uint32_t crc32(std::span<const std::uint8_t> bytes, std::uint32_t crc = 0) noexcept;

}  // namespace dynpos::io::detail
