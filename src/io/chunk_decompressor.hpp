#pragma once
// Decompression of MCAP chunks: zstd and LZ4 frames (private to the module).

#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

namespace dynpos::io::detail {

/// Decompresses one chunk after another, each into a buffer of the caller's (a chunk's slot),
/// which only grows: to the bytes the data actually gives, never to a declared size up front.
/// Each chunk is decompressed into room sized as if the buffer were new (the buffer's size left
/// by earlier chunks is not used), so that what a chunk gives, errors included, does not depend
/// on the chunks before it, nor on which thread's decompressor took it. Its zstd and LZ4
/// contexts are kept from chunk to chunk (one decompressor per thread).
class ChunkDecompressor {
 public:
  ChunkDecompressor();
  ~ChunkDecompressor();
  ChunkDecompressor(const ChunkDecompressor&) = delete;
  ChunkDecompressor& operator=(const ChunkDecompressor&) = delete;
  ChunkDecompressor(ChunkDecompressor&&) noexcept;
  ChunkDecompressor& operator=(ChunkDecompressor&&) noexcept;

  /// The `size` bytes that `in` decompresses to with `compression` ("" = none: `in` itself,
  /// "zstd", "lz4"), in `buffer` (grown as needed; its first `size` bytes). Throws ByteError
  /// (offset in `in`) for an unknown compression, bad or truncated data, or another size than
  /// `size`.
  std::span<const std::uint8_t> decompress(std::string_view compression,
                                           std::span<const std::uint8_t> in, std::uint64_t size,
                                           std::vector<std::uint8_t>& buffer);

 private:
  // The output of one chunk: the caller's buffer and the room used of it.
  struct Output {
    std::vector<std::uint8_t>& buffer;
    std::size_t room = 0;
    // Room for more: doubled, up to `size`; false when it holds `size` already.
    bool grow(std::uint64_t size);
  };
  void zstd(std::span<const std::uint8_t> in, std::uint64_t size, Output& out);
  void lz4(std::span<const std::uint8_t> in, std::uint64_t size, Output& out);

  struct Contexts;
  std::unique_ptr<Contexts> contexts_;
};

}  // namespace dynpos::io::detail
