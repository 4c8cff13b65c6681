#include "crc32.hpp"

#include <zlib.h>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace dynpos::io::detail {
namespace {

#if defined(__x86_64__)
// CRC-32 by carry-less multiplication: the bytes (a multiple of 16, at least 64) folded 64 at a
// time into four 128-bit lanes (or 128 at a time into eight, in 256-bit registers), the lanes
// into one, then reduced to 32 bits (Barrett). The constants are x^k mod P for the reflected
// polynomial, shifted left by one: k = 512 ± 32 (folding four lanes; 1024 ± 32, eight), 128 ± 32
// (one lane), 64; then floor(x^64 / P) and P itself.
#define DYNPOS_CLMUL __attribute__((target("pclmul,sse4.1")))

DYNPOS_CLMUL inline __m128i load(const std::uint8_t* at) {
  return _mm_loadu_si128(reinterpret_cast<const __m128i*>(at));
}

// x's lanes carried forward by k's distances, plus the next bytes.
DYNPOS_CLMUL inline __m128i fold(__m128i x, __m128i k, __m128i next) {
  return _mm_xor_si128(
      _mm_xor_si128(_mm_clmulepi64_si128(x, k, 0x00), _mm_clmulepi64_si128(x, k, 0x11)), next);
}

DYNPOS_CLMUL inline __m128i one_lane() { return _mm_set_epi64x(0x0ccaa009e, 0x1751997d0); }

// The CRC of the lane x (the bytes before p + at folded) and of the bytes [at, n) that follow.
DYNPOS_CLMUL std::uint32_t reduce(__m128i x, const std::uint8_t* p, std::size_t at,
                                  std::size_t n) noexcept {
  const __m128i one = one_lane();
  const __m128i x64 = _mm_set_epi64x(0, 0x163cd6124);
  const __m128i barrett = _mm_set_epi64x(0x1f7011641, 0x1db710641);
  const __m128i low32 = _mm_set_epi32(0, 0, 0, -1);
  for (; n - at >= 16; at += 16) x = fold(x, one, load(p + at));
  x = _mm_xor_si128(_mm_clmulepi64_si128(x, one, 0x10), _mm_srli_si128(x, 8));
  x = _mm_xor_si128(_mm_clmulepi64_si128(_mm_and_si128(x, low32), x64, 0x00), _mm_srli_si128(x, 4));
  __m128i t = _mm_and_si128(_mm_clmulepi64_si128(_mm_and_si128(x, low32), barrett, 0x10), low32);
  t = _mm_clmulepi64_si128(t, barrett, 0x00);
  return ~static_cast<std::uint32_t>(_mm_extract_epi32(_mm_xor_si128(t, x), 1));
}

DYNPOS_CLMUL std::uint32_t crc32_folded(std::uint32_t crc, const std::uint8_t* p,
                                        std::size_t n) noexcept {
  const __m128i four = _mm_set_epi64x(0x1c6e41596, 0x154442bd4);
  const __m128i one = one_lane();
  __m128i x0 = _mm_xor_si128(load(p), _mm_cvtsi32_si128(static_cast<int>(~crc)));
  __m128i x1 = load(p + 16);
  __m128i x2 = load(p + 32);
  __m128i x3 = load(p + 48);
  std::size_t at = 64;
  for (; n - at >= 64; at += 64) {
    x0 = fold(x0, four, load(p + at));
    x1 = fold(x1, four, load(p + at + 16));
    x2 = fold(x2, four, load(p + at + 32));
    x3 = fold(x3, four, load(p + at + 48));
  }
  return reduce(fold(fold(fold(x0, one, x1), one, x2), one, x3), p, at, n);
}

// The same with eight lanes in four 256-bit registers (VPCLMULQDQ), 128 bytes a step: k = 1024
// ± 32. The bytes: a multiple of 16, at least 128.
#define DYNPOS_VCLMUL __attribute__((target("vpclmulqdq,avx2,pclmul,sse4.1")))

DYNPOS_VCLMUL inline __m256i load256(const std::uint8_t* at) {
  return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(at));
}

