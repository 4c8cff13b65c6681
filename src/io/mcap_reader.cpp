#include "dynpos/io/mcap_reader.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <deque>
#include <exception>

#include <fmt/format.h>

#include "byte_cursor.hpp"
#include "chunk_decompressor.hpp"
#include "crc32.hpp"
#include "dynpos/core/parallel_for.hpp"
#include "ordered_work.hpp"

namespace dynpos::io {
namespace {

using detail::ByteCursor;
using detail::ByteError;

constexpr std::array<std::uint8_t, 8> kMagic = {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};
constexpr std::uint64_t kRecordHeaderBytes = 9;  // opcode u8, length u64
constexpr std::uint64_t kFooterBytes = kRecordHeaderBytes + 20;
constexpr std::uint64_t kMessageHeadBytes = 22;  // channel u16, sequence u32, two times u64

enum Opcode : std::uint8_t {
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
  kChunkIndex = 0x08,
  kStatistics = 0x0B,
  kDataEnd = 0x0F,
};

struct ChunkIndex {
  std::uint64_t start = 0;   // the chunk record's offset
  std::uint64_t length = 0;  // its bytes, header included
  std::vector<std::uint16_t> channels;
};

std::string at_byte(std::uint64_t offset) { return fmt::format("byte {}", offset); }

}  // namespace

std::string McapMessage::position() const {
  if (!offset_in_chunk) return at_byte(record_offset);
  return fmt::format("byte {} of the records of the chunk at byte {}", *offset_in_chunk,
                     record_offset);
}

bool looks_like_mcap(const std::filesystem::path& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) return false;
  std::array<std::uint8_t, 8> head{};
  const bool magic = std::fread(head.data(), 1, head.size(), f) == head.size() && head == kMagic;
  std::fclose(f);
  return magic;
}

// One chunk read, decompressed and checked off the thread that hands its messages on.
struct ChunkSlot {
  std::uint64_t offset = 0;        // the chunk record's
  std::uint64_t length = 0;        // from a chunk index: the record's bytes; else its content's
  bool indexed = false;            // found through a chunk index (whose bounds are still to check)
  std::vector<std::uint8_t> kept;  // its records, when the calling thread is to read them
  std::span<const std::uint8_t> plain;  // its records, decompressed (and checked once loaded)
  std::uint32_t crc = 0;                // the CRC the chunk declares (0: none)
  std::unique_ptr<McapChunkWork> work;  // taking messages ahead, if any
  std::vector<signed char> wanted;      // State::wanted as the chunk was queued
  std::size_t resume = 0;               // the byte of `plain` where the calling thread goes on
};

// The CRC of a chunk's records, computed in slices just ahead of the records looked at, so that
// their bytes are still in the cache when they are decoded.
struct RunningCrc {
  static constexpr std::size_t kSliceBytes = std::size_t{32} << 10;
  std::span<const std::uint8_t> bytes;
  bool wanted = true;  // else value stays 0
  std::uint32_t value = 0;
  std::size_t done = 0;  // the bytes covered

  // Covers at least the bytes [0, end).
  void upto(std::size_t end) {
    if (!wanted || end <= done) return;
    const std::size_t to = std::min(bytes.size(), std::max(end, done + kSliceBytes));
    value = detail::crc32(bytes.subspan(done, to - done), value);
    done = to;
  }
};

// What a thread keeps from chunk to chunk: the room it reads a chunk into and decompresses it
// into (still in its cache for the next), and its decompression contexts.
struct ThreadRoom {
  std::vector<std::uint8_t> bytes;
  std::vector<std::uint8_t> decompressed;
  detail::ChunkDecompressor decompressor;
};

// What comes next in file order: a chunk (in a slot), another record, or the error found there.
struct Unit {
  std::uint8_t op = 0;
  std::uint64_t offset = 0;
  std::uint64_t length = 0;  // of the content
  std::size_t slot = 0;
  std::exception_ptr error;
};

