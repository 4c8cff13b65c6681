#include "csv_blocks.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <limits>
#include <mutex>
#include <string_view>

#include <fmt/format.h>

#include "csv_cell.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/core/log.hpp"
#include "dynpos/core/parallel_for.hpp"
#include "dynpos/io/csv_reader.hpp"

namespace dynpos::io::detail {
namespace {

constexpr std::uint64_t kBlockBytes = std::uint64_t{1} << 20;   // nominal block size
constexpr std::uint64_t kSlackBytes = std::uint64_t{64} << 10;  // read past it for the last line
constexpr std::size_t kNoSlot = std::numeric_limits<std::size_t>::max();

[[noreturn]] void throw_read_error(const std::string& path, int error) {
  core::InputLocation where;
  where.file = path;
  throw core::InputError(where, fmt::format("read error: {}", std::strerror(error)));
}

// The first `c` in [p, end), or end: eight bytes at a time (a byte equal to c is a zero byte of
// word ^ c…c, found by the borrow trick; the lowest flagged byte is always a true match).
const char* find_byte(const char* p, const char* end, char c) {
  if constexpr (std::endian::native == std::endian::little) {
    constexpr std::uint64_t kOnes = 0x0101010101010101ULL;
    const std::uint64_t pattern = kOnes * static_cast<unsigned char>(c);
    while (end - p >= 8) {
      std::uint64_t word = 0;
      std::memcpy(&word, p, sizeof word);
      const std::uint64_t x = word ^ pattern;
      const std::uint64_t found = (x - kOnes) & ~x & (kOnes << 7);
      if (found != 0) return p + (std::countr_zero(found) >> 3);
      p += 8;
    }
  }
  while (p != end && *p != c) ++p;
  return p;
}

// A block's bytes as read so far: [from, from + size) of the file.
struct Buffer {
  std::unique_ptr<char[]> data;
  std::size_t capacity = 0;
  std::uint64_t from = 0;
  std::size_t size = 0;
};

// The cells of a row that are parsed: each one's text and, when it was a plain decimal read as
// the row was cut (scan_plain_decimal), its number.
struct RowCells {
  std::vector<std::string_view> text;
  std::vector<double> number;
  std::vector<char> is_number;
};

// The bytes of the file whose lines make a block: the lines that start in [start, stop),
// `start` itself when it is known to be a line start.
struct BlockSpan {
  std::uint64_t start = 0;
  std::uint64_t stop = 0;
  bool at_line_start = false;
};

}  // namespace

struct BlockReader::State {
  std::string path;
  int fd = -1;
  std::uint64_t file_size = 0;
  BlockLayout layout;
  unsigned jobs = 1;
  std::vector<std::size_t> slot_of_field;  // field → index into a row's cells, or kNoSlot
  std::size_t time_slot = 0;
  std::vector<std::size_t> channel_slot;
  std::size_t slots = 0;
  std::size_t last_field = 0;  // the last field that is parsed
  bool scan_numbers = true;    // no missing token is itself a plain decimal
  std::vector<Block> blocks;   // the blocks in flight, each with its buffer
  std::vector<Buffer> buffers;

