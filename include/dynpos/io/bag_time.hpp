#pragma once
/// \file
/// BagTime: which time of a bag's message is its time stamp (--bag-time).

#include <cstdint>
#include <optional>
#include <string_view>

namespace dynpos::io {

enum class BagTime : std::uint8_t {
  kAuto,     ///< header.stamp when the message type has a std_msgs/Header `header`, else receive
  kHeader,   ///< header.stamp; a topic whose type has none is an error
  kReceive,  ///< the log (receive) time the recorder wrote
};

/// "auto", "header" or "receive".
std::string_view bag_time_name(BagTime time) noexcept;
std::optional<BagTime> find_bag_time(std::string_view name) noexcept;

}  // namespace dynpos::io