struct McapReader::State {
  std::string name;
  int fd = -1;
  unsigned jobs = 1;
  std::uint64_t size = 0;
  std::uint64_t data_end = 0;
  std::map<std::uint16_t, McapSchema> schemas;
  std::map<std::uint16_t, McapChannel> channels;
  std::map<std::uint16_t, std::uint64_t> message_counts;
  std::vector<ChunkIndex> chunk_indexes;
  bool summary = false;
  std::vector<std::uint8_t> record;
  std::vector<std::uint8_t> window;  // bytes [window_at, +size) of the file, for small reads
  std::uint64_t window_at = 0;
  std::vector<ChunkSlot> slots;
  std::vector<ThreadRoom> rooms;    // by thread (OrderedWork)
  std::vector<signed char> wanted;  // by channel id: -1 not asked yet, else 0 or 1
  const std::function<bool(const McapChannel&)>* want = nullptr;
  const std::function<void(const McapMessage&)>* on_message = nullptr;
  const std::function<std::unique_ptr<McapChunkWork>()>* chunk_work = nullptr;

  ~State() {
    if (fd >= 0) ::close(fd);
  }

  core::InputError error(std::uint64_t offset, const std::string& problem,
                         const std::string& topic = {}) const {
    return core::InputError({name, {}, {}, topic},
                            fmt::format("at {}: {}", at_byte(offset), problem),
                            "the file is not a complete MCAP file (cut short or damaged?)");
  }

  // Throws unless the file holds n bytes at `offset`.
  void check_span(std::uint64_t offset, std::uint64_t n) const {
    if (offset > size || n > size - offset) {
      throw error(offset, fmt::format("{} bytes are declared, only {} are left in the file", n,
                                      offset > size ? 0 : size - offset));
    }
  }

  // Reads n bytes at `offset` into `out` (resized), checked against the file's size; safe on
  // any thread.
  void pread_at(std::uint64_t offset, std::uint64_t n, std::vector<std::uint8_t>& out) const {
    check_span(offset, n);
    out.resize(static_cast<std::size_t>(n));
    pread_into(offset, out);
  }
  // Reads out.size() bytes at `offset` (checked against the file's size already).
  void pread_into(std::uint64_t offset, std::span<std::uint8_t> out) const {
    std::size_t done = 0;
    while (done < out.size()) {
      const ssize_t got =
          ::pread(fd, out.data() + done, out.size() - done, static_cast<off_t>(offset + done));
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) throw error(offset, "cannot read the file there");
      done += static_cast<std::size_t>(got);
    }
  }

  // As pread_at, small reads served from a window of the file read ahead (the calling thread's
  // records one after another).
  void read_at(std::uint64_t offset, std::uint64_t n, std::vector<std::uint8_t>& out) {
    constexpr std::uint64_t kWindowBytes = std::uint64_t{1} << 16;
    check_span(offset, n);
    if (n > kWindowBytes / 2) return pread_at(offset, n, out);
    if (offset < window_at || offset + n > window_at + window.size()) {
      pread_at(offset, std::min(kWindowBytes, size - offset), window);
      window_at = offset;
    }
    const auto* from = window.data() + (offset - window_at);
    out.assign(from, from + n);
  }

  // The opcode and content length of the record at `offset`, which must end by `limit`.
  std::pair<std::uint8_t, std::uint64_t> record_header(std::uint64_t offset, std::uint64_t limit) {
    std::vector<std::uint8_t>& head = record;
    read_at(offset, kRecordHeaderBytes, head);
    return check_header(head, offset, limit);
  }
  std::pair<std::uint8_t, std::uint64_t> check_header(std::span<const std::uint8_t> head,
                                                      std::uint64_t offset,
                                                      std::uint64_t limit) const {
    std::uint64_t length = 0;
    std::memcpy(&length, head.data() + 1, 8);
    const std::uint64_t left = limit - offset - kRecordHeaderBytes;
    if (length > left) {
      throw error(offset, fmt::format("the record (opcode 0x{:02x}) declares {} bytes, only {} "
                                      "are left",
                                      head[0], length, left));
    }
    return {head[0], length};
  }

  void open_summary();
  void add_schema(ByteCursor c);
  void add_channel(ByteCursor c);
  void add_statistics(ByteCursor c);
  bool wants(std::uint16_t channel_id);
  void message(ByteCursor c, std::uint64_t offset, std::optional<std::uint64_t> in_chunk);
  // A chunk's records, decompressed, checked and offered to its work; what the calling thread
  // is to read of them in slot.plain (any thread).
  void load_chunk(ChunkSlot& slot, ThreadRoom& room) const;
  void unpack_chunk(ChunkSlot& slot, std::span<const std::uint8_t> content,
                    detail::ChunkDecompressor& decompressor, std::vector<std::uint8_t>& out) const;
  static std::size_t take_ahead(ChunkSlot& slot, RunningCrc& crc);
  void chunk_records(std::span<const std::uint8_t> plain, std::uint64_t offset, std::size_t from);
  void chunk_record(std::uint8_t op, std::span<const std::uint8_t> content, std::uint64_t offset,
                    std::uint64_t in_chunk);
  std::optional<Unit> next_indexed(std::size_t& next_index, bool settled, bool& later);
  std::optional<Unit> next_linear(std::uint64_t& at);
  void read_units(bool indexed);
};

