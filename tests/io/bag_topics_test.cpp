#include "bag_topics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "dynpos/io/cdr_decoder.hpp"
#include "dynpos/io/column_map.hpp"
#include "dynpos/io/ros2_msg.hpp"
#include "mcap_test_writer.hpp"

namespace dynpos::io::detail {
namespace {

using testing::CdrWriter;

const std::string kStampedMsg =
    "std_msgs/Header header\nfloat64 heading\nfloat32 speed\nint16 mode\n" +
    std::string(testing::kHeaderDeps);

// Two topics planned as read_bag_file plans them: /a's heading in degrees (to radians) and its
// speed scaled by -2; /b's heading, its time the receive time.
BagTopics planned() {
  ColumnMap map;
  map.set_column("heading", "/a.heading");
  map.set_unit({.role = "heading", .unit = "deg"});
  map.set_column("u", "/a.speed");
  map.set_scale("u", -2.0);
  map.set_column("r", "/b.mode");
  BagTopics topics = plan_bag_topics(map, "t.mcap");
  const Ros2Schema schema = Ros2Schema::parse("a/msg/Stamped", kStampedMsg);
  add_bag_decoder(topics.at("/a"), 1, schema, true);
  add_bag_decoder(topics.at("/b"), 2, schema, false);
  return topics;
}

testing::Bytes message(int k) {
  return CdrWriter()
      .header(1'700'000'000'000'000'000LL + 10'000'000LL * k, "f")
      .put(0.1 * k - 30.0)
      .put(static_cast<float>(std::sin(k)))
      .put(static_cast<std::int16_t>(k % 7 - 3))
      .bytes();
}

std::vector<std::int64_t> times(const ColumnBlocks<std::int64_t>& c) {
  std::vector<std::int64_t> out;
  for (std::size_t k = 0; k < c.size(); ++k) out.push_back(c[k]);
  return out;
}
std::vector<double> values(const ColumnBlocks<double>& c) {
  std::vector<double> out;
  for (std::size_t k = 0; k < c.size(); ++k) out.push_back(c[k]);
  return out;
}

// Rows decoded apart (decode_bag_row into BagRows, as a chunk's thread does) and appended in
// order give the columns that add_bag_message gives message by message, bit for bit, over more
// than a column block.
TEST(BagRows, AppendedGiveTheColumnsOfMessageByMessage) {
  BagTopics serial = planned();
  BagTopics apart = planned();
  std::vector<BagRows> rows;
  for (const char* topic : {"/a", "/b"}) rows.emplace_back(apart.at(topic).roles.size());
  std::vector<double> scratch;
  const std::size_t n = ColumnBlocks<double>::kBlockSize + 1000;
  for (std::size_t k = 0; k < n; ++k) {
    const testing::Bytes m = message(static_cast<int>(k));
    const std::uint64_t source = 1 + k % 2;
    const std::size_t t = k % 2;
    const char* topic = t == 0 ? "/a" : "/b";
    const auto receive_ns = static_cast<std::int64_t>(5 * k);
    add_bag_message(serial.at(topic), source, m, receive_ns);
    const BagTopic& read = apart.at(topic);
    const std::int64_t t_ns =
        decode_bag_row(read.roles, read.sources.at(source), m, receive_ns, scratch);
    rows[t].add(t_ns, std::span<const double>(scratch).first(read.roles.size()));
    if (k % 997 == 0 || k + 1 == n) {  // a chunk's rows handed on
      append_bag_rows(apart.at("/a"), rows[0]);
      append_bag_rows(apart.at("/b"), rows[1]);
      EXPECT_TRUE(rows[0].time_ns.empty() && rows[0].values[0].empty());
    }
  }
  for (const char* topic : {"/a", "/b"}) {
    const BagTopic& s = serial.at(topic);
    const BagTopic& a = apart.at(topic);
    ASSERT_EQ(s.time_ns.size(), n / 2);
    EXPECT_EQ(times(a.time_ns), times(s.time_ns)) << topic;
    ASSERT_EQ(a.values.size(), s.values.size());
    for (std::size_t r = 0; r < s.values.size(); ++r) {
      EXPECT_EQ(values(a.values[r]), values(s.values[r])) << topic << " role " << r;
    }
  }
  // The values as read_bag_file gives them: header stamps, SI, scale; receive times.
  const BagTopic& a = serial.at("/a");
  EXPECT_EQ(a.time_ns[3], 1'700'000'000'000'000'000LL + 10'000'000LL * 6);
  EXPECT_DOUBLE_EQ(a.values[0][3], (0.1 * 6 - 30.0) * M_PI / 180.0);
  EXPECT_DOUBLE_EQ(a.values[1][3], -2.0 * static_cast<double>(static_cast<float>(std::sin(6))));
  EXPECT_EQ(serial.at("/b").time_ns[3], 5 * 7);
  EXPECT_DOUBLE_EQ(serial.at("/b").values[0][3], -3.0 * M_PI / 180.0);  // r: deg/s by default
}

// A message its decoder cannot read adds no row.
TEST(BagRows, AMessageThatDoesNotDecodeAddsNothing) {
  BagTopics topics = planned();
  const BagTopic& read = topics.at("/a");
  std::vector<double> scratch;
  const testing::Bytes whole = message(1);
  ASSERT_GT(whole.size(), 3U);
  const testing::Bytes cut(whole.begin(), whole.end() - 3);
  EXPECT_THROW(decode_bag_row(read.roles, read.sources.at(1), cut, 0, scratch), CdrError);
}

TEST(ColumnBlocks, AppendedSpansEqualValuesPushedOneByOne) {
  ColumnBlocks<std::int64_t> pushed;
  ColumnBlocks<std::int64_t> appended;
  std::vector<std::int64_t> span;
  std::int64_t next = 0;
  for (const std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{5000},
                              ColumnBlocks<std::int64_t>::kBlockSize - 5001,
                              ColumnBlocks<std::int64_t>::kBlockSize + 7, std::size_t{3}}) {
    span.clear();
    for (std::size_t k = 0; k < n; ++k) span.push_back(next++ * 3 - 1);
    for (const std::int64_t v : span) pushed.push_back(v);
    appended.append(span);
  }
  ASSERT_EQ(appended.size(), pushed.size());
  ASSERT_EQ(appended.size(), static_cast<std::size_t>(next));
  EXPECT_EQ(times(appended), times(pushed));
  const auto taken = appended.take<std::int64_t>([](std::int64_t v) { return v; });
  EXPECT_EQ(taken, times(pushed));
  EXPECT_TRUE(appended.empty());
}

// Room reserved by a hint: the values go there first and, when they fill most of it and no more
// came, the column is taken out as that vector; a hint too small spills into blocks, one far
// too large is copied out into a vector of the values' size. The values are the same each way.
TEST(ColumnBlocks, AReservedColumnGivesTheSameValuesWhateverTheHint) {
  const std::size_t n = ColumnBlocks<double>::kBlockSize + 333;
  std::vector<double> expected;
  for (std::size_t k = 0; k < n; ++k) expected.push_back(0.25 * static_cast<double>(k) - 7.0);
  for (const std::size_t hint : {std::size_t{0}, n / 3, n, n + n / 10, 4 * n}) {
    ColumnBlocks<double> c;
    c.reserve(hint);
    c.append(std::span<const double>(expected).first(1000));
    for (std::size_t k = 1000; k < n / 2; ++k) c.push_back(expected[k]);
    c.append(std::span<const double>(expected).subspan(n / 2));
    ASSERT_EQ(c.size(), n) << hint;
    EXPECT_EQ(c[n / 3 - 1], expected[n / 3 - 1]) << hint;
    EXPECT_EQ(c[n / 3], expected[n / 3]) << hint;
    EXPECT_EQ(c[n - 1], expected[n - 1]) << hint;
    const std::vector<double> taken = c.take();
    EXPECT_EQ(taken, expected) << hint;
    EXPECT_LE(taken.capacity(), n + n / 8) << hint;
    EXPECT_TRUE(c.empty());
  }
  ColumnBlocks<double> refused;  // a hint the system cannot hold is none
  refused.reserve(SIZE_MAX / 8);
  refused.push_back(1.5);
  EXPECT_EQ(refused.take(), std::vector<double>{1.5});
}

}  // namespace
}  // namespace dynpos::io::detail