  // Reads [from, from + bytes) (up to the end of the file) into `b`, keeping what it holds.
  void read_into(Buffer& b, std::uint64_t from, std::uint64_t bytes);
  void parse_block(Block& block, Buffer& buffer, BlockSpan span);
  bool parse_row(std::string_view line, RowCells& cells, Block& block) const;
  const char* scan_plain_row(const char* p, const char* end, RowCells& cells) const;
  bool store_row(const RowCells& cells, Block& block) const;
  CellKind cell(const RowCells& cells, std::size_t slot, double& value) const;
};

void BlockReader::State::read_into(Buffer& b, std::uint64_t from, std::uint64_t bytes) {
  const std::uint64_t to = std::min(from + bytes, file_size);
  if (b.size == 0 || b.from != from) {
    b.from = from;
    b.size = 0;
  }
  const auto want = static_cast<std::size_t>(to - from);
  if (want > b.capacity) {
    auto grown = std::make_unique<char[]>(want);
    if (b.size > 0) std::memcpy(grown.get(), b.data.get(), b.size);
    b.data = std::move(grown);
    b.capacity = want;
  }
  while (b.size < want) {
    const ssize_t got =
        ::pread(fd, b.data.get() + b.size, want - b.size, static_cast<off_t>(from + b.size));
    if (got < 0) {
      if (errno == EINTR) continue;
      throw_read_error(path, errno);
    }
    if (got == 0) {  // the file is shorter than when reading began (a logger cut it)
      core::InputLocation where;
      where.file = path;
      throw core::InputError(
          where, fmt::format("the file shrank while it was read (to {} bytes)", from + b.size),
          "read a copy of the file, or wait until the logger has finished with it");
    }
    b.size += static_cast<std::size_t>(got);
  }
}

// What the cell in `slot` holds, `value` set for a number.
CellKind BlockReader::State::cell(const RowCells& cells, std::size_t slot, double& value) const {
  if (cells.is_number[slot] != 0) {
    value = cells.number[slot];
    return CellKind::kNumber;
  }
  return parse_cell(cells.text[slot], layout.missing_tokens, value);
}

// One row into the block (the caller has checked it holds no quote); false when it is not
// plain (the block is then read row by row).
bool BlockReader::State::parse_row(std::string_view line, RowCells& cells, Block& block) const {
  // The fields up to the last one parsed are cut out; the rest are only counted. A parsed field
  // that is a plain decimal up to the delimiter is read as it is cut (the same number parse_cell
  // gives: it has nothing to trim and is no missing token); any other is cut, then parsed.
  const char delimiter = layout.delimiter;
  const char* start = line.data();
  const char* const end = start + line.size();
  std::size_t field = 0;
  for (;;) {
    const std::size_t slot = slot_of_field[field];
    const char* stop = nullptr;
    if (slot != kNoSlot) {
      double value = 0.0;
      const char* scanned = scan_numbers ? scan_plain_decimal(start, end, value) : nullptr;
      const bool number = scanned != nullptr && (scanned == end || *scanned == delimiter);
      stop = number ? scanned : find_byte(start, end, delimiter);
      cells.text[slot] = std::string_view(start, static_cast<std::size_t>(stop - start));
      cells.number[slot] = value;
      cells.is_number[slot] = number ? 1 : 0;
    } else {
      stop = find_byte(start, end, delimiter);
    }
    ++field;
    if (stop == end) break;
    start = stop + 1;
    if (field > last_field) {
      field += static_cast<std::size_t>(std::count(start, end, delimiter)) + 1;
      break;
    }
  }
  return field == layout.field_count && store_row(cells, block);
}

// The line from p on, when every parsed field is a plain decimal up to its delimiter or the end
// of the line and the line has the header's number of fields: its '\n' (the row's cells set),
// else nullptr. The line is found as it is read, [p, end) being the bytes read so far: nullptr
// too when its end is not among them. For such a line parse_row() gives the same cells.
const char* BlockReader::State::scan_plain_row(const char* p, const char* const end,
                                               RowCells& cells) const {
  const char delimiter = layout.delimiter;
  std::size_t field = 0;
  for (;;) {
    const std::size_t slot = slot_of_field[field];
    const char* stop = p;
    if (slot != kNoSlot) {
      double value = 0.0;
      stop = scan_plain_decimal(p, end, value);
      if (stop == nullptr) return nullptr;
      cells.number[slot] = value;
      cells.is_number[slot] = 1;
    } else {
      while (stop != end && *stop != delimiter && *stop != '\n') ++stop;
    }
    ++field;
    if (stop == end) return nullptr;
    if (*stop == delimiter) {
      p = stop + 1;
      if (field <= last_field) continue;
      std::size_t more = 1;  // the fields after it, only counted
      while (p != end && *p != '\n') more += *p++ == delimiter ? 1 : 0;
      return p != end && field + more == layout.field_count ? p : nullptr;
    }
    if (*stop == '\r' && stop + 1 != end) ++stop;  // a CRLF line end
    return *stop == '\n' && field == layout.field_count ? stop : nullptr;
  }
}

// The cells of a row with the header's number of fields into the block; false when it is not
// plain.
bool BlockReader::State::store_row(const RowCells& cells, Block& block) const {
  double raw = 0.0;
  if (cell(cells, time_slot, raw) != CellKind::kNumber) return false;
  const double t = to_si(layout.time.unit, raw * layout.time.scale);
  if (!std::isfinite(t) || (!block.time_s.empty() && !(t > block.time_s.back()))) return false;
  for (std::size_t k = 0; k < channel_slot.size(); ++k) {
    const CellKind kind = cell(cells, channel_slot[k], raw);
    if (kind == CellKind::kNumber) {
      const double value = to_si(layout.channels[k].unit, raw * layout.channels[k].scale);
      if (!std::isfinite(value)) return false;  // the row reader names the cell
      block.channels[k].values.push_back(value);
    } else if (kind == CellKind::kMissing) {
      block.channels[k].values.push_back(core::kMissing);
    } else {
      return false;
    }
  }
  block.time_s.push_back(t);
  return true;
}

// The block of the lines of `span`.
void BlockReader::State::parse_block(Block& block, Buffer& buffer, BlockSpan span) {
  const std::uint64_t start = span.start;
  const std::uint64_t stop = span.stop;
  const bool at_line_start = span.at_line_start;
  block.time_s.clear();
  block.skipped.clear();
  block.channels.resize(layout.channels.size());
  for (auto& c : block.channels) c.values.clear();
  block.lines = 0;
  block.clean = true;

  const std::uint64_t from = at_line_start ? start : start - 1;
  read_into(buffer, from, stop - from + kSlackBytes);
  // Finds the end of the line from buffer offset `at`, reading on while it is not in view;
  // returns the offset of its '\n' or of the end of the file, or kTooLong past
  // kMaxCsvRecordBytes (the row reader then names the line).
  constexpr std::size_t kTooLong = std::numeric_limits<std::size_t>::max();
  const auto line_end = [&](std::size_t at) {
    for (;;) {
      const void* nl =
          at < buffer.size ? std::memchr(buffer.data.get() + at, '\n', buffer.size - at) : nullptr;
      if (nl != nullptr)
        return static_cast<std::size_t>(static_cast<const char*>(nl) - buffer.data.get());
      if (buffer.from + buffer.size >= file_size) return buffer.size;
      if (buffer.size - at > kMaxCsvRecordBytes) return kTooLong;
      read_into(buffer, buffer.from, 2 * buffer.size + kSlackBytes);
    }
  };
  std::size_t at = 0;
  if (!at_line_start) {  // the first line start at or after `start`
    const std::size_t nl = line_end(0);
    at = nl == kTooLong ? buffer.size : std::min(nl + 1, buffer.size);
    block.clean = nl != kTooLong;
  }
  block.begin = buffer.from + at;
  RowCells cells{std::vector<std::string_view>(slots), std::vector<double>(slots),
                 std::vector<char>(slots)};
  const std::string_view prefix = layout.comment_prefix;
  // A quote anywhere read: the block is read row by row. Checked again as the buffer grows.
  std::size_t quotes_checked = at;
  const auto check_quotes = [&] {
    if (quotes_checked >= buffer.size) return;
    block.clean = std::memchr(buffer.data.get() + quotes_checked, '"',
                              buffer.size - quotes_checked) == nullptr;
    quotes_checked = buffer.size;
  };
  while (buffer.from + at < stop && buffer.from + at < file_size) {
    if (block.clean) check_quotes();
    // The common row, all its parsed cells plain decimals, is read as its end is looked for;
    // any other line (blank, a comment, spaces, text, cut off by the bytes read) as below.
    const char* const data = buffer.data.get();
    if (block.clean && scan_numbers && at < buffer.size &&
        (prefix.empty() || data[at] != prefix.front())) {
      if (const char* nl = scan_plain_row(data + at, data + buffer.size, cells)) {
        ++block.lines;
        at = static_cast<std::size_t>(nl - data) + 1;
        if (!store_row(cells, block)) block.clean = false;
        continue;
      }
    }
    const std::size_t nl = line_end(at);
    if (nl == kTooLong) {  // read row by row, which stops at this line
      block.clean = false;
      at = buffer.size;
      break;
    }
    std::string_view line(buffer.data.get() + at, nl - at);
    ++block.lines;
    at = std::min(nl + 1, buffer.size);
    if (!block.clean) continue;  // only counting the lines now
    check_quotes();
    if (!block.clean) continue;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const char first = line.empty() ? ' ' : line.front();
    if (first == ' ' || first == '\t' || (!prefix.empty() && first == prefix.front())) {
      const std::string_view text = trim(line);  // blank, a comment, or a row after spaces
      if (text.empty() || (!prefix.empty() && text.substr(0, prefix.size()) == prefix)) {
        block.skipped.push_back(block.time_s.size());
        continue;
      }
    }
    if (!parse_row(line, cells, block)) block.clean = false;
  }
  block.end = buffer.from + at;
}

BlockReader::BlockReader(std::filesystem::path path, BlockLayout layout, unsigned jobs)
    : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.path = path.string();
  s.layout = std::move(layout);
  s.fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (s.fd < 0) throw_read_error(s.path, errno);
  struct stat info {};
  if (::fstat(s.fd, &info) != 0) throw_read_error(s.path, errno);
  file_size_ = static_cast<std::uint64_t>(info.st_size);
  s.file_size = file_size_;
  s.jobs = core::job_count(jobs, 1024);
  s.slot_of_field.assign(s.layout.field_count, kNoSlot);
  const auto slot = [&](std::size_t field) {
    if (s.slot_of_field[field] == kNoSlot) s.slot_of_field[field] = s.slots++;
    s.last_field = std::max(s.last_field, field);
    return s.slot_of_field[field];
  };
  s.time_slot = slot(s.layout.time.field);
  double token_value = 0.0;
  s.scan_numbers = std::none_of(
      s.layout.missing_tokens.begin(), s.layout.missing_tokens.end(),
      [&](const std::string& token) { return parse_plain_decimal(trim(token), token_value); });
  for (const BlockColumn& c : s.layout.channels) s.channel_slot.push_back(slot(c.field));
}