void McapReader::State::add_schema(ByteCursor c) {
  McapSchema s;
  s.id = c.u16("the schema id");
  s.name = c.string("the schema name");
  s.encoding = c.string("the schema encoding");
  s.data = c.string("the schema data");
  if (s.id != 0) schemas.try_emplace(s.id, std::move(s));
}

void McapReader::State::add_statistics(ByteCursor c) {
  std::map<std::uint16_t, std::uint64_t> counts;
  try {
    c.skip(8 + 2 + 4 + 4 + 4 + 4 + 8 + 8, "the statistics' counts and times");
    ByteCursor map(c.bytes(c.u32("the channel message counts"), "the counts"));
    while (!map.done()) {
      const std::uint16_t channel = map.u16("a channel id");
      counts[channel] = map.u64("its message count");
    }
  } catch (const ByteError&) {
    return;  // a hint only: a damaged record is as none
  }
  message_counts = std::move(counts);
}

void McapReader::State::add_channel(ByteCursor c) {
  McapChannel ch;
  ch.id = c.u16("the channel id");
  ch.schema_id = c.u16("the channel's schema id");
  ch.topic = c.string("the channel topic");
  ch.message_encoding = c.string("the channel's message encoding");
  channels.try_emplace(ch.id, std::move(ch));
}

bool McapReader::State::wants(std::uint16_t channel_id) {
  if (channel_id >= wanted.size()) wanted.resize(std::size_t{channel_id} + 1, -1);
  signed char& known = wanted[channel_id];
  if (known >= 0) return known != 0;
  const auto ch = channels.find(channel_id);
  if (ch == channels.end()) return false;  // the message reports it
  const bool yes = want == nullptr || (*want)(ch->second);
  known = yes ? 1 : 0;
  return yes;
}

void McapReader::State::message(ByteCursor c, std::uint64_t offset,
                                std::optional<std::uint64_t> in_chunk) {
  McapMessage m;
  m.channel_id = c.u16("the message's channel id");
  c.u32("the message's sequence number");
  m.log_time_ns = c.u64("the message's log time");
  m.publish_time_ns = c.u64("the message's publish time");
  m.data = c.bytes(c.left(), "the message data");
  m.record_offset = offset;
  m.offset_in_chunk = in_chunk;
  if (wants(m.channel_id)) {
    (*on_message)(m);
  } else if (!channels.contains(m.channel_id)) {
    throw core::InputError({name, {}, {}, {}},
                           fmt::format("at {}: a message of channel {}, which no Channel record "
                                       "declared before it",
                                       m.position(), m.channel_id),
                           "the file is not valid MCAP");
  }
}

void McapReader::State::chunk_record(std::uint8_t op, std::span<const std::uint8_t> content,
                                     std::uint64_t offset, std::uint64_t in_chunk) {
  if (op == kMessage) message(ByteCursor(content), offset, in_chunk);
  if (op == kSchema) add_schema(ByteCursor(content));
  if (op == kChannel) add_channel(ByteCursor(content));
}

