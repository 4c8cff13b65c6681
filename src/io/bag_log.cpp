#include "dynpos/io/bag_log.hpp"

#include <algorithm>
#include <cstdint>
#include <exception>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "bag_topics.hpp"
#include "dynpos/io/cdr_decoder.hpp"
#include "dynpos/io/mcap_reader.hpp"

namespace dynpos::io {
namespace {

using detail::BagTopics;

// Reads the bag's messages into `topics`, with a decoder per channel made at its first message
// (on the calling thread, in file order); the later messages of chunks are decoded ahead, on the
// chunk's thread, into rows per topic (ChunkRows) that the calling thread appends in file order.
class BagRead {
 public:
  BagRead(McapReader& reader, BagTopics& topics, BagTime time, const Ros2MsgSet& msgs)
      : reader_(reader), time_(time), msgs_(msgs) {
    for (auto& [name, topic] : topics) topics_.emplace_back(name, &topic);
  }

  void run() {
    reader_.read_messages([this](const McapChannel& c) { return find_topic(c.topic) != nullptr; },
                          [this](const McapMessage& m) { message(m); },
                          [this] { return std::make_unique<ChunkRows>(*this); });
  }

 private:
  // Where a channel's messages go, found at its first message.
  struct Route {
    const McapChannel* channel = nullptr;
    std::size_t topic = 0;  // in topics_
    const detail::BagSource* source = nullptr;
  };

  // A chunk's messages decoded ahead by the routes known as it was queued, into rows by topic.
  class ChunkRows final : public McapChunkWork {
   public:
    explicit ChunkRows(const BagRead& read) : read_(read) {
      for (const auto& topic : read.topics_) rows_.emplace_back(topic.second->roles.size());
    }
    void prepare() override {
      ahead_.assign(read_.routes_.size(), {});
      for (std::size_t c = 0; c < ahead_.size(); ++c) {
        const Route& route = read_.routes_[c];
        if (route.source == nullptr) continue;
        ahead_[c] = {route.source, &read_.topics_[route.topic].second->roles, &rows_[route.topic]};
      }
    }
    bool take(const McapMessage& m) override {
      if (m.channel_id >= ahead_.size() || ahead_[m.channel_id].source == nullptr) return false;
      const Ahead& a = ahead_[m.channel_id];
      if (m.log_time_ns > static_cast<std::uint64_t>(INT64_MAX) && !a.source->header) {
        return false;  // an error, which the calling thread meets again
      }
      try {
        const std::int64_t t_ns =
            detail::decode_bag_row(*a.roles, *a.source, m.data, receive_ns(m), scratch_);
        a.rows->add(t_ns, std::span<const double>(scratch_).first(a.roles->size()));
      } catch (const std::exception&) {
        return false;  // the calling thread decodes it again and meets the same error
      }
      return true;
    }
    void hand_on() override {
      for (std::size_t k = 0; k < rows_.size(); ++k) {
        if (!rows_[k].time_ns.empty()) detail::append_bag_rows(*read_.topics_[k].second, rows_[k]);
      }
    }

   private:
    struct Ahead {
      const detail::BagSource* source = nullptr;
      const std::vector<detail::BagRolePlan>* roles = nullptr;
      detail::BagRows* rows = nullptr;
    };
    const BagRead& read_;
    std::vector<detail::BagRows> rows_;  // by topic
    std::vector<Ahead> ahead_;           // by channel id
    std::vector<double> scratch_;
  };

  static std::int64_t receive_ns(const McapMessage& m) {
    return static_cast<std::int64_t>(
        std::min<std::uint64_t>(m.log_time_ns, static_cast<std::uint64_t>(INT64_MAX)));
  }

  detail::BagTopic* find_topic(const std::string& name) const {
    for (const auto& [topic_name, topic] : topics_) {
      if (topic_name == name) return topic;
    }
    return nullptr;
  }

  void message(const McapMessage& m) {
    if (m.channel_id >= routes_.size()) routes_.resize(std::size_t{m.channel_id} + 1);
    if (routes_[m.channel_id].source == nullptr) add_route(m);
    const Route& route = routes_[m.channel_id];
    if (m.log_time_ns > static_cast<std::uint64_t>(INT64_MAX) && !route.source->header) {
      throw reader_.error(m.position(),
                          fmt::format("the log time {} ns is past 2262", m.log_time_ns),
                          route.channel->topic);
    }
    try {
      detail::add_bag_message(*topics_[route.topic].second, m.channel_id, m.data, receive_ns(m));
    } catch (const CdrError& e) {
      throw reader_.error(m.position(),
                          fmt::format("the message: {} (byte {} of it)", e.what(), e.offset),
                          route.channel->topic, "the message does not match its schema");
    }
  }

  // The messages of `topic` the bag's statistics declare (0 without them).
  std::uint64_t declared_messages(const std::string& topic) const {
    std::uint64_t n = 0;
    for (const auto& [id, count] : reader_.message_counts()) {
      const auto channel = reader_.channels().find(id);
      if (channel != reader_.channels().end() && channel->second.topic == topic) {
        n = count > UINT64_MAX - n ? UINT64_MAX : n + count;
      }
    }
    return n;
  }

  void add_route(const McapMessage& m) {
    const McapChannel& channel = reader_.channels().at(m.channel_id);
    const auto topic = std::find_if(topics_.begin(), topics_.end(),
                                    [&](const auto& t) { return t.first == channel.topic; });
    detail::BagTopic& read = *topic->second;
    const bool first = read.sources.empty();
    if (!read.sources.contains(m.channel_id)) add_decoder(read, channel, m);
    if (first) detail::reserve_bag_rows(read, declared_messages(channel.topic));
    routes_[m.channel_id] = {&channel, static_cast<std::size_t>(topic - topics_.begin()),
                             &read.sources.at(m.channel_id)};
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
  std::vector<std::pair<std::string, detail::BagTopic*>> topics_;  // in the order of BagTopics
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
  return detail::bag_file_log(file, topics, axis, "mcap", jobs);
}

}  // namespace dynpos::io
