#include "dynpos/io/mcap_reader.hpp"

#include <algorithm>
#include <array>
#include <cstring>

#include <fmt/format.h>

#include "byte_cursor.hpp"
#include "chunk_decompressor.hpp"
#include "crc32.hpp"

namespace dynpos::io {
namespace {

using detail::ByteCursor;
using detail::ByteError;

constexpr std::array<std::uint8_t, 8> kMagic = {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};
constexpr std::uint64_t kRecordHeaderBytes = 9;  // opcode u8, length u64
constexpr std::uint64_t kFooterBytes = kRecordHeaderBytes + 20;

enum Opcode : std::uint8_t {
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
  kChunkIndex = 0x08,
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

struct McapReader::State {
  std::string name;
  std::FILE* file = nullptr;
  std::uint64_t size = 0;
  std::uint64_t pos = 0;  // of the FILE
  std::uint64_t data_end = 0;
  std::map<std::uint16_t, McapSchema> schemas;
  std::map<std::uint16_t, McapChannel> channels;
  std::vector<ChunkIndex> chunk_indexes;
  bool summary = false;
  std::vector<std::uint8_t> record;
  std::vector<std::uint8_t> chunk_records;
  detail::ChunkDecompressor decompressor;
  std::map<std::uint16_t, bool> wanted;
  const std::function<bool(const McapChannel&)>* want = nullptr;
  const std::function<void(const McapMessage&)>* on_message = nullptr;

  ~State() {
    if (file != nullptr) std::fclose(file);
  }

  core::InputError error(std::uint64_t offset, const std::string& problem,
                         const std::string& topic = {}) const {
    return core::InputError({name, {}, {}, topic},
                            fmt::format("at {}: {}", at_byte(offset), problem),
                            "the file is not a complete MCAP file (cut short or damaged?)");
  }

  // Reads n bytes at `offset` into `out` (resized), checked against the file's size.
  void read_at(std::uint64_t offset, std::uint64_t n, std::vector<std::uint8_t>& out) {
    if (offset > size || n > size - offset) {
      throw error(offset, fmt::format("{} bytes are declared, only {} are left in the file", n,
                                      offset > size ? 0 : size - offset));
    }
    if (pos != offset && ::fseeko(file, static_cast<off_t>(offset), SEEK_SET) != 0) {
      throw error(offset, "cannot seek there");
    }
    out.resize(static_cast<std::size_t>(n));
    if (std::fread(out.data(), 1, out.size(), file) != out.size()) {
      throw error(offset, "cannot read the file there");
    }
    pos = offset + n;
  }