void McapReader::State::load_chunk(ChunkSlot& slot, ThreadRoom& room) const {
  std::uint64_t length = slot.length;
  if (slot.indexed) {
    if (slot.offset < kMagic.size() || slot.offset > data_end ||
        slot.length > data_end - slot.offset || slot.length < kRecordHeaderBytes) {
      throw error(slot.offset, fmt::format("a chunk index points to [{}, +{}), outside the data "
                                           "section",
                                           slot.offset, slot.length));
    }
    std::array<std::uint8_t, kRecordHeaderBytes> head{};
    check_span(slot.offset, kRecordHeaderBytes);
    pread_into(slot.offset, head);
    const auto [op, declared] = check_header(head, slot.offset, data_end);
    if (op != kChunk || declared + kRecordHeaderBytes != slot.length) {
      throw error(slot.offset, "the chunk index does not point to a chunk of its length");
    }
    if (declared > kMaxMcapChunkBytes + 64) throw error(slot.offset, "the chunk is too large");
    length = declared;
  }
  // Into the thread's room, kept from chunk to chunk: a vector's resize would zero what it adds
  // each time. Records taken ahead need no other; else they are kept with the chunk.
  check_span(slot.offset + kRecordHeaderBytes, length);
  if (room.bytes.size() < length) room.bytes.resize(static_cast<std::size_t>(length));
  const auto content = std::span(room.bytes).first(static_cast<std::size_t>(length));
  pread_into(slot.offset + kRecordHeaderBytes, content);
  unpack_chunk(slot, content, room.decompressor, slot.work ? room.decompressed : slot.kept);
  RunningCrc crc{slot.plain, slot.crc != 0};
  slot.resume = slot.work ? take_ahead(slot, crc) : 0;
  crc.upto(slot.plain.size());
  if (crc.value != slot.crc) {
    throw error(slot.offset, fmt::format("the chunk's CRC is {:08x}, its records give {:08x}",
                                         slot.crc, crc.value));
  }
  if (slot.resume == slot.plain.size()) {
    slot.plain = {};  // every record taken ahead: nothing left for the calling thread
    slot.resume = 0;
    std::vector<std::uint8_t>().swap(slot.kept);  // what an earlier chunk left, freed
  } else if (slot.plain.data() != slot.kept.data()) {
    slot.kept.assign(slot.plain.begin(), slot.plain.end());
    slot.plain = slot.kept;
  }
}

// Offers slot.work the chunk's messages of channels wanted (as known when it was queued) and
// skips those of channels not wanted, up to a record the calling thread must see: a Schema or
// Channel record, a message of a channel not judged yet or that the work leaves, a record cut
// short. Returns the byte where that record starts (the end when there is none).
std::size_t McapReader::State::take_ahead(ChunkSlot& slot, RunningCrc& crc) {
  const std::span<const std::uint8_t> plain = slot.plain;
  const std::uint8_t* const base = plain.data();
  std::size_t at = 0;
  while (plain.size() - at >= kRecordHeaderBytes) {
    const std::uint8_t op = base[at];
    std::uint64_t length = 0;
    std::memcpy(&length, base + at + 1, 8);
    const std::size_t content = at + kRecordHeaderBytes;
    if (length > plain.size() - content || op == kSchema || op == kChannel) break;
    crc.upto(content + static_cast<std::size_t>(length));
    if (op == kMessage) {
      if (length < kMessageHeadBytes) break;
      McapMessage m;
      std::memcpy(&m.channel_id, base + content, 2);
      const signed char wanted = m.channel_id < slot.wanted.size() ? slot.wanted[m.channel_id] : -1;
      if (wanted < 0) break;
      if (wanted > 0) {
        std::memcpy(&m.log_time_ns, base + content + 6, 8);
        std::memcpy(&m.publish_time_ns, base + content + 14, 8);
        m.data = plain.subspan(content + kMessageHeadBytes,
                               static_cast<std::size_t>(length - kMessageHeadBytes));
        m.record_offset = slot.offset;
        m.offset_in_chunk = at;
        if (!slot.work->take(m)) break;
      }
    }
    at = content + static_cast<std::size_t>(length);
  }
  return at;
}

