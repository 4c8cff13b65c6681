#pragma once
// A small MCAP writer and CDR encoder for the tests' own ROS 2 bags (not part of dynpos).

#include <lz4frame.h>
#include <zstd.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace dynpos::io::testing {

using Bytes = std::vector<std::uint8_t>;

/// CDR (XCDR1) of one message: the encapsulation header, then fields aligned to their size
/// from the byte after it.
class CdrWriter {
 public:
  explicit CdrWriter(bool big_endian = false) : big_(big_endian) {
    out_ = {0x00, static_cast<std::uint8_t>(big_endian ? 0x00 : 0x01), 0x00, 0x00};
  }
  template <class T>
  CdrWriter& put(T value) {
    align(sizeof(T));
    std::uint8_t b[sizeof(T)];
    std::memcpy(b, &value, sizeof(T));
    if (big_) std::reverse(b, b + sizeof(T));
    out_.insert(out_.end(), b, b + sizeof(T));
    return *this;
  }
  CdrWriter& string(std::string_view s) {
    put(static_cast<std::uint32_t>(s.size() + 1));
    out_.insert(out_.end(), s.begin(), s.end());
    out_.push_back(0);
    return *this;
  }
  /// std_msgs/Header: stamp (sec, nanosec) and frame_id.
  CdrWriter& header(std::int64_t stamp_ns, std::string_view frame = "base_link") {
    put(static_cast<std::int32_t>(stamp_ns / 1'000'000'000));
    put(static_cast<std::uint32_t>(stamp_ns % 1'000'000'000));
    return string(frame);
  }
  const Bytes& bytes() const { return out_; }

 private:
  void align(std::size_t n) {
    while ((out_.size() - 4) % n != 0) out_.push_back(0);
  }
  bool big_;
  Bytes out_;
};

/// How McapWriter lays the file out.
struct McapLayout {
  bool chunked = true;
  std::string compression;  ///< "", "zstd" or "lz4"
  std::size_t messages_per_chunk = 100;
  bool summary = true;  ///< a summary section (schemas, channels, chunk indexes) and footer
  bool crc = true;      ///< the chunks' uncompressed CRC
  /// Chunked: each channel's Schema and Channel records in the chunk of its first message, just
  /// before it (as writers that learn of topics while recording do); else all in the first chunk.
  bool declare_at_first_use = false;
  /// With a summary: a Statistics record, each channel's message count plus `count_error` (a
  /// writer's mistake, for the tests of counts taken as a hint).
  bool statistics = false;
  std::int64_t count_error = 0;
};

inline std::uint32_t test_crc32(const Bytes& b) {
  std::uint32_t c = 0xFFFFFFFFU;
  for (std::uint8_t x : b) {
    c ^= x;
    for (int k = 0; k < 8; ++k) c = (c & 1U) ? 0xEDB88320U ^ (c >> 1) : c >> 1;
  }
  return ~c;
}

class McapWriter {
 public:
  explicit McapWriter(McapLayout layout = {}) : layout_(std::move(layout)) {}

  std::uint16_t schema(std::string name, std::string text, std::string encoding = "ros2msg") {
    Bytes r;
    const auto id = static_cast<std::uint16_t>(schemas_.size() + 1);
    u16(r, id);
    str(r, name);
    str(r, encoding);
    str(r, text);
    schemas_.push_back(record(0x03, r));
    return id;
  }
  std::uint16_t channel(std::uint16_t schema_id, std::string topic, std::string encoding = "cdr") {
    Bytes r;
    const auto id = static_cast<std::uint16_t>(channels_.size() + 1);
    u16(r, id);
    u16(r, schema_id);
    str(r, topic);
    str(r, encoding);
    u32(r, 0);  // metadata: an empty map
    channels_.push_back(record(0x04, r));
    channel_schema_.push_back(schema_id);
    return id;
  }
  void message(std::uint16_t channel, std::uint64_t log_time_ns, const Bytes& data) {
    Bytes r;
    u16(r, channel);
    u32(r, static_cast<std::uint32_t>(messages_.size()));
    u64(r, log_time_ns);
    u64(r, log_time_ns);
    r.insert(r.end(), data.begin(), data.end());
    messages_.push_back({channel, log_time_ns, record(0x05, r)});
  }

  Bytes finish() const {
    Bytes f = {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};
    Bytes h;
    str(h, "ros2");
    str(h, "dynpos-test");
    append(f, record(0x01, h));
    std::vector<Bytes> indexes;
    if (!layout_.chunked) {
      for (const Bytes& s : schemas_) append(f, s);
      for (const Bytes& c : channels_) append(f, c);
      for (const Message& m : messages_) append(f, m.record);
    } else {
      for (std::size_t first = 0; first < messages_.size() || first == 0;
           first += layout_.messages_per_chunk) {
        indexes.push_back(write_chunk(f, first));
        if (first + layout_.messages_per_chunk >= messages_.size()) break;
      }
    }
    Bytes end;
    u32(end, 0);
    append(f, record(0x0F, end));
    std::uint64_t summary_start = 0;
    if (layout_.summary) {
      summary_start = f.size();
      for (const Bytes& s : schemas_) append(f, s);
      for (const Bytes& c : channels_) append(f, c);
      for (const Bytes& i : indexes) append(f, i);
      if (layout_.statistics) append(f, statistics());
    }
    Bytes footer;
    u64(footer, summary_start);
    u64(footer, 0);
    u32(footer, 0);
    append(f, record(0x02, footer));
    append(f, Bytes{0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'});
    return f;
  }

  void write(const std::filesystem::path& path) const {
    const Bytes b = finish();
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
  }

  static Bytes record(std::uint8_t op, const Bytes& content) {
    Bytes r;
    r.reserve(9 + content.size());
    r.push_back(op);
    u64(r, content.size());
    append(r, content);
    return r;
  }
  static void u16(Bytes& b, std::uint16_t v) { put(b, v); }
  static void u32(Bytes& b, std::uint32_t v) { put(b, v); }
  static void u64(Bytes& b, std::uint64_t v) { put(b, v); }
  static void str(Bytes& b, std::string_view s) {
    u32(b, static_cast<std::uint32_t>(s.size()));
    b.insert(b.end(), s.begin(), s.end());
  }
  static void append(Bytes& b, const Bytes& more) { b.insert(b.end(), more.begin(), more.end()); }

 private:
  struct Message {
    std::uint16_t channel;
    std::uint64_t time;
    Bytes record;
  };
  template <class T>
  static void put(Bytes& b, T v) {
    std::uint8_t x[sizeof(T)];
    std::memcpy(x, &v, sizeof(T));
    b.insert(b.end(), x, x + sizeof(T));
  }

  Bytes compress(const Bytes& plain) const {
    if (layout_.compression.empty()) return plain;
    Bytes out;
    if (layout_.compression == "zstd") {
      out.resize(ZSTD_compressBound(plain.size()));
      out.resize(ZSTD_compress(out.data(), out.size(), plain.data(), plain.size(), 3));
    } else {
      out.resize(LZ4F_compressFrameBound(plain.size(), nullptr));
      out.resize(LZ4F_compressFrame(out.data(), out.size(), plain.data(), plain.size(), nullptr));
    }
    return out;
  }

  // Writes the chunk of the messages from `first` (with every schema and channel in the first
  // chunk); returns its ChunkIndex record.
  Bytes write_chunk(Bytes& f, std::size_t first) const {
    Bytes plain;
    if (first == 0 && !layout_.declare_at_first_use) {
      for (const Bytes& s : schemas_) append(plain, s);
      for (const Bytes& c : channels_) append(plain, c);
    }
    std::map<std::uint16_t, std::uint64_t> channels;
    std::uint64_t t0 = ~std::uint64_t{0}, t1 = 0;
    const std::size_t last = std::min(messages_.size(), first + layout_.messages_per_chunk);
    for (std::size_t i = first; i < last; ++i) {
      if (layout_.declare_at_first_use) declare(plain, messages_[i].channel, i);
      append(plain, messages_[i].record);
      channels[messages_[i].channel] = 0;
      t0 = std::min(t0, messages_[i].time);
      t1 = std::max(t1, messages_[i].time);
    }
    const Bytes packed = compress(plain);
    Bytes c;
    u64(c, t0);
    u64(c, t1);
    u64(c, plain.size());
    u32(c, layout_.crc ? test_crc32(plain) : 0);
    str(c, layout_.compression);
    u64(c, packed.size());
    append(c, packed);
    const Bytes chunk = record(0x06, c);
    const std::uint64_t start = f.size();
    append(f, chunk);
    Bytes i;
    u64(i, t0);
    u64(i, t1);
    u64(i, start);
    u64(i, chunk.size());
    u32(i, static_cast<std::uint32_t>(channels.size() * 10));
    for (const auto& [id, offset] : channels) {
      u16(i, id);
      u64(i, offset);
    }
    u64(i, 0);
    str(i, layout_.compression);
    u64(i, packed.size());
    u64(i, plain.size());
    return record(0x08, i);
  }

  // The Statistics record: counts of messages, schemas, channels, …, then per channel.
  Bytes statistics() const {
    std::map<std::uint16_t, std::uint64_t> counts;
    for (const Message& m : messages_) ++counts[m.channel];
    Bytes r;
    u64(r, messages_.size());
    u16(r, static_cast<std::uint16_t>(schemas_.size()));
    u32(r, static_cast<std::uint32_t>(channels_.size()));
    u32(r, 0);  // attachments
    u32(r, 0);  // metadata
    u32(r, 0);  // chunks (not read)
    u64(r, messages_.empty() ? 0 : messages_.front().time);
    u64(r, messages_.empty() ? 0 : messages_.back().time);
    u32(r, static_cast<std::uint32_t>(counts.size() * 10));
    for (const auto& [channel, n] : counts) {
      u16(r, channel);
      u64(r, static_cast<std::uint64_t>(static_cast<std::int64_t>(n) + layout_.count_error));
    }
    return record(0x0B, r);
  }

  // The Schema and Channel records of `channel` when message i is its first (the schema only
  // when no message before i has a channel of that schema).
  void declare(Bytes& plain, std::uint16_t channel, std::size_t i) const {
    const auto before = [&](auto same) {
      return std::any_of(messages_.begin(), messages_.begin() + static_cast<std::ptrdiff_t>(i),
                         same);
    };
    if (before([&](const Message& m) { return m.channel == channel; })) return;
    const std::uint16_t schema = channel_schema_[channel - 1u];
    if (!before([&](const Message& m) { return channel_schema_[m.channel - 1u] == schema; })) {
      append(plain, schemas_[schema - 1u]);
    }
    append(plain, channels_[channel - 1u]);
  }

  McapLayout layout_;
  std::vector<Bytes> schemas_;
  std::vector<Bytes> channels_;
  std::vector<std::uint16_t> channel_schema_;  // by channel id - 1
  std::vector<Message> messages_;
};

/// ros2msg schema texts of the tests' message types (written for these tests).
inline constexpr std::string_view kFloat64Msg = "float64 data\n";
inline constexpr std::string_view kHeaderDeps =
    "================================================================================\n"
    "MSG: std_msgs/Header\n"
    "builtin_interfaces/Time stamp\n"
    "string frame_id\n"
    "================================================================================\n"
    "MSG: builtin_interfaces/Time\n"
    "int32 sec\n"
    "uint32 nanosec\n";

}  // namespace dynpos::io::testing
