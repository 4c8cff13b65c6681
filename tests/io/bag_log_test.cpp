#include "dynpos/io/bag_log.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io_test_util.hpp"
#include "mcap_test_writer.hpp"

namespace dynpos::io {
namespace {

using testing::CdrWriter;
using testing::McapLayout;
using testing::McapWriter;
using testing::TempDir;

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
  ColumnMap map;
  map.set_column("time", "time");
  map.set_column("input", "/a.data");
  map.set_column("output", "/b.data");
  const FileLog log = read_bag_file(path, map, BagTime::kAuto);
  EXPECT_EQ(log.report.topic, "/a");
  EXPECT_EQ(log.log.time(), (std::vector<double>{0.0, 1.0, 2.0, 3.0}));
  EXPECT_EQ(log.log.values("input"), (std::vector<double>{0.0, 10.0, 20.0, 30.0}));
  EXPECT_EQ(log.report.skipped.count("repeated time"), 1u);
  ASSERT_EQ(log.more.size(), 1u);
  EXPECT_EQ(log.more[0].report.topic, "/b");
  EXPECT_EQ(*log.more[0].origin_ns - *log.origin_ns, 500'000'000);
  // The time role names the axis topic.
  map.set_column("time", "/b");
  const FileLog by_b = read_bag_file(path, map, BagTime::kReceive);
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

}  // namespace
}  // namespace dynpos::io