void McapReader::State::unpack_chunk(ChunkSlot& slot, std::span<const std::uint8_t> content,
                                     detail::ChunkDecompressor& decompressor,
                                     std::vector<std::uint8_t>& out) const {
  const std::uint64_t offset = slot.offset;
  ByteCursor c(content);
  std::span<const std::uint8_t> records;
  std::uint64_t size = 0;
  std::uint32_t crc = 0;
  std::string_view compression;
  try {
    c.skip(16, "the chunk's message times");
    size = c.u64("the chunk's uncompressed size");
    crc = c.u32("the chunk's CRC");
    compression = c.string("the chunk's compression");
    records = c.bytes(c.u64("the chunk's records length"), "the chunk's records");
  } catch (const ByteError& e) {
    throw error(offset, fmt::format("a chunk: {} (byte {} of the record)", e.what(), e.offset));
  }
  if (size > kMaxMcapChunkBytes) {
    throw error(offset, fmt::format("a chunk declares {} uncompressed bytes, more than the {} "
                                    "dynpos reads",
                                    size, kMaxMcapChunkBytes));
  }
  try {
    slot.plain = decompressor.decompress(compression, records, size, out);
  } catch (const ByteError& e) {
    throw error(offset, fmt::format("the chunk's {} data: {} (byte {} of it)",
                                    compression.empty() ? "uncompressed" : compression, e.what(),
                                    e.offset));
  }
  slot.crc = crc;
}

void McapReader::State::chunk_records(std::span<const std::uint8_t> plain, std::uint64_t offset,
                                      std::size_t from) {
  ByteCursor in(plain);
  in.skip(from, "the records taken ahead");
  while (!in.done()) {
    const std::size_t at = in.pos();
    try {
      const std::uint8_t op = in.u8("a record's opcode");
      const std::uint64_t length = in.u64("a record's length");
      chunk_record(op, in.bytes(length, "the record"), offset, at);
    } catch (const ByteError& e) {
      throw error(offset, fmt::format("byte {} of the chunk's records: {}", at, e.what()));
    }
  }
}
void McapReader::State::open_summary() {
  if (size < kMagic.size() + kFooterBytes + kMagic.size()) return;
  std::vector<std::uint8_t> tail;
  const std::uint64_t footer = size - kMagic.size() - kFooterBytes;
  read_at(footer, kFooterBytes + kMagic.size(), tail);
  if (!std::equal(kMagic.begin(), kMagic.end(), tail.end() - kMagic.size()) || tail[0] != kFooter) {
    return;  // cut short: read linearly
  }
  ByteCursor c(std::span<const std::uint8_t>(tail).subspan(kRecordHeaderBytes));
  const std::uint64_t start = c.u64("summary start");
  const std::uint64_t offset_start = c.u64("summary offset start");
  data_end = footer;
  if (start == 0) return;
  const std::uint64_t end = offset_start != 0 ? offset_start : footer;
  if (start < kMagic.size() || start > end || end > footer) {
    throw error(footer, fmt::format("the footer's summary section [{}, {}) is not inside the "
                                    "file's {} bytes",
                                    start, end, footer));
  }
  data_end = start;
  for (std::uint64_t at = start; at < end;) {
    if (end - at < kRecordHeaderBytes) throw error(at, "a summary record is cut short");
    const auto [op, length] = record_header(at, end);
    if (op == kStatistics && length <= kMaxMcapChunkBytes) {
      read_at(at + kRecordHeaderBytes, length, record);
      add_statistics(ByteCursor(record));
    }
    if (op == kSchema || op == kChannel || op == kChunkIndex) {
      if (length > kMaxMcapChunkBytes) throw error(at, "a summary record is too large");
      read_at(at + kRecordHeaderBytes, length, record);
      ByteCursor r(record);
      try {
        if (op == kSchema) add_schema(r);
        if (op == kChannel) add_channel(r);
        if (op == kChunkIndex) {
          ChunkIndex index;
          r.skip(16, "the chunk's message times");
          index.start = r.u64("the chunk's offset");
          index.length = r.u64("the chunk's length");
          ByteCursor offsets(r.bytes(r.u32("the message index offsets"), "the offsets"));
          while (!offsets.done()) {
            index.channels.push_back(offsets.u16("a channel id"));
            offsets.u64("a message index offset");
          }
          chunk_indexes.push_back(std::move(index));
        }
      } catch (const ByteError& e) {
        throw error(at, fmt::format("a summary record (opcode 0x{:02x}): {}", op, e.what()));
      }
    }
    at += kRecordHeaderBytes + length;
  }
  summary = true;
  std::sort(chunk_indexes.begin(), chunk_indexes.end(),
            [](const ChunkIndex& a, const ChunkIndex& b) { return a.start < b.start; });
}

