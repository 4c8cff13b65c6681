#pragma once
/// \file
/// Ros2MsgSet: the definitions of ROS 2 message types that a bag does not carry (rosbag2's
/// SQLite bags before Iron store type names only): a built-in set of common types and the .msg
/// files of folders (--msg-path).
///
/// A type "pkg/Type" (or "pkg/msg/Type") is looked up in each folder in the order given, as
/// DIR/pkg/msg/Type.msg, then DIR/Type.msg; then in the built-in set (builtin_interfaces,
/// std_msgs, geometry_msgs, sensor_msgs, nav_msgs; ros2_builtin_msg_types()). The text is the
/// .msg format of io/ros2_msg.hpp; a type it names is looked up the same way, so custom types
/// may refer to each other and to the built-in ones.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dynpos/io/ros2_msg.hpp"

namespace dynpos::io {

/// The largest .msg file read [bytes]: 1 MiB.
inline constexpr std::uintmax_t kMaxMsgFileBytes = std::uintmax_t{1} << 20;

/// The built-in types, "pkg/Type", sorted.
std::vector<std::string> ros2_builtin_msg_types();

class Ros2MsgSet {
 public:
  Ros2MsgSet() = default;
  /// The built-in set and the .msg files under `folders` (searched first, in order).
  explicit Ros2MsgSet(std::vector<std::filesystem::path> folders);

  /// The .msg text of `type`, or nullopt when no folder has it and it is not built in. Throws
  /// Ros2MsgError for a file that cannot be read or is larger than kMaxMsgFileBytes.
  std::optional<std::string> find(std::string_view type) const;

  /// The schema of `type` (types[0]) with every type it nests, all from this set. Throws
  /// Ros2MsgError for a type it lacks or a bad definition.
  Ros2Schema schema(std::string_view type) const;

  /// This set as the lookup of Ros2Schema::parse (valid while this set lives).
  Ros2MsgLookup lookup() const;

  const std::vector<std::filesystem::path>& folders() const noexcept { return folders_; }

 private:
  std::vector<std::filesystem::path> folders_;
};

}  // namespace dynpos::io
