#include "dynpos/io/bag_log.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

#include <fmt/format.h>

#include "bag_topics.hpp"
#include "dynpos/io/cdr_decoder.hpp"
#include "dynpos/io/mcap_reader.hpp"

namespace dynpos::io {
namespace {

using detail::BagTopics;

// Reads the bag's messages into `topics`, with a decoder per channel made at its first message.
class BagRead {
 public:
  BagRead(McapReader& reader, BagTopics& topics, BagTime time, const Ros2MsgSet& msgs)
      : reader_(reader), topics_(topics), time_(time), msgs_(msgs) {}

  void run() {
    reader_.read_messages([this](const McapChannel& c) { return topics_.contains(c.topic); },
                          [this](const McapMessage& m) { message(m); });
  }

 private:
  // Where a channel's messages go, found at its first message.
  struct Route {
    const McapChannel* channel = nullptr;
    detail::BagTopic* topic = nullptr;
    bool header = false;
  };

  void message(const McapMessage& m) {
    if (m.channel_id >= routes_.size()) routes_.resize(std::size_t{m.channel_id} + 1);
    Route& route = routes_[m.channel_id];
    if (route.topic == nullptr) {
      const McapChannel& channel = reader_.channels().at(m.channel_id);
      detail::BagTopic& topic = topics_.at(channel.topic);
      if (!topic.decoders.contains(m.channel_id)) add_decoder(topic, channel, m);
      route = {&channel, &topic, topic.header_time.at(m.channel_id)};
    }
    const McapChannel& channel = *route.channel;
    detail::BagTopic& topic = *route.topic;
    if (m.log_time_ns > static_cast<std::uint64_t>(INT64_MAX) && !route.header) {
      throw reader_.error(m.position(),
                          fmt::format("the log time {} ns is past 2262", m.log_time_ns),
                          channel.topic);
    }
    try {
      detail::add_bag_message(topic, m.channel_id, m.data,
                              static_cast<std::int64_t>(std::min<std::uint64_t>(
                                  m.log_time_ns, static_cast<std::uint64_t>(INT64_MAX))));
    } catch (const CdrError& e) {
      throw reader_.error(m.position(),
                          fmt::format("the message: {} (byte {} of it)", e.what(), e.offset),
                          channel.topic, "the message does not match its schema");
    }
  }

  void add_decoder(detail::BagTopic& topic, const McapChannel& channel, const McapMessage& m) {
    const auto schema = reader_.schemas().find(channel.schema_id);
    const std::string encoding = schema == reader_.schemas().end() ? "" : schema->second.encoding;
    if (encoding != "ros2msg" || channel.message_encoding != "cdr") {
      throw reader_.error(
          m.position(),
          fmt::format("the topic's schema encoding is '{}' and its message encoding '{}'", encoding,
                      channel.message_encoding),
          channel.topic, "dynpos reads ROS 2 bags: ros2msg schemas with cdr messages");
    }
    try {
      Ros2Schema parsed =
          Ros2Schema::parse(schema->second.name, schema->second.data, msgs_.lookup());
      const bool header = detail::uses_header_stamp(parsed, time_);
      if (time_ == BagTime::kHeader && !header) {
        throw reader_.error(m.position(),
                            fmt::format("{} has no header.stamp", schema->second.name),
                            channel.topic, "read its receive time with --bag-time auto or receive");
      }
      detail::add_bag_decoder(topic, m.channel_id, std::move(parsed), header);
    } catch (const Ros2MsgError& e) {
      throw reader_.error(
          m.position(),
          fmt::format("{} (the first message of type {})", e.what(), schema->second.name),
          channel.topic, std::string(detail::kBagColumnHint));
    }
  }

  McapReader& reader_;
  BagTopics& topics_;
  BagTime time_;
  const Ros2MsgSet& msgs_;
  std::vector<Route> routes_;  // by channel id
};

std::vector<std::string> topic_names(const McapReader& reader) {
  std::vector<std::string> names;
  for (const auto& [id, c] : reader.channels()) {
    if (std::find(names.begin(), names.end(), c.topic) == names.end()) names.push_back(c.topic);
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

FileLog read_bag_file(const std::filesystem::path& path, const ColumnMap& map, BagTime time,
                      unsigned jobs, const Ros2MsgSet& msgs) {
  const std::string file = path.string();
  BagTopics topics = detail::plan_bag_topics(map, file);
  McapReader reader(path, jobs);
  const std::string axis = detail::bag_axis_topic(map, topics, topic_names(reader), file);
  BagRead(reader, topics, time, msgs).run();
  detail::check_bag_read(file, topic_names(reader), topics);
  return detail::bag_file_log(file, topics, axis, "mcap");
}

}  // namespace dynpos::io