BlockReader::~BlockReader() {
  if (state_ && state_->fd >= 0) ::close(state_->fd);
}

void BlockReader::stream(std::uint64_t offset, const std::function<bool(const Block&)>& take) {
  State& s = *state_;
  if (offset >= file_size_) return;
  const std::uint64_t count = (file_size_ - offset + kBlockBytes - 1) / kBlockBytes;
  // Two blocks in flight per thread: one being parsed, one parsed and waiting its turn.
  const auto slots = static_cast<std::size_t>(std::min<std::uint64_t>(2 * s.jobs, count));
  if (s.blocks.size() < slots) s.blocks.resize(slots);
  if (s.buffers.size() < slots) s.buffers.resize(slots);
  std::mutex mutex;  // guards what follows, up to the workers
  std::condition_variable freed;
  std::uint64_t next = 0;   // the next block to parse
  std::uint64_t taken = 0;  // the blocks handed on
  std::vector<char> parsed(slots, 0);
  bool stop = false;    // a block was refused, or a thread failed
  bool taking = false;  // a thread is handing blocks on; it takes the others' too
  // Hands on the parsed blocks in file order, one at a time, while other threads parse on.
  const auto hand_on = [&](std::unique_lock<std::mutex>& lock) {
    taking = true;
    while (!stop && taken < count && parsed[taken % slots] != 0) {
      const std::size_t slot = taken % slots;
      lock.unlock();
      bool go = false;
      try {
        go = take(s.blocks[slot]);
      } catch (...) {
        lock.lock();
        stop = true;
        taking = false;
        freed.notify_all();
        throw;
      }
      lock.lock();
      parsed[slot] = 0;
      ++taken;
      stop = stop || !go;
      freed.notify_all();
    }
    taking = false;
  };
  const auto worker = [&](std::size_t) {
    for (;;) {
      std::unique_lock lock(mutex);
      freed.wait(lock, [&] { return stop || next >= count || next < taken + slots; });
      if (stop || next >= count) return;
      const std::uint64_t k = next++;
      lock.unlock();
      const std::size_t slot = k % slots;
      const std::uint64_t start = offset + k * kBlockBytes;
      try {
        s.parse_block(s.blocks[slot], s.buffers[slot],
                      {start, std::min(start + kBlockBytes, file_size_), k == 0});
      } catch (...) {
        lock.lock();
        stop = true;
        freed.notify_all();
        throw;
      }
      lock.lock();
      parsed[slot] = 1;
      if (!taking) hand_on(lock);
    }
  };
  core::parallel_for(core::job_count(s.jobs, count), s.jobs, worker);
}

}  // namespace dynpos::io::detail
