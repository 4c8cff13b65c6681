#pragma once
/// \file
/// The roles of a column map read from a ROS 2 bag (MCAP with ros2msg schemas and CDR
/// messages), without ROS.
///
/// A role's column is TOPIC.FIELD[.FIELD…], an array element FIELD[i]: "/gps/fix.latitude",
/// "/imu.angular_velocity.z", "/joint_states.position[1]". Each topic is like a file of its
/// own: its messages' times (io/bag_time.hpp) on its own axis, t = 0 at its first message.
/// Numbers are converted to SI as a CSV column without a header unit is (declared unit, else
/// the role's default; scale). Messages are ordered by time; a repeated time keeps the first
/// message and counts the others as skipped "repeated time".

#include <filesystem>

#include "dynpos/io/bag_time.hpp"
#include "dynpos/io/column_map.hpp"
#include "dynpos/io/log_file.hpp"
#include "dynpos/io/ros2_msg_set.hpp"

namespace dynpos::io {

/// Reads the roles `map` assigns to columns of the bag `path`, in one pass over it. The result
/// holds the topic of the `time` role when it names one of the bag's topics, else the mapped
/// topic with the most messages; each other mapped topic is in `more`, on its own axis with
/// its own origin (FileLog::origin_ns: its first time stamp, UTC). Throws core::InputError
/// naming the file, the byte offset and the topic for a bad record or message, a topic the bag
/// lacks (listing its topics), a field its type lacks (listing its fields) and a schema that is
/// not ros2msg or messages that are not CDR. A type a schema names without its definition is
/// taken from `msgs` (io/ros2_msg_set.hpp). Chunks are decompressed on `jobs` threads (0 = every
/// core; McapReader); the result does not depend on it.
FileLog read_bag_file(const std::filesystem::path& path, const ColumnMap& map, BagTime time,
                      unsigned jobs = 0, const Ros2MsgSet& msgs = {});

}  // namespace dynpos::io