// The next chunk the index lists that holds a wanted channel. A chunk that lists a channel
// not known yet (declared in an earlier chunk, not in the summary) is judged once every unit
// before it is handed on (`settled`); until then `later` is set.
std::optional<Unit> McapReader::State::next_indexed(std::size_t& next_index, bool settled,
                                                    bool& later) {
  while (next_index < chunk_indexes.size()) {
    const ChunkIndex& index = chunk_indexes[next_index];
    const auto unknown = [this](std::uint16_t id) { return !channels.contains(id); };
    if (!settled && std::any_of(index.channels.begin(), index.channels.end(), unknown)) {
      later = true;
      return std::nullopt;
    }
    ++next_index;
    bool wanted = index.channels.empty();
    for (const std::uint16_t id : index.channels) {
      wanted = wants(id) || wanted;  // each judged now, for the work taking messages ahead
    }
    if (!wanted) continue;
    return Unit{kChunk, index.start, index.length, 0, nullptr};
  }
  return std::nullopt;
}

// The next record from `at` on that is read (its header checked), or the error found there.
std::optional<Unit> McapReader::State::next_linear(std::uint64_t& at) {
  while (at < data_end) {
    Unit unit{0, at, 0, 0, nullptr};
    try {
      if (data_end - at < kRecordHeaderBytes) {
        throw error(at, fmt::format("the file ends {} bytes into a record's header (cut short)",
                                    data_end - at));
      }
      const auto [op, length] = record_header(at, data_end);
      if (op == kFooter || op == kDataEnd) {
        at = data_end;
        return std::nullopt;
      }
      at += kRecordHeaderBytes + length;
      if (op != kSchema && op != kChannel && op != kMessage && op != kChunk) continue;
      if (length > kMaxMcapChunkBytes + 64) {
        throw error(unit.offset, fmt::format("a record of {} bytes, more than the {} dynpos reads",
                                             length, kMaxMcapChunkBytes));
      }
      unit.op = op;
      unit.length = length;
    } catch (const core::InputError&) {
      unit.error = std::current_exception();
      at = data_end;
    }
    return unit;
  }
  return std::nullopt;
}

// Hands on the messages of the chunks (read ahead on worker threads) and records in file order.
void McapReader::State::read_units(bool indexed) {
  // Chunks in flight: two per worker and the one being handed on, within a budget of bytes.
  constexpr std::uint64_t kAheadBytes = std::uint64_t{64} << 20;
  const unsigned workers = jobs > 1 ? jobs : 0;
  if (slots.size() < 2 * std::size_t{workers} + 1) slots.resize(2 * std::size_t{workers} + 1);
  if (rooms.size() < std::size_t{workers} + 1) {
    rooms.resize(std::size_t{workers} + 1);  // the workers' and the calling thread's
  }
  detail::OrderedWork work(workers, slots.size(), [this](std::size_t k, unsigned thread) {
    load_chunk(slots[k], rooms[thread]);
  });
  std::deque<Unit> units;
  std::size_t next_index = 0;
  std::uint64_t at = kMagic.size();
  std::size_t next_slot = 0;
  std::uint64_t ahead = 0;  // bytes of the chunks in flight
  bool ended = false;
  const auto fill = [&] {
    while (!ended && work.in_flight() < work.slots() &&
           (work.in_flight() == 0 || ahead < kAheadBytes) &&
           (units.empty() || units.back().op == kChunk)) {
      bool later = false;
      std::optional<Unit> unit =
          indexed ? next_indexed(next_index, units.empty(), later) : next_linear(at);
      if (later) return;
      if (!unit || unit->error) ended = true;
      if (!unit) return;
      if (unit->op == kChunk && !unit->error) {
        ChunkSlot& slot = slots[next_slot];
        slot.offset = unit->offset;
        slot.length = unit->length;
        slot.indexed = indexed;
        if (chunk_work != nullptr) {
          if (!slot.work) slot.work = (*chunk_work)();
          slot.wanted = wanted;
          slot.work->prepare();
        }
        unit->slot = next_slot;
        next_slot = (next_slot + 1) % slots.size();
        ahead += unit->length;
        work.queue(unit->slot);
      }
      units.push_back(*unit);
    }
  };
  for (fill(); !units.empty(); fill()) {
    const Unit unit = units.front();
    units.pop_front();
    if (unit.error) std::rethrow_exception(unit.error);
    if (unit.op == kChunk) {
      work.take(unit.slot);
      ahead -= unit.length;
      ChunkSlot& slot = slots[unit.slot];
      if (slot.work) slot.work->hand_on();
      chunk_records(slot.plain, unit.offset, slot.resume);
      continue;
    }
    read_at(unit.offset + kRecordHeaderBytes, unit.length, record);
    try {
      chunk_record(unit.op, record, unit.offset, 0);
    } catch (const ByteError& e) {
      throw error(unit.offset, fmt::format("a record (opcode 0x{:02x}): {}", unit.op, e.what()));
    }
  }
}

