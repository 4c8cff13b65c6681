#include "chunk_decompressor.hpp"

#include <algorithm>
#include <string>

#include <lz4frame.h>
#include <zstd.h>

#include "byte_cursor.hpp"

namespace dynpos::io::detail {

struct ChunkDecompressor::Contexts {
  ZSTD_DCtx* zstd = nullptr;
  LZ4F_dctx* lz4 = nullptr;
  ~Contexts() {
    ZSTD_freeDCtx(zstd);
    if (lz4 != nullptr) LZ4F_freeDecompressionContext(lz4);
  }
};

ChunkDecompressor::ChunkDecompressor() : contexts_(std::make_unique<Contexts>()) {}
ChunkDecompressor::~ChunkDecompressor() = default;
ChunkDecompressor::ChunkDecompressor(ChunkDecompressor&&) noexcept = default;
ChunkDecompressor& ChunkDecompressor::operator=(ChunkDecompressor&&) noexcept = default;

namespace {

std::string size_text(std::uint64_t n) { return std::to_string(n) + " bytes"; }

// The first output buffer for `in`: what a good compression ratio gives, at most `size`.
std::uint64_t first_guess(std::span<const std::uint8_t> in, std::uint64_t size) {
  return std::min<std::uint64_t>(size, 16 * std::uint64_t{in.size()} + (64U << 10));
}

[[noreturn]] void too_long(std::uint64_t size, std::size_t at) {
  throw ByteError("it decompresses to more than the declared " + size_text(size), at);
}

}  // namespace

bool ChunkDecompressor::Output::grow(std::uint64_t size) {
  if (room >= size) return false;
  room = static_cast<std::size_t>(std::min<std::uint64_t>(size, 2 * std::uint64_t{room}));
  if (buffer.size() < room) buffer.resize(room);
  return true;
}

std::span<const std::uint8_t> ChunkDecompressor::decompress(std::string_view compression,
                                                            std::span<const std::uint8_t> in,
                                                            std::uint64_t size,
                                                            std::vector<std::uint8_t>& buffer) {
  if (compression.empty()) {
    if (in.size() != size) {
      throw ByteError(
          "an uncompressed chunk of " + size_text(in.size()) + " declares " + size_text(size), 0);
    }
    return in;
  }
  if (in.empty() && size == 0) return {};
  Output out{buffer, static_cast<std::size_t>(first_guess(in, size))};
  if (buffer.size() < out.room) buffer.resize(out.room);
  if (compression == "zstd") {
    zstd(in, size, out);
  } else if (compression == "lz4") {
    lz4(in, size, out);
  } else {
    throw ByteError("unknown compression '" + std::string(compression) +
                        "' (dynpos reads \"\", \"lz4\" and \"zstd\")",
                    0);
  }
  return {buffer.data(), static_cast<std::size_t>(size)};
}

void ChunkDecompressor::zstd(std::span<const std::uint8_t> in, std::uint64_t size, Output& out) {
  if (contexts_->zstd == nullptr) contexts_->zstd = ZSTD_createDCtx();
  if (contexts_->zstd == nullptr) throw std::bad_alloc();
  ZSTD_DCtx_reset(contexts_->zstd, ZSTD_reset_session_only);
  ZSTD_inBuffer src{in.data(), in.size(), 0};
  std::size_t produced = 0;
  std::size_t pending = 1;  // ZSTD_decompressStream: 0 once a frame is complete
  while (src.pos < src.size || pending != 0) {
    std::uint8_t spare = 0;  // past `size`: one byte tells whether there is more
    const bool full = produced == out.room && !out.grow(size);
    ZSTD_outBuffer dst =
        full ? ZSTD_outBuffer{&spare, 1, 0} : ZSTD_outBuffer{out.buffer.data(), out.room, produced};
    const std::size_t before_in = src.pos;
    pending = ZSTD_decompressStream(contexts_->zstd, &dst, &src);
    if (ZSTD_isError(pending)) {
      throw ByteError(std::string("zstd: ") + ZSTD_getErrorName(pending), src.pos);
    }
    if (full && dst.pos > 0) too_long(size, src.pos);
    if (!full) {
      const bool progress = dst.pos > produced || src.pos > before_in;
      produced = dst.pos;
      if (!progress && produced < out.room) break;  // input ends inside a frame
    } else if (src.pos == before_in) {
      break;
    }
  }
  if (pending != 0) throw ByteError("the zstd data ends inside a frame (truncated)", src.pos);
  if (produced != size) {
    throw ByteError(
        "it decompresses to " + size_text(produced) + ", not the declared " + size_text(size),
        src.pos);
  }
}

void ChunkDecompressor::lz4(std::span<const std::uint8_t> in, std::uint64_t size, Output& out) {
  if (contexts_->lz4 == nullptr &&
      LZ4F_isError(LZ4F_createDecompressionContext(&contexts_->lz4, LZ4F_VERSION))) {
    throw std::bad_alloc();
  }
  LZ4F_resetDecompressionContext(contexts_->lz4);
  std::size_t consumed = 0;
  std::size_t produced = 0;
  std::size_t pending = 1;  // LZ4F_decompress: 0 once a frame is complete
  while (consumed < in.size() || pending != 0) {
    std::uint8_t spare = 0;
    const bool full = produced == out.room && !out.grow(size);
    std::size_t dst_size = full ? 1 : out.room - produced;
    std::size_t src_size = in.size() - consumed;
    pending = LZ4F_decompress(contexts_->lz4, full ? &spare : out.buffer.data() + produced,
                              &dst_size, in.data() + consumed, &src_size, nullptr);
    if (LZ4F_isError(pending)) {
      throw ByteError(std::string("lz4: ") + LZ4F_getErrorName(pending), consumed);
    }
    if (full && dst_size > 0) too_long(size, consumed);
    consumed += src_size;
    if (!full) produced += dst_size;
    if (src_size == 0 && dst_size == 0) break;  // no progress
  }
  if (pending != 0) throw ByteError("the lz4 data ends inside a frame (truncated)", consumed);
  if (produced != size) {
    throw ByteError(
        "it decompresses to " + size_text(produced) + ", not the declared " + size_text(size),
        consumed);
  }
}

}  // namespace dynpos::io::detail
