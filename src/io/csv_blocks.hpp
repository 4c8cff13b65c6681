#pragma once
// The block parser of the CSV reader (private to the io module): the rows of a regular file are
// parsed in blocks of a few MiB on several threads, each block on its own, and handed back in
// file order. A block is "clean" when every row in it is plain: no quote, the header's number
// of fields, a plain-seconds time later than the row before, numbers or missing cells in the
// mapped columns. Only clean blocks are used as parsed; the reader reads any other block row by
// row, so that values, errors, dropped rows and notes are exactly those of reading row by row.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "dynpos/core/units.hpp"

namespace dynpos::io::detail {

/// A mapped column: its 0-based field in the row, and how its number becomes SI.
struct BlockColumn {
  std::size_t field = 0;
  core::Unit unit;
  double scale = 1.0;
};

/// What the rows look like and which fields to parse.
struct BlockLayout {
  char delimiter = ',';
  std::size_t field_count = 0;  // fields of the header
  std::string comment_prefix;
  std::vector<std::string> missing_tokens;
  BlockColumn time;
  std::vector<BlockColumn> channels;
};

/// One channel's values in a block. Blocks and their channels sit on cache lines of their own:
/// threads parsing neighbouring blocks would otherwise write the same lines with every row.
struct alignas(64) BlockValues {
  std::vector<double> values;  // per row (SI, NaN = missing)
};

/// One block of rows as parsed.
struct alignas(64) Block {
  std::uint64_t begin = 0;     // byte offset of its first line
  std::uint64_t end = 0;       // byte offset after its last line
  std::size_t lines = 0;       // physical lines in [begin, end), blank and comment lines included
  bool clean = false;          // every row plain (see the file comment); the values are then valid
  std::vector<double> time_s;  // per row [s]
  std::vector<BlockValues> channels;  // per channel
  std::vector<std::size_t> skipped;   // per blank or comment line: the rows before it

  /// The line of row `row`, counted from the block's first line.
  std::size_t line_of_row(std::size_t row) const {
    return row + static_cast<std::size_t>(std::upper_bound(skipped.begin(), skipped.end(), row) -
                                          skipped.begin());
  }
};

/// Parses the rows of a regular file from a line start on, block by block.
class BlockReader {
 public:
  /// `jobs` threads (0 = every core); throws nothing until read.
  BlockReader(std::filesystem::path path, BlockLayout layout, unsigned jobs);
  ~BlockReader();
  BlockReader(const BlockReader&) = delete;
  BlockReader& operator=(const BlockReader&) = delete;

  /// Parses the blocks from `offset` (a line start) on, on several threads, and hands each to
  /// `take` in file order, one at a time, while the next ones are parsed; stops after the first
  /// block `take` returns false for, or at the end of the file. A block ends at the end of the
  /// file or at a line start. Throws core::InputError if the file cannot be read, and what `take`
  /// throws, once every thread has stopped.
  void stream(std::uint64_t offset, const std::function<bool(const Block&)>& take);

  std::uint64_t file_size() const noexcept { return file_size_; }

 private:
  struct State;
  std::unique_ptr<State> state_;
  std::uint64_t file_size_ = 0;
};

}  // namespace dynpos::io::detail