McapReader::McapReader(const std::filesystem::path& path, unsigned jobs)
    : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.name = path.string();
  s.jobs = core::job_count(jobs, 64);
  std::error_code ec;
  s.size = std::filesystem::file_size(path, ec);
  s.fd = ec ? -1 : ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (s.fd < 0) {
    throw core::InputError({s.name, {}, {}, {}}, "cannot open the file", "check the path");
  }
  std::vector<std::uint8_t> head;
  if (s.size < kMagic.size() || (s.read_at(0, kMagic.size(), head),
                                 !std::equal(kMagic.begin(), kMagic.end(), head.begin()))) {
    throw core::InputError({s.name, {}, {}, {}}, "not an MCAP file (no \\x89MCAP0 magic)");
  }
  s.data_end = s.size;
  s.open_summary();
}

McapReader::~McapReader() = default;
McapReader::McapReader(McapReader&&) noexcept = default;
McapReader& McapReader::operator=(McapReader&&) noexcept = default;

const std::map<std::uint16_t, McapSchema>& McapReader::schemas() const noexcept {
  return state_->schemas;
}
const std::map<std::uint16_t, McapChannel>& McapReader::channels() const noexcept {
  return state_->channels;
}
bool McapReader::has_summary() const noexcept { return state_->summary; }
const std::map<std::uint16_t, std::uint64_t>& McapReader::message_counts() const noexcept {
  return state_->message_counts;
}

void McapReader::read_messages(const std::function<bool(const McapChannel&)>& wanted,
                               const std::function<void(const McapMessage&)>& on_message) {
  read_messages(wanted, on_message, {});
}

void McapReader::read_messages(const std::function<bool(const McapChannel&)>& wanted,
                               const std::function<void(const McapMessage&)>& on_message,
                               const std::function<std::unique_ptr<McapChunkWork>()>& chunk_work) {
  State& s = *state_;
  s.want = &wanted;
  s.on_message = &on_message;
  s.chunk_work = chunk_work ? &chunk_work : nullptr;
  s.wanted.clear();
  for (ChunkSlot& slot : s.slots) slot.work.reset();
  const auto done = [&s] {
    s.want = nullptr;
    s.on_message = nullptr;
    s.chunk_work = nullptr;
    for (ChunkSlot& slot : s.slots) slot.work.reset();
  };
  try {
    s.read_units(s.summary && !s.chunk_indexes.empty());
  } catch (...) {
    done();
    throw;
  }
  done();
}

core::InputError McapReader::error(const std::string& where, const std::string& problem,
                                   const std::string& topic, const std::string& hint) const {
  return core::InputError({state_->name, {}, {}, topic}, fmt::format("at {}: {}", where, problem),
                          hint);
}

}  // namespace dynpos::io