DYNPOS_VCLMUL inline __m256i fold256(__m256i x, __m256i k, __m256i next) {
  return _mm256_xor_si256(
      _mm256_xor_si256(_mm256_clmulepi64_epi128(x, k, 0x00), _mm256_clmulepi64_epi128(x, k, 0x11)),
      next);
}

DYNPOS_VCLMUL std::uint32_t crc32_folded_wide(std::uint32_t crc, const std::uint8_t* p,
                                              std::size_t n) noexcept {
  const __m256i eight = _mm256_set_epi64x(0x14a7fe880, 0x1e88ef372, 0x14a7fe880, 0x1e88ef372);
  const __m128i one = one_lane();
  const __m128i first = _mm_cvtsi32_si128(static_cast<int>(~crc));
  __m256i y0 =
      _mm256_xor_si256(load256(p), _mm256_inserti128_si256(_mm256_setzero_si256(), first, 0));
  __m256i y1 = load256(p + 32);
  __m256i y2 = load256(p + 64);
  __m256i y3 = load256(p + 96);
  std::size_t at = 128;
  for (; n - at >= 128; at += 128) {
    y0 = fold256(y0, eight, load256(p + at));
    y1 = fold256(y1, eight, load256(p + at + 32));
    y2 = fold256(y2, eight, load256(p + at + 64));
    y3 = fold256(y3, eight, load256(p + at + 96));
  }
  // The eight lanes in file order, folded into one.
  __m128i x = fold(_mm256_castsi256_si128(y0), one, _mm256_extracti128_si256(y0, 1));
  for (const __m256i y : {y1, y2, y3}) {
    x = fold(fold(x, one, _mm256_castsi256_si128(y)), one, _mm256_extracti128_si256(y, 1));
  }
  return reduce(x, p, at, n);
}

#undef DYNPOS_VCLMUL
#undef DYNPOS_CLMUL

bool has_clmul() noexcept {
  return __builtin_cpu_supports("pclmul") && __builtin_cpu_supports("sse4.1");
}
bool has_wide_clmul() noexcept {
  return has_clmul() && __builtin_cpu_supports("vpclmulqdq") && __builtin_cpu_supports("avx2");
}
#endif

}  // namespace

bool crc32_has(Crc32Kernel kernel) noexcept {
#if defined(__x86_64__)
  if (kernel == Crc32Kernel::kClmul) return has_clmul();
  if (kernel == Crc32Kernel::kWideClmul) return has_wide_clmul();
#endif
  return kernel == Crc32Kernel::kZlib;
}

std::uint32_t crc32_by(Crc32Kernel kernel, std::span<const std::uint8_t> bytes,
                       std::uint32_t crc) noexcept {
  const std::uint8_t* p = bytes.data();
  std::size_t n = bytes.size();
#if defined(__x86_64__)
  if (kernel != Crc32Kernel::kZlib && n >= 64) {
    const std::size_t folded = n & ~std::size_t{15};
    crc = kernel == Crc32Kernel::kWideClmul && n >= 128 ? crc32_folded_wide(crc, p, folded)
                                                        : crc32_folded(crc, p, folded);
    p += folded;
    n -= folded;
  }
#endif
  // zlib's braided CRC-32 for the rest (and on other machines): the same polynomial and
  // conventions.
  return static_cast<std::uint32_t>(::crc32_z(crc, p, n));
}

std::uint32_t crc32(std::span<const std::uint8_t> bytes, std::uint32_t crc) noexcept {
  const Crc32Kernel best = crc32_has(Crc32Kernel::kWideClmul) ? Crc32Kernel::kWideClmul
                           : crc32_has(Crc32Kernel::kClmul)   ? Crc32Kernel::kClmul
                                                              : Crc32Kernel::kZlib;
  return crc32_by(best, bytes, crc);
}

}  // namespace dynpos::io::detail