  // The opcode and content length of the record at `offset`, which must end by `limit`.
  std::pair<std::uint8_t, std::uint64_t> record_header(std::uint64_t offset, std::uint64_t limit) {
    std::vector<std::uint8_t>& head = record;
    read_at(offset, kRecordHeaderBytes, head);
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
  bool wants(std::uint16_t channel_id);
  void message(ByteCursor c, std::uint64_t offset, std::optional<std::uint64_t> in_chunk);
  void chunk(std::span<const std::uint8_t> content, std::uint64_t offset);
  void chunk_record(std::uint8_t op, std::span<const std::uint8_t> content, std::uint64_t offset,
                    std::uint64_t in_chunk);
  void read_indexed();
  void read_linear();
};

void McapReader::State::add_schema(ByteCursor c) {
  McapSchema s;
  s.id = c.u16("the schema id");
  s.name = c.string("the schema name");
  s.encoding = c.string("the schema encoding");
  s.data = c.string("the schema data");
  if (s.id != 0) schemas.try_emplace(s.id, std::move(s));
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
  const auto known = wanted.find(channel_id);
  if (known != wanted.end()) return known->second;
  const auto ch = channels.find(channel_id);
  if (ch == channels.end()) return false;  // the message reports it
  const bool yes = want == nullptr || (*want)(ch->second);
  wanted.emplace(channel_id, yes);
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
  if (!channels.contains(m.channel_id)) {
    throw core::InputError({name, {}, {}, {}},
                           fmt::format("at {}: a message of channel {}, which no Channel record "
                                       "declared before it",
                                       m.position(), m.channel_id),
                           "the file is not valid MCAP");
  }
  if (wants(m.channel_id)) (*on_message)(m);
}

void McapReader::State::chunk_record(std::uint8_t op, std::span<const std::uint8_t> content,
                                     std::uint64_t offset, std::uint64_t in_chunk) {
  if (op == kSchema) add_schema(ByteCursor(content));
  if (op == kChannel) add_channel(ByteCursor(content));
  if (op == kMessage) message(ByteCursor(content), offset, in_chunk);
}

void McapReader::State::chunk(std::span<const std::uint8_t> content, std::uint64_t offset) {
  ByteCursor c(content);
  std::span<const std::uint8_t> records;
  std::uint64_t size = 0;
  std::uint32_t crc = 0;
  std::string compression;
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
  std::span<const std::uint8_t> plain;
  try {
    plain = decompressor.decompress(compression, records, size);
  } catch (const ByteError& e) {
    throw error(offset, fmt::format("the chunk's {} data: {} (byte {} of it)",
                                    compression.empty() ? "uncompressed" : compression, e.what(),
                                    e.offset));
  }
  if (crc != 0 && detail::crc32(plain) != crc) {
    throw error(offset, fmt::format("the chunk's CRC is {:08x}, its records give {:08x}", crc,
                                    detail::crc32(plain)));
  }
  ByteCursor in(plain);
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

void McapReader::State::read_indexed() {
  for (const ChunkIndex& index : chunk_indexes) {
    if (!index.channels.empty() && std::none_of(index.channels.begin(), index.channels.end(),
                                                [this](std::uint16_t id) { return wants(id); })) {
      continue;
    }
    if (index.start < kMagic.size() || index.start > data_end ||
        index.length > data_end - index.start || index.length < kRecordHeaderBytes) {
      throw error(index.start, fmt::format("a chunk index points to [{}, +{}), outside the data "
                                           "section",
                                           index.start, index.length));
    }
    const auto [op, length] = record_header(index.start, data_end);
    if (op != kChunk || length + kRecordHeaderBytes != index.length) {
      throw error(index.start, "the chunk index does not point to a chunk of its length");
    }
    if (length > kMaxMcapChunkBytes + 64) throw error(index.start, "the chunk is too large");
    read_at(index.start + kRecordHeaderBytes, length, chunk_records);
    chunk(chunk_records, index.start);
  }
}

void McapReader::State::read_linear() {
  std::uint64_t at = kMagic.size();
  while (at < data_end) {
    if (data_end - at < kRecordHeaderBytes) {
      throw error(at, fmt::format("the file ends {} bytes into a record's header (cut short)",
                                  data_end - at));
    }
    const auto [op, length] = record_header(at, data_end);
    if (op == kFooter || op == kDataEnd) return;
    if (op == kSchema || op == kChannel || op == kMessage || op == kChunk) {
      if (length > kMaxMcapChunkBytes + 64) {
        throw error(at, fmt::format("a record of {} bytes, more than the {} dynpos reads", length,
                                    kMaxMcapChunkBytes));
      }
      std::vector<std::uint8_t>& content = op == kChunk ? chunk_records : record;
      read_at(at + kRecordHeaderBytes, length, content);
      if (op == kChunk) {
        chunk(content, at);
      } else {
        try {
          chunk_record(op, content, at, 0);
        } catch (const ByteError& e) {
          throw error(at, fmt::format("a record (opcode 0x{:02x}): {}", op, e.what()));
        }
      }
    }
    at += kRecordHeaderBytes + length;
  }
}

McapReader::McapReader(const std::filesystem::path& path) : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.name = path.string();
  std::error_code ec;
  s.size = std::filesystem::file_size(path, ec);
  s.file = ec ? nullptr : std::fopen(path.c_str(), "rb");
  if (s.file == nullptr) {
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

void McapReader::read_messages(const std::function<bool(const McapChannel&)>& wanted,
                               const std::function<void(const McapMessage&)>& on_message) {
  State& s = *state_;
  s.want = &wanted;
  s.on_message = &on_message;
  s.wanted.clear();
  if (s.summary && !s.chunk_indexes.empty()) {
    s.read_indexed();
  } else {
    s.read_linear();
  }
  s.want = nullptr;
  s.on_message = nullptr;
}

core::InputError McapReader::error(const std::string& where, const std::string& problem,
                                   const std::string& topic, const std::string& hint) const {
  return core::InputError({state_->name, {}, {}, topic}, fmt::format("at {}: {}", where, problem),
                          hint);
}

}  // namespace dynpos::io
