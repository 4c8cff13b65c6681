#include "dynpos/io/mcap_reader.hpp"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "../source_dir.hpp"
#include "io_test_util.hpp"
#include "mcap_test_writer.hpp"

namespace dynpos::io {
namespace {

using io::testing::caught_input_error;
using io::testing::TempDir;
using testing::Bytes;
using testing::CdrWriter;
using ::testing::HasSubstr;
using testing::McapLayout;
using testing::McapWriter;

McapLayout layout(bool chunked, std::string compression, std::size_t per_chunk, bool summary = true,
                  bool crc = true) {
  return {chunked, std::move(compression), per_chunk, summary, crc};
}

// Two topics: /cmd (Float64) at every step, /speed (Float64) at every other one.
McapWriter two_topics(const McapLayout& layout, int steps = 50) {
  McapWriter w(layout);
  const std::uint16_t s = w.schema("std_msgs/msg/Float64", std::string(testing::kFloat64Msg));
  const std::uint16_t cmd = w.channel(s, "/cmd");
  const std::uint16_t speed = w.channel(s, "/speed");
  for (int k = 0; k < steps; ++k) {
    const std::uint64_t t = 1'700'000'000'000'000'000ULL + 100'000'000ULL * k;
    w.message(cmd, t, CdrWriter().put(1000.0 + k).bytes());
    if (k % 2 == 0) w.message(speed, t, CdrWriter().put(-1.0 * k).bytes());
  }
  return w;
}

std::filesystem::path write_bytes(const TempDir& dir, const std::string& name, const Bytes& b) {
  return dir.write(name, std::string_view(reinterpret_cast<const char*>(b.data()), b.size()));
}

struct Read {
  std::vector<std::string> topics;
  std::vector<double> values;
};

Read read_all(const std::filesystem::path& path, const std::string& only = {}, unsigned jobs = 0) {
  McapReader reader(path, jobs);
  Read out;
  reader.read_messages([&](const McapChannel& c) { return only.empty() || c.topic == only; },
                       [&](const McapMessage& m) {
                         out.topics.push_back(reader.channels().at(m.channel_id).topic);
                         double v = 0;
                         EXPECT_EQ(m.data.size(), 12u);
                         std::memcpy(&v, m.data.data() + 4, 8);
                         out.values.push_back(v);
                       });
  return out;
}

TEST(McapReader, ReadsEveryLayoutAlike) {
  const TempDir dir;
  const std::vector<McapLayout> layouts = {
      layout(false, "", 0, false),
      layout(false, "", 0, true),
      layout(true, "", 7),
      layout(true, "zstd", 10),
      layout(true, "lz4", 1000),
      layout(true, "zstd", 9, false),
      layout(true, "lz4", 4, true, false),
  };
  for (std::size_t i = 0; i < layouts.size(); ++i) {
    const auto path =
        write_bytes(dir, "run" + std::to_string(i) + ".mcap", two_topics(layouts[i]).finish());
    EXPECT_TRUE(looks_like_mcap(path));
    const Read all = read_all(path);
    ASSERT_EQ(all.values.size(), 75u) << i;
    EXPECT_EQ(all.topics[0], "/cmd");
    EXPECT_EQ(all.values[0], 1000.0);
    EXPECT_EQ(all.topics[1], "/speed");
    EXPECT_EQ(all.values.back(), 1049.0);
    const Read speed = read_all(path, "/speed");
    ASSERT_EQ(speed.values.size(), 25u) << i;
    EXPECT_EQ(speed.values[3], -6.0);
  }
}

TEST(McapReader, SkipsChunksWithoutAWantedChannelByTheIndex) {
  const TempDir dir;
  McapWriter w(layout(true, "zstd", 5));
  const std::uint16_t s = w.schema("std_msgs/msg/Float64", std::string(testing::kFloat64Msg));
  const std::uint16_t a = w.channel(s, "/a");
  const std::uint16_t b = w.channel(s, "/b");
  for (int k = 0; k < 10; ++k) w.message(a, k, CdrWriter().put(1.0 * k).bytes());
  for (int k = 0; k < 10; ++k) w.message(b, 100 + k, CdrWriter().put(2.0 * k).bytes());
  Bytes bytes = w.finish();
  // Damage the first chunk's data: a chunk of /a only, never read for /b.
  bytes[74] ^= 0xFF;  // the CRC of the first chunk (after magic, header record, chunk times, size)
  const auto path = write_bytes(dir, "skip.mcap", bytes);
  EXPECT_EQ(read_all(path, "/b").values.size(), 10u);
  EXPECT_TRUE(caught_input_error([&] { read_all(path, "/a"); }));
}

TEST(McapReader, NotMcapIsAnError) {
  const TempDir dir;
  const auto path = dir.write("x.mcap", "time,a\n0,1\n");
  EXPECT_FALSE(looks_like_mcap(path));
  const auto e = caught_input_error([&] { McapReader r(path); });
  ASSERT_TRUE(e);
  EXPECT_THAT(e->what(), HasSubstr("not an MCAP file"));
}

TEST(McapReader, TruncatedChunkNamesItsOffset) {
  const TempDir dir;
  Bytes bytes = two_topics(layout(true, "zstd", 30)).finish();
  bytes.resize(bytes.size() / 2);  // no footer: read linearly, into a cut chunk
  const auto path = write_bytes(dir, "cut.mcap", bytes);
  const auto e = caught_input_error([&] { read_all(path); });
  ASSERT_TRUE(e);
  EXPECT_THAT(e->what(), HasSubstr("cut.mcap"));
  EXPECT_THAT(e->what(), ::testing::MatchesRegex(".*at byte [0-9]+: the record \\(opcode "
                                                 "0x06\\) declares [0-9]+ bytes, only [0-9]+ "
                                                 "are left.*"));
}

TEST(McapReader, BadCrcIsAnError) {
  const TempDir dir;
  Bytes bytes = two_topics(layout(true, "", 20)).finish();
  const double wanted = 1010.0;  // a /cmd value inside the first chunk
  std::uint8_t pattern[8];
  std::memcpy(pattern, &wanted, 8);
  const auto at = std::search(bytes.begin(), bytes.end(), pattern, pattern + 8);
  ASSERT_NE(at, bytes.end());
  at[7] ^= 0x01;
  const auto path = write_bytes(dir, "crc.mcap", bytes);
  const auto e = caught_input_error([&] { read_all(path); });
  ASSERT_TRUE(e);
  EXPECT_THAT(e->what(), HasSubstr("the chunk's CRC is"));
  EXPECT_THAT(e->what(), HasSubstr("crc.mcap"));
}

// A message as handed on: its channel, times, bytes and position.
struct Seen {
  std::uint16_t channel;
  std::uint64_t log_time_ns;
  Bytes data;
  std::string position;
  bool operator==(const Seen&) const = default;
};

std::vector<Seen> every_message(const std::filesystem::path& path, unsigned jobs) {
  McapReader reader(path, jobs);
  std::vector<Seen> out;
  reader.read_messages([](const McapChannel& c) { return c.topic != "/skipped"; },
                       [&](const McapMessage& m) {
                         out.push_back({m.channel_id, m.log_time_ns,
                                        Bytes(m.data.begin(), m.data.end()), m.position()});
                       });
  return out;
}

// The offsets of the file's Chunk records, from its start (records: opcode, u64 length).
std::vector<std::size_t> chunk_offsets(const Bytes& b) {
  std::vector<std::size_t> out;
  for (std::size_t at = 8; at + 9 <= b.size();) {
    std::uint64_t length = 0;
    std::memcpy(&length, b.data() + at + 1, 8);
    if (b[at] == 0x06) out.push_back(at);
    if (b[at] == 0x02) break;
    at += 9 + static_cast<std::size_t>(length);
  }
  return out;
}

// Three topics over many chunks, one of them never wanted.
McapWriter many_chunks(const McapLayout& layout) {
  McapWriter w(layout);
  const std::uint16_t s = w.schema("std_msgs/msg/Float64", std::string(testing::kFloat64Msg));
  const std::uint16_t a = w.channel(s, "/a");
  const std::uint16_t b = w.channel(s, "/b");
  const std::uint16_t skipped = w.channel(s, "/skipped");
  for (int k = 0; k < 2000; ++k) {
    w.message(a, 1000 + 10 * k, CdrWriter().put(0.5 * k).bytes());
    if (k % 3 == 0) w.message(b, 1001 + 10 * k, CdrWriter().put(-1.0 * k).bytes());
    if (k % 7 == 0) w.message(skipped, 1002 + 10 * k, CdrWriter().put(7.0).bytes());
  }
  return w;
}

TEST(McapReader, ThreadsHandOnTheSameMessagesInTheSameOrder) {
  const TempDir dir;
  const std::vector<McapLayout> layouts = {
      layout(true, "zstd", 37),        // through the chunk indexes
      layout(true, "lz4", 50, false),  // read from the start: no summary
      layout(true, "", 101),           // uncompressed chunks
      layout(false, "", 0, false),     // no chunk at all
  };
  for (std::size_t i = 0; i < layouts.size(); ++i) {
    const auto path =
        write_bytes(dir, "many" + std::to_string(i) + ".mcap", many_chunks(layouts[i]).finish());
    const std::vector<Seen> one = every_message(path, 1);
    ASSERT_EQ(one.size(), 2000u + 667u) << i;
    for (const unsigned jobs : {2u, 3u, 8u}) {
      EXPECT_TRUE(every_message(path, jobs) == one) << "layout " << i << ", " << jobs << " jobs";
    }
  }
}

// Takes ahead the messages of its chunk up to one whose value is a multiple of 125 (/a: 0.5 k,
// /b: -k), which it leaves, handed on into `seen` as the calling thread would see them.
class TakeSome final : public McapChunkWork {
 public:
  TakeSome(std::vector<Seen>& seen, std::atomic<int>& taken) : seen_(seen), taken_(taken) {}
  void prepare() override { mine_.clear(); }
  bool take(const McapMessage& m) override {
    double v = 0;
    std::memcpy(&v, m.data.data() + 4, 8);
    if (std::fmod(v, 125.0) == 0.0) return false;
    mine_.push_back(
        {m.channel_id, m.log_time_ns, Bytes(m.data.begin(), m.data.end()), m.position()});
    ++taken_;
    return true;
  }
  void hand_on() override {
    seen_.insert(seen_.end(), mine_.begin(), mine_.end());
    mine_.clear();
  }

