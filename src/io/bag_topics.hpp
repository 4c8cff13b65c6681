#pragma once
// What every storage of ROS 2 bags shares once its messages are found (MCAP: bag_log.cpp,
// rosbag2 SQLite: db3_log.cpp): the topics the column map reads, a CdrDecoder per source of
// messages (an MCAP channel, a topic of a .db3 file), the time axis, and each topic as a
// FileLog ordered by time.

#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "column_blocks.hpp"
#include "dynpos/io/bag_time.hpp"
#include "dynpos/io/cdr_decoder.hpp"
#include "dynpos/io/column_map.hpp"
#include "dynpos/io/log_file.hpp"

namespace dynpos::io::detail {

inline constexpr std::string_view kBagColumnHint =
    "a column of a bag is TOPIC.FIELD[.FIELD…], e.g. /gps/fix.latitude or "
    "/imu.angular_velocity.z, an array element FIELD[i] (docs/log-format.md, \"ROS 2 bags\")";

// One role read from a topic: its field and how its numbers become SI.
struct BagRolePlan {
  std::string role;
  std::string field;  // the path in the message
  core::Unit unit;
  double scale = 1.0;
  core::Interp interp = core::Interp::kLinear;
  core::InputLocation source;
};

// How the messages of one source (an MCAP channel, a topic of a .db3 file) become rows of
// their topic: the decoder of the roles' fields, then of header.stamp's sec and nanosec when
// `header`. Not changed once made: threads decoding ahead read it.
struct BagSource {
  std::unique_ptr<CdrDecoder> decoder;
  bool header = false;  // the time is the header stamp, else the receive time
};

// Rows of one topic decoded apart from it (a chunk's, ahead of the thread that appends them),
// appended to it in order later.
struct BagRows {
  std::vector<std::int64_t> time_ns;
  std::vector<std::vector<double>> values;  // by role

  explicit BagRows(std::size_t roles = 0) : values(roles) {}
  /// Appends a row (`row`: a value per role, row.size() == values.size()), all or nothing.
  void add(std::int64_t t_ns, std::span<const double> row) {
    if (time_ns.size() == time_ns.capacity()) reserve_more();  // then no push_back throws
    for (std::size_t i = 0; i < row.size(); ++i) values[i].push_back(row[i]);
    time_ns.push_back(t_ns);
  }

 private:
  void reserve_more();
};

// What is read of one topic, and what was read.
struct BagTopic {
  std::vector<BagRolePlan> roles;
  std::map<std::uint64_t, BagSource> sources;  // by source of messages
  ColumnBlocks<std::int64_t> time_ns;
  bool unordered = false;                    // a time not after the one before it was appended
  std::vector<ColumnBlocks<double>> values;  // by role
  std::vector<double> scratch;
};

using BagTopics = std::map<std::string, BagTopic>;

// The topics the roles of `map` read (the `time` role aside), each with its roles. Throws
// core::InputError for a column that names no field of a topic.
BagTopics plan_bag_topics(const ColumnMap& map, const std::string& file);

// The topic `map`'s time role names (added to `topics`, for its times) when it is one of
// `names` (the bag's topics), a mapped topic or looks like a topic; else empty. Throws
// core::InputError when no role is mapped to a field of the bag.
std::string bag_axis_topic(const ColumnMap& map, BagTopics& topics,
                           const std::vector<std::string>& names, const std::string& file);

// Whether the messages' time is their header.stamp: a std_msgs/Header `header` whose `stamp`
// is builtin_interfaces/Time, unless `time` is kReceive.
bool uses_header_stamp(const Ros2Schema& schema, BagTime time);

// Adds the decoder of the messages of `source` of the topic: the roles' fields, then the
// header stamp when `header`. Throws Ros2MsgError for a field the type lacks.
void add_bag_decoder(BagTopic& topic, std::uint64_t source, Ros2Schema schema, bool header);

// Decodes a message of `source` into its time (the header stamp, else `receive_ns`), returned,
// and its roles' values in SI, scratch[0, roles.size()) (scratch sized by the decoder's
// fields). Throws CdrError.
std::int64_t decode_bag_row(const std::vector<BagRolePlan>& roles, const BagSource& source,
                            std::span<const std::uint8_t> data, std::int64_t receive_ns,
                            std::vector<double>& scratch);

// Decodes a message of `source` (its decoder added) and appends its row to the topic. Throws
// CdrError.
void add_bag_message(BagTopic& topic, std::uint64_t source, std::span<const std::uint8_t> data,
                     std::int64_t receive_ns);

// Room for `rows` values in each role's column of the topic (a hint: a bag's declared message
// count), so that they are written once, never copied; the times still go through blocks
// (converted to seconds when taken).
void reserve_bag_rows(BagTopic& topic, std::uint64_t rows);

// Appends `rows` (decoded for the topic) to it and empties them, keeping their room.
void append_bag_rows(BagTopic& topic, BagRows& rows);

// Throws core::InputError unless every topic has a message (`names`: the bag's topics).
void check_bag_read(const std::string& path, const std::vector<std::string>& names,
                    const BagTopics& topics);

// The topics as read: the axis topic (`axis`, else the one with the most messages) with the
// others in FileLog::more, each ordered by time, a repeated time kept once; report format
// `format`. The columns are taken out of `topics` on `jobs` threads (core::parallel_for).
FileLog bag_file_log(const std::string& path, BagTopics& topics, std::string axis,
                     std::string_view format, unsigned jobs);

}  // namespace dynpos::io::detail
