#pragma once
// CRC-32 (IEEE 802.3, the one of zlib and MCAP) of bytes (private to the module).

#include <cstdint>
#include <span>

namespace dynpos::io::detail {

/// The CRC-32 of `bytes`, continued from `crc` (0 for the first part): folded by carry-less
/// multiplication where the processor has it (x86-64 VPCLMULQDQ with AVX2, else PCLMULQDQ),
/// else zlib's.
std::uint32_t crc32(std::span<const std::uint8_t> bytes, std::uint32_t crc = 0) noexcept;

/// The ways crc32() computes, each giving the same CRC: zlib's table-driven loop, four 128-bit
/// lanes folded by PCLMULQDQ, eight by VPCLMULQDQ.
enum class Crc32Kernel : unsigned char { kZlib, kClmul, kWideClmul };
/// Whether this processor has `kernel`.
bool crc32_has(Crc32Kernel kernel) noexcept;
/// crc32() by `kernel` (which this processor has).
std::uint32_t crc32_by(Crc32Kernel kernel, std::span<const std::uint8_t> bytes,
                       std::uint32_t crc = 0) noexcept;

}  // namespace dynpos::io::detail