 private:
  std::vector<Seen>& seen_;
  std::atomic<int>& taken_;
  std::vector<Seen> mine_;
};

// every_message() with TakeSome taking messages ahead; the number it took.
std::pair<std::vector<Seen>, int> every_message_ahead(const std::filesystem::path& path,
                                                      unsigned jobs) {
  McapReader reader(path, jobs);
  std::vector<Seen> out;
  std::atomic<int> taken = 0;
  reader.read_messages([](const McapChannel& c) { return c.topic != "/skipped"; },
                       [&](const McapMessage& m) {
                         out.push_back({m.channel_id, m.log_time_ns,
                                        Bytes(m.data.begin(), m.data.end()), m.position()});
                       },
                       [&] { return std::make_unique<TakeSome>(out, taken); });
  return {out, taken.load()};
}

// Work taking messages ahead (some of them: a message it leaves goes to the calling thread with
// the rest of its chunk) sees the messages of the calling thread alone, in the same order, with
// the same positions: with chunk indexes, read from the start, with channels declared in the
// chunk of their first message, and without chunks (nothing to take ahead).
TEST(McapReader, WorkAheadSeesEveryMessageOnceInFileOrder) {
  const TempDir dir;
  McapLayout late = layout(true, "zstd", 30, false);
  late.declare_at_first_use = true;
  McapLayout late_indexed = layout(true, "lz4", 45);
  late_indexed.declare_at_first_use = true;
  const std::vector<McapLayout> layouts = {
      layout(true, "zstd", 37),
      layout(true, "lz4", 50, false),
      layout(true, "", 101),
      late,
      late_indexed,
      layout(false, "", 0, false),
  };
  for (std::size_t i = 0; i < layouts.size(); ++i) {
    const auto path =
        write_bytes(dir, "ahead" + std::to_string(i) + ".mcap", many_chunks(layouts[i]).finish());
    const std::vector<Seen> alone = every_message(path, 1);
    ASSERT_EQ(alone.size(), 2000u + 667u) << i;
    for (const unsigned jobs : {1u, 2u, 3u, 8u}) {
      const auto [seen, taken] = every_message_ahead(path, jobs);
      EXPECT_TRUE(seen == alone) << "layout " << i << ", " << jobs << " jobs";
      if (layouts[i].chunked) {
        // All but the first message of each channel, the 14 messages left and the rest of their
        // chunks, and without a summary what the chunks queued before a channel was first seen
        // leave (at most 2 × 8 + 1 chunks).
        EXPECT_GT(taken, 1000) << "layout " << i << ", " << jobs << " jobs";
      } else {
        EXPECT_EQ(taken, 0) << "layout " << i;
      }
    }
  }
}

// The error thrown is the first in file order, whatever thread found it and when.
TEST(McapReader, TheFirstBadChunkInFileOrderIsTheErrorOnAnyNumberOfThreads) {
  const TempDir dir;
  for (const bool summary : {true, false}) {
    Bytes bytes = many_chunks(layout(true, "zstd", 40, summary)).finish();
    const std::vector<std::size_t> chunks = chunk_offsets(bytes);
    ASSERT_GT(chunks.size(), 40u);
    bytes[chunks[9] + 9 + 24] ^= 0x01;   // its CRC
    bytes[chunks[30] + 9 + 50] ^= 0xFF;  // its compressed records
    bytes[chunks[31] + 9 + 24] ^= 0x01;
    const auto path = write_bytes(dir, "bad.mcap", bytes);
    const std::string expected = fmt::format("bad.mcap: at byte {}: the chunk's CRC", chunks[9]);
    for (const unsigned jobs : {1u, 2u, 4u}) {
      for (int run = 0; run < 10; ++run) {
        const auto e = caught_input_error([&] { every_message(path, jobs); });
        ASSERT_TRUE(e);
        ASSERT_THAT(e->what(), HasSubstr(expected)) << jobs << " jobs, run " << run;
      }
    }
    // Bad from the first chunk read ahead on: the chunk at the head, not one behind it.
    bytes[chunks[1] + 9 + 24] ^= 0x01;
    const auto early = write_bytes(dir, "early.mcap", bytes);
    for (const unsigned jobs : {1u, 2u, 4u}) {
      const auto e = caught_input_error([&] { every_message(early, jobs); });
      ASSERT_TRUE(e);
      EXPECT_THAT(e->what(), HasSubstr(fmt::format("at byte {}: the chunk's CRC", chunks[1])));
    }
  }
}

// A fuzz finding: zstd's error for bad data depended on the room the decompressor had left
// from the chunk before, so one thread and several named the same chunk's problem differently.
TEST(McapReader, AChunksErrorDoesNotDependOnTheChunksBeforeIt) {
  const std::string path = std::string(DYNPOS_SOURCE_DIR) +
                           "/fuzz/regressions/mcap_reader/zstd_error_after_a_larger_chunk.mcap";
  const auto alone = caught_input_error([&] { every_message(path, 1); });
  ASSERT_TRUE(alone);
  EXPECT_THAT(alone->what(), HasSubstr("at byte 411: the chunk's zstd data: zstd:"));
  for (const unsigned jobs : {2u, 3u}) {
    const auto threads = caught_input_error([&] { every_message(path, jobs); });
    ASSERT_TRUE(threads);
    EXPECT_EQ(std::string(threads->what()), std::string(alone->what())) << jobs << " jobs";
  }
}

Bytes magic() { return {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'}; }

TEST(McapReader, HugeDeclaredSizesAreErrorsBeforeAnyAllocation) {
  const TempDir dir;
  {  // a record far longer than the file
    Bytes b = magic();
    b.push_back(0x05);
    McapWriter::u64(b, std::uint64_t{1} << 60);
    b.resize(b.size() + 30);
    const auto e = caught_input_error([&] { read_all(write_bytes(dir, "rec.mcap", b)); });
    ASSERT_TRUE(e);
    EXPECT_THAT(e->what(), HasSubstr("rec.mcap: at byte 8: the record (opcode 0x05) declares "
                                     "1152921504606846976 bytes, only 30 are left"));
  }
  {  // a chunk of 1 TiB uncompressed
    Bytes c;
    McapWriter::u64(c, 0);
    McapWriter::u64(c, 0);
    McapWriter::u64(c, std::uint64_t{1} << 40);
    McapWriter::u32(c, 0);
    McapWriter::str(c, "zstd");
    McapWriter::u64(c, 4);
    McapWriter::u32(c, 0);
    Bytes b = magic();
    McapWriter::append(b, McapWriter::record(0x06, c));
    const auto e = caught_input_error([&] { read_all(write_bytes(dir, "big.mcap", b)); });
    ASSERT_TRUE(e);
    EXPECT_THAT(e->what(), HasSubstr("at byte 8: a chunk declares 1099511627776 uncompressed "
                                     "bytes, more than the"));
  }
  {  // a chunk whose records length runs past the record; a schema name of 2 GiB
    Bytes c;
    McapWriter::u64(c, 0);
    McapWriter::u64(c, 0);
    McapWriter::u64(c, 10);
    McapWriter::u32(c, 0);
    McapWriter::str(c, "");
    McapWriter::u64(c, std::uint64_t{1} << 50);
    Bytes b = magic();
    McapWriter::append(b, McapWriter::record(0x06, c));
    Bytes s;
    McapWriter::u16(s, 1);
    McapWriter::u32(s, 0x80000000U);
    McapWriter::append(b, McapWriter::record(0x03, s));
    const auto e = caught_input_error([&] { read_all(write_bytes(dir, "len.mcap", b)); });
    ASSERT_TRUE(e);
    EXPECT_THAT(e->what(), HasSubstr("the chunk's records needs 1125899906842624 bytes"));
    b.erase(b.begin() + 8, b.begin() + 8 + 9 + static_cast<std::ptrdiff_t>(c.size()));
    const auto s_error = caught_input_error([&] { read_all(write_bytes(dir, "name.mcap", b)); });
    ASSERT_TRUE(s_error);
    EXPECT_THAT(s_error->what(), HasSubstr("the schema name needs 2147483648 bytes, only 0"));
  }
}

TEST(McapReader, BadCompressedDataIsAnError) {
  const TempDir dir;
  for (const char* compression : {"zstd", "lz4", "brotli"}) {
    Bytes c;
    McapWriter::u64(c, 0);
    McapWriter::u64(c, 0);
    McapWriter::u64(c, 100'000'000);
    McapWriter::u32(c, 0);
    McapWriter::str(c, compression);
    McapWriter::u64(c, 16);
    c.resize(c.size() + 16, 0x5A);
    Bytes b = magic();
    McapWriter::append(b, McapWriter::record(0x06, c));
    const auto e = caught_input_error([&] { read_all(write_bytes(dir, "z.mcap", b)); });
    ASSERT_TRUE(e) << compression;
    EXPECT_THAT(e->what(), HasSubstr("z.mcap: at byte 8: the chunk's"));
    if (std::string(compression) == "brotli") {
      EXPECT_THAT(e->what(), HasSubstr("unknown compression 'brotli'"));
    }
  }
  // Valid zstd data of another size than declared.
  const std::vector<std::uint8_t> plain(1000, 7);
  Bytes packed(ZSTD_compressBound(plain.size()));
  packed.resize(ZSTD_compress(packed.data(), packed.size(), plain.data(), plain.size(), 1));
  Bytes c;
  McapWriter::u64(c, 0);
  McapWriter::u64(c, 0);
  McapWriter::u64(c, 999);
  McapWriter::u32(c, 0);
  McapWriter::str(c, "zstd");
  McapWriter::u64(c, packed.size());
  McapWriter::append(c, packed);
  Bytes b = magic();
  McapWriter::append(b, McapWriter::record(0x06, c));
  const auto e = caught_input_error([&] { read_all(write_bytes(dir, "n.mcap", b)); });
  ASSERT_TRUE(e);
  EXPECT_THAT(e->what(), HasSubstr("more than the declared 999 bytes"));
}

}  // namespace
}  // namespace dynpos::io
