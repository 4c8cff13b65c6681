#pragma once
// Decompression of MCAP chunks: zstd and LZ4 frames (private to the module).

#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

namespace dynpos::io::detail {

/// Decompresses one chunk after another into one buffer, which only grows: to the bytes the
/// data actually gives, never to a declared size up front. Each chunk is decompressed into room
/// sized as if the buffer were new (the buffer's size left by earlier chunks is not used), so
/// that what a chunk gives, errors included, does not depend on the chunks before it, nor on
/// which thread's decompressor took it.
class ChunkDecompressor {
 public:
  ChunkDecompressor();
  ~ChunkDecompressor();
  ChunkDecompressor(const ChunkDecompressor&) = delete;
  ChunkDecompressor& operator=(const ChunkDecompressor&) = delete;
  ChunkDecompressor(ChunkDecompressor&&) noexcept;
  ChunkDecompressor& operator=(ChunkDecompressor&&) noexcept;

  /// The `size` bytes that `in` decompresses to with `compression` ("" = none, "zstd", "lz4"),
  /// valid until the next call. Throws ByteError (offset in `in`) for an unknown compression,
  /// bad or truncated data, or another size than `size`.
  std::span<const std::uint8_t> decompress(std::string_view compression,
                                           std::span<const std::uint8_t> in, std::uint64_t size);

 private:
  void zstd(std::span<const std::uint8_t> in, std::uint64_t size);
  void lz4(std::span<const std::uint8_t> in, std::uint64_t size);
  // Room for more output: the buffer doubled, up to `size`; false when it holds `size` already.
  bool grow(std::uint64_t size);

  struct Contexts;
  std::unique_ptr<Contexts> contexts_;
  std::vector<std::uint8_t> buffer_;
  std::size_t room_ = 0;  // of buffer_, for the chunk being decompressed
};

}  // namespace dynpos::io::detail
