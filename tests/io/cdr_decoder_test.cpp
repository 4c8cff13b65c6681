#include "dynpos/io/cdr_decoder.hpp"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "mcap_test_writer.hpp"

namespace dynpos::io {
namespace {

using testing::CdrWriter;
using ::testing::HasSubstr;

const std::string kNavSatFix = std::string(
                                   "uint8 COVARIANCE_TYPE_UNKNOWN = 0  # a constant\n"
                                   "std_msgs/Header header\n"
                                   "NavSatStatus status\n"
                                   "float64 latitude\n"
                                   "float64 longitude\n"
                                   "float64 altitude 0.0\n"
                                   "float64[9] position_covariance\n"
                                   "uint8 position_covariance_type\n") +
                               std::string(testing::kHeaderDeps) +
                               "================================================================"
                               "================\n"
                               "MSG: sensor_msgs/NavSatStatus\n"
                               "int8 STATUS_FIX=0\n"
                               "int8 status\n"
                               "uint16 service\n";

std::vector<std::uint8_t> nav_sat_fix(bool big_endian) {
  CdrWriter w(big_endian);
  w.header(1'700'000'000'250'000'000LL, "gps");
  w.put(std::int8_t{2}).put(std::uint16_t{1});
  w.put(63.4).put(10.4).put(42.5);
  for (int i = 0; i < 9; ++i) w.put(0.1 * i);
  w.put(std::uint8_t{2});
  return w.bytes();
}

std::vector<double> decode(const CdrDecoder& d, const std::vector<std::uint8_t>& m, std::size_t n) {
  std::vector<double> v(n);
  d.decode(m, v);
  return v;
}

TEST(CdrDecoder, PicksFieldsOfANestedMessageInBothByteOrders) {
  const Ros2Schema schema = Ros2Schema::parse("sensor_msgs/msg/NavSatFix", kNavSatFix);
  const std::vector<std::string> paths = {
      "latitude",       "header.stamp.sec",       "header.stamp.nanosec",
      "status.service", "position_covariance[8]", "position_covariance_type",
      "latitude",       "status.status"};
  const CdrDecoder d(schema, paths);
  for (const bool big : {false, true}) {
    const std::vector<double> v = decode(d, nav_sat_fix(big), paths.size());
    EXPECT_EQ(v[0], 63.4);
    EXPECT_EQ(v[1], 1'700'000'000.0);
    EXPECT_EQ(v[2], 250'000'000.0);
    EXPECT_EQ(v[3], 1.0);
    EXPECT_EQ(v[4], 0.1 * 8);
    EXPECT_EQ(v[5], 2.0);
    EXPECT_EQ(v[6], 63.4);
    EXPECT_EQ(v[7], 2.0);
  }
  EXPECT_THAT(CdrDecoder::numeric_fields(schema, 100),
              ::testing::ElementsAre("header.stamp.sec", "header.stamp.nanosec", "status.status",
                                     "status.service", "latitude", "longitude", "altitude",
                                     "position_covariance[0]", "position_covariance_type"));
}

// The compiled plan reads what the walk reads: the same values, and for every cut of the
// message (and XCDR2's alignment) the same error at the same offset.
TEST(CdrDecoder, ThePlanEqualsTheWalkOnEveryCutOfAMessage) {
  const Ros2Schema schema = Ros2Schema::parse("sensor_msgs/msg/NavSatFix", kNavSatFix);
  const std::vector<std::string> paths = {"position_covariance[4]", "header.stamp.nanosec",
                                          "altitude", "status.service"};
  const CdrDecoder d(schema, paths);
  for (const bool big : {false, true}) {
    for (const std::uint8_t xcdr2 : {0, 6}) {
      std::vector<std::uint8_t> whole = nav_sat_fix(big);
      whole[1] = static_cast<std::uint8_t>(whole[1] + xcdr2);
      for (std::size_t n = 0; n <= whole.size(); ++n) {
        const std::vector<std::uint8_t> cut(whole.begin(),
                                            whole.begin() + static_cast<std::ptrdiff_t>(n));
        std::vector<double> planned(paths.size()), walked(paths.size());
        std::string plan_error, walk_error;
        try {
          d.decode(cut, planned);
        } catch (const CdrError& e) {
          plan_error = fmt::format("{} at {}", e.what(), e.offset);
        }
        try {
          d.decode_by_walking(cut, walked);
        } catch (const CdrError& e) {
          walk_error = fmt::format("{} at {}", e.what(), e.offset);
        }
        EXPECT_EQ(plan_error, walk_error) << n;
        if (walk_error.empty()) {
          for (std::size_t i = 0; i < paths.size(); ++i) {
            EXPECT_TRUE(planned[i] == walked[i] ||
                        (std::isnan(planned[i]) && std::isnan(walked[i])))
                << n << " " << paths[i];
          }
        }
      }
      if (xcdr2 != 0) continue;  // written aligned for XCDR1: read otherwise as XCDR2
      std::vector<double> v(paths.size());
      d.decode(whole, v);
      EXPECT_EQ(v[0], 0.1 * 4);
      EXPECT_EQ(v[2], 42.5);
    }
  }
}

TEST(CdrDecoder, SequencesAndStrings) {
  const std::string text =
      "string name\n"
      "float32[] values\n"
      "Point[<=3] points\n"
      "string<=8[2] tags\n"
      "bool flag\n"
      "int64 big\n"
      "================\n"
      "MSG: test_msgs/Point\n"
      "float64 x\n"
      "float64 y\n";
  const Ros2Schema schema = Ros2Schema::parse("test_msgs/msg/Thing", text);
  const std::vector<std::string> paths = {"values[1]", "values[5]", "points[1].y", "flag", "big"};
  const CdrDecoder d(schema, paths);
  CdrWriter w;
  w.string("odd").put(std::uint32_t{2}).put(1.5F).put(-2.5F);
  w.put(std::uint32_t{2}).put(1.0).put(2.0).put(3.0).put(4.0);
  w.string("a").string("bcdefg").put(std::uint8_t{1}).put(std::int64_t{-7});
  const std::vector<double> v = decode(d, w.bytes(), paths.size());
  EXPECT_EQ(v[0], -2.5);
  EXPECT_TRUE(std::isnan(v[1]));  // past the sequence's end
  EXPECT_EQ(v[2], 4.0);
  EXPECT_EQ(v[3], 1.0);
  EXPECT_EQ(v[4], -7.0);
}

TEST(CdrDecoder, AnEmptySequenceHasNoPaddingBeforeItsElements) {
  // As rosbag2's serializers write it: the count of an empty float64[] at an offset that is 4
  // mod 8 is followed at once by the next field, not by padding to 8.
  const Ros2Schema schema =
      Ros2Schema::parse("test_msgs/msg/J", "float64[] velocity\nfloat64[] effort\nuint32 n\n");
  for (const std::vector<std::string>& paths :
       {std::vector<std::string>{"effort[0]", "n"}, {"velocity[0]", "effort[0]", "n"}}) {
    const CdrDecoder d(schema, paths);
    CdrWriter w;
    w.put(std::uint32_t{0}).put(std::uint32_t{1}).put(2.5).put(std::uint32_t{7});
    ASSERT_EQ(w.bytes().size(), 4U + 4 + 4 + 8 + 4);
    const std::vector<double> v = decode(d, w.bytes(), paths.size());
    EXPECT_EQ(v[paths.size() - 2], 2.5);
    EXPECT_EQ(v[paths.size() - 1], 7.0);
  }
}

TEST(CdrDecoder, BadPathsNameTheFields) {
  const Ros2Schema schema = Ros2Schema::parse("sensor_msgs/msg/NavSatFix", kNavSatFix);
  const auto error = [&](const std::string& path) {
    try {
      CdrDecoder d(schema, {path});
    } catch (const Ros2MsgError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_THAT(error("lattitude"), HasSubstr("has no field 'lattitude' (its fields: header, "
                                            "status, latitude"));
  EXPECT_THAT(error("header.frame_id"), HasSubstr("is text, not a number"));
  EXPECT_THAT(error("header"), HasSubstr("a message std_msgs/Header, not a number"));
  EXPECT_THAT(error("position_covariance"), HasSubstr("is an array; give an element"));
  EXPECT_THAT(error("position_covariance[9]"), HasSubstr("has at most 9 elements"));
  EXPECT_THAT(error("latitude[0]"), HasSubstr("is not an array"));
}

TEST(CdrDecoder, BadMessagesAreErrorsWithTheirOffset) {
  const Ros2Schema schema = Ros2Schema::parse("test_msgs/msg/S", "float64[] v\nfloat64 x\n");
  const CdrDecoder d(schema, {"x"});
  std::vector<double> v(1);
  CdrWriter huge;
  huge.put(std::uint32_t{0x10000000});
  try {
    d.decode(huge.bytes(), v);
    ADD_FAILURE();
  } catch (const CdrError& e) {
    EXPECT_THAT(e.what(), HasSubstr("declares 268435456 elements, more than the 0 bytes left"));
    EXPECT_EQ(e.offset, 8u);
  }
  std::vector<std::uint8_t> bad = {0x00, 0x02, 0, 0};
  EXPECT_THROW(d.decode(bad, v), CdrError);
  std::vector<std::uint8_t> cut = CdrWriter().put(std::uint32_t{0}).bytes();
  EXPECT_THROW(d.decode(cut, v), CdrError);
}

TEST(Ros2Schema, BadDefinitionsAreErrors) {
  EXPECT_THROW(Ros2Schema::parse("a/B", "c/D d\n"), Ros2MsgError);  // undefined
  EXPECT_THROW(Ros2Schema::parse("a/B", "B b\n"), Ros2MsgError);    // recursive
  EXPECT_THROW(Ros2Schema::parse("a/B", "float64[0] x\n"), Ros2MsgError);
  EXPECT_THROW(Ros2Schema::parse("a/B", "float64\n"), Ros2MsgError);
  // A separator or MSG line last, without a line end (a fuzz finding): no type follows it.
  EXPECT_EQ(Ros2Schema::parse("a/B", "float64 x\n===").types.size(), 1u);
  EXPECT_EQ(Ros2Schema::parse("a/B", "float64 x\n===\nMSG: a/C").types.size(), 1u);
  // Time is known without its definition; an empty message has one byte.
  const Ros2Schema s =
      Ros2Schema::parse("a/msg/B", "builtin_interfaces/Time t\nE e\n===\nMSG: a/E\n");
  ASSERT_EQ(s.types.size(), 3u);
  EXPECT_EQ(s.types[0].min_bytes, 9u);
}

}  // namespace
}  // namespace dynpos::io
