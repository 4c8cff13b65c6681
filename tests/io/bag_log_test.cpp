#include "dynpos/io/bag_log.hpp"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <map>

#include "dynpos/io/mcap_reader.hpp"
#include "io_test_util.hpp"
#include "mcap_test_writer.hpp"

namespace dynpos::io {
namespace {

using testing::CdrWriter;
using testing::McapLayout;
using testing::McapWriter;
using testing::TempDir;

// Roles on topics /a (input) and /b (output), the time axis `time`.
ColumnMap a_and_b(const char* time) {
  ColumnMap map;
  map.set_column("time", time);
  map.set_column("input", "/a.data");
  map.set_column("output", "/b.data");
  return map;
}

TEST(ReadBagFile, OrdersMessagesByTimeAndKeepsARepeatedTimeOnce) {
  const TempDir dir;
  McapWriter w(McapLayout{true, "lz4", 3, true, true});
  const std::uint16_t s = w.schema("std_msgs/msg/Float64", "float64 data\n");
  const std::uint16_t a = w.channel(s, "/a");
  const std::uint16_t b = w.channel(s, "/b");
  for (const int k : {3, 1, 2, 2, 0})
    w.message(a, 1'000'000'000ULL * k, CdrWriter().put(10.0 * k).bytes());
  w.message(b, 500'000'000ULL, CdrWriter().put(-1.0).bytes());
  const auto path = dir / "order.mcap";
  w.write(path);
  const ColumnMap map = a_and_b("time");
  const FileLog log = read_bag_file(path, map, BagTime::kAuto);
  EXPECT_EQ(log.report.topic, "/a");
  EXPECT_EQ(log.log.time(), (std::vector<double>{0.0, 1.0, 2.0, 3.0}));
  EXPECT_EQ(log.log.values("input"), (std::vector<double>{0.0, 10.0, 20.0, 30.0}));
  EXPECT_EQ(log.report.skipped.count("repeated time"), 1u);
  ASSERT_EQ(log.more.size(), 1u);
  EXPECT_EQ(log.more[0].report.topic, "/b");
  EXPECT_EQ(*log.more[0].origin_ns - *log.origin_ns, 500'000'000);
  // The time role names the axis topic.
  const FileLog by_b = read_bag_file(path, a_and_b("/b"), BagTime::kReceive);
  EXPECT_EQ(by_b.report.topic, "/b");
  EXPECT_EQ(by_b.log.size(), 1u);
}

TEST(ReadBagFile, AStampThatIsNotBuiltinTimeIsNotAHeaderStamp) {
  // A fuzz finding: "float64 sec" read as seconds overflowed the nanoseconds.
  const TempDir dir;
  McapWriter w(McapLayout{false, "", 0, false, true});
  const std::uint16_t s =
      w.schema("a/msg/M",
               "H header\nfloat64 v\n===\nMSG: a/H\nS stamp\n===\nMSG: a/S\nfloat64 sec\n"
               "uint32 nanosec\n");
  const std::uint16_t c = w.channel(s, "/m");
  w.message(c, 5, CdrWriter().put(9e18).put(std::uint32_t{1}).put(2.0).bytes());
  const auto path = dir / "stamp.mcap";
  w.write(path);
  ColumnMap map;
  map.set_column("time", "time");
  map.set_column("input", "/m.v");
  const FileLog log = read_bag_file(path, map, BagTime::kAuto);
  EXPECT_EQ(log.report.time_format, "receive time");
  EXPECT_EQ(*log.origin_ns, 5);
}

// Two topics at their own rates over many chunks, /b's messages out of order in places.
McapWriter two_rates(const McapLayout& layout, int bad_message = -1) {
  McapWriter w(layout);
  const std::uint16_t s = w.schema("std_msgs/msg/Float64", "float64 data\n");
  const std::uint16_t a = w.channel(s, "/a");
  const std::uint16_t b = w.channel(s, "/b");
  for (int k = 0; k < 3000; ++k) {
    const std::uint64_t t = 1'700'000'000'000'000'000ULL + 10'000'000ULL * k;
    w.message(a, t, CdrWriter().put(std::sin(0.01 * k)).bytes());
    if (k == bad_message) w.message(b, t, {0x00, 0x01, 0x00, 0x00, 0x01});  // cut short
    if (k % 4 == 0)
      w.message(b, k % 40 == 0 ? t + 45'000'000 : t, CdrWriter().put(1.0 * k).bytes());
  }
  return w;
}

ColumnMap two_rates_map() {
  ColumnMap map;
  map.set_column("time", "time");
  map.set_column("input", "/b.data");
  map.set_column("output", "/a.data");
  return map;
}

TEST(ReadBagFile, ColumnsDoNotDependOnTheThreads) {
  const TempDir dir;
  for (const bool summary : {true, false}) {
    const auto path = dir / "rates.mcap";
    two_rates(McapLayout{true, "zstd", 64, summary, true}).write(path);
    const FileLog one = read_bag_file(path, two_rates_map(), BagTime::kAuto, 1);
    ASSERT_EQ(one.log.size(), 3000u);
    ASSERT_EQ(one.more.size(), 1u);
    EXPECT_EQ(one.more[0].log.size(), 750u);
    for (const unsigned jobs : {2u, 4u}) {
      const FileLog many = read_bag_file(path, two_rates_map(), BagTime::kAuto, jobs);
      EXPECT_EQ(many.log.time(), one.log.time());
      EXPECT_EQ(many.log.values("output"), one.log.values("output"));
      ASSERT_EQ(many.more.size(), 1u);
      EXPECT_EQ(many.more[0].log.time(), one.more[0].log.time());
      EXPECT_EQ(many.more[0].log.values("input"), one.more[0].log.values("input"));
      EXPECT_EQ(*many.more[0].origin_ns, *one.more[0].origin_ns);
    }
  }
}

// The messages per channel of a Statistics record only reserve room: right, too few, far too
// many or none, the columns are the same.
TEST(ReadBagFile, DeclaredMessageCountsAreOnlyAHint) {
  const TempDir dir;
  std::vector<FileLog> logs;
  for (const std::int64_t error : {0, -500, 100000, -1}) {
    McapLayout layout{true, "zstd", 64, true, true};
    layout.statistics = error != -1;
    layout.count_error = error;
    const auto path = dir / "counts.mcap";
    two_rates(layout).write(path);
    if (error == 0) {
      const McapReader reader(path);
      ASSERT_EQ(reader.message_counts().size(), 2u);
      EXPECT_EQ(reader.message_counts().at(1), 3000u);
      EXPECT_EQ(reader.message_counts().at(2), 750u);
    }
    logs.push_back(read_bag_file(path, two_rates_map(), BagTime::kAuto, 2));
  }
  for (std::size_t k = 1; k < logs.size(); ++k) {
    EXPECT_EQ(logs[k].log.time(), logs[0].log.time()) << k;
    EXPECT_EQ(logs[k].log.values("output"), logs[0].log.values("output")) << k;
    ASSERT_EQ(logs[k].more.size(), 1u);
    EXPECT_EQ(logs[k].more[0].log.values("input"), logs[0].more[0].log.values("input")) << k;
  }
  EXPECT_EQ(logs[0].log.size(), 3000u);
}

// Chunks whose time ranges overlap (each holds 40 steps of 10 ms, the next starts 30 steps
// later): the topics' messages are out of time order across chunks, and times repeat in two
// chunks with other values. Read alone and on threads (most messages decoded ahead, on the
// chunk's thread), each topic comes ordered by time, a repeated time keeping the message first
// in the file.
TEST(ReadBagFile, ChunksWhoseTimesOverlapAreOrderedByTimeOnAnyNumberOfThreads) {
  const TempDir dir;
  for (const bool summary : {true, false}) {
    McapWriter w(McapLayout{true, "zstd", 40, summary, true});
    const std::uint16_t s = w.schema("std_msgs/msg/Float64", "float64 data\n");
    const std::uint16_t a = w.channel(s, "/a");
    const std::uint16_t b = w.channel(s, "/b");
    std::map<std::uint64_t, double> first_a;  // time → the value of its first message
    std::map<std::uint64_t, double> first_b;
    std::size_t messages_a = 0;
    for (int c = 0; c < 60; ++c) {
      for (int i = 0; i < 40; ++i) {
        const std::uint64_t t = 1'700'000'000'000'000'000ULL + 10'000'000ULL * (30 * c + i);
        const double v = 1000.0 * c + i;
        const bool on_b = i % 4 == 3;
        w.message(on_b ? b : a, t, CdrWriter().put(v).bytes());
        (on_b ? first_b : first_a).try_emplace(t, v);
        messages_a += on_b ? 0 : 1;
      }
    }
    ASSERT_GT(messages_a, first_a.size() + 100);  // times repeated
    const auto path = dir / "overlap.mcap";
    w.write(path);
    const ColumnMap map = a_and_b("/a");
    const auto expect = [](const FileLog& log, const std::map<std::uint64_t, double>& first,
                           const char* role, const std::string& what) {
      std::vector<double> t;
      std::vector<double> v;
      const std::uint64_t origin = first.begin()->first;
      for (const auto& [ns, value] : first) {
        t.push_back(static_cast<double>(static_cast<std::int64_t>(ns - origin)) * 1e-9);
        v.push_back(value);
      }
      EXPECT_EQ(log.log.time(), t) << what;
      EXPECT_EQ(log.log.values(role), v) << what;
    };
    for (const unsigned jobs : {1u, 2u, 4u}) {
      const std::string what = fmt::format("summary {}, {} jobs", summary, jobs);
      const FileLog log = read_bag_file(path, map, BagTime::kAuto, jobs);
      expect(log, first_a, "input", what);
      EXPECT_EQ(log.report.skipped.count("repeated time"), messages_a - first_a.size()) << what;
      ASSERT_EQ(log.more.size(), 1u);
      expect(log.more[0], first_b, "output", what);
    }
  }
}

// A message that does not match its schema, decoded as its chunk is handed on, comes before a
// damaged chunk after it that a thread may have read long before: the message is the error.
TEST(ReadBagFile, TheFirstBadMessageOrChunkInFileOrderIsTheError) {
  const TempDir dir;
  testing::Bytes bytes = two_rates(McapLayout{true, "zstd", 64, true, true}, 1000).finish();
  std::vector<std::size_t> chunks;
  for (std::size_t at = 8; at + 9 <= bytes.size() && bytes[at] != 0x0F;) {
    std::uint64_t length = 0;
    std::memcpy(&length, bytes.data() + at + 1, 8);
    if (bytes[at] == 0x06) chunks.push_back(at);
    at += 9 + static_cast<std::size_t>(length);
  }
  // Message 1000 of /a and its /b neighbours: in chunk (1000 + 250) / 64 = 19.
  ASSERT_GT(chunks.size(), 30u);
  bytes[chunks[25] + 9 + 24] ^= 0x01;  // a CRC after it
  const auto path = dir / "bad.mcap";
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
  std::string first;
  for (const unsigned jobs : {1u, 2u, 4u}) {
    for (int run = 0; run < 5; ++run) {
      const auto e = testing::caught_input_error(
          [&] { read_bag_file(path, two_rates_map(), BagTime::kAuto, jobs); });
      ASSERT_TRUE(e);
      if (first.empty()) first = e->what();
      EXPECT_EQ(e->what(), first) << jobs << " jobs";
    }
  }
  EXPECT_THAT(first, ::testing::HasSubstr("bad.mcap (/b): at byte "));
  EXPECT_THAT(
      first, ::testing::HasSubstr(fmt::format("of the chunk at byte {}: the message", chunks[19])));
}

}  // namespace
}  // namespace dynpos::io
