#pragma once
/// \file
/// The roles of a column map read from a rosbag2 SQLite bag (a .db3 file or a bag folder,
/// io/db3_reader.hpp), without ROS: as io/bag_log.hpp reads an MCAP bag (TOPIC.FIELD columns,
/// each topic on its own axis, --bag-time), with each message's type defined by the bag's
/// message_definitions table when it holds the type as ros2msg text, else by `msgs` (the
/// built-in set and --msg-path, io/ros2_msg_set.hpp).

#include <filesystem>

#include "dynpos/io/bag_time.hpp"
#include "dynpos/io/column_map.hpp"
#include "dynpos/io/log_file.hpp"
#include "dynpos/io/ros2_msg_set.hpp"

namespace dynpos::io {

/// Reads the roles `map` assigns to columns of the bag `path` (file or folder): only the mapped
/// topics' messages are queried, file by file, in timestamp order. The result is as
/// read_bag_file's, with format "db3". Throws core::InputError naming the file (a folder's
/// .db3 file), the message id and the topic: not an SQLite file or not a bag, a topic the bag
/// lacks, a serialization format other than cdr, a type with no definition, a field its type
/// lacks, a message whose data does not hold its fields.
FileLog read_db3_bag(const std::filesystem::path& path, const ColumnMap& map, BagTime time,
                     const Ros2MsgSet& msgs = {});

}  // namespace dynpos::io
