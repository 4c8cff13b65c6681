#include "dynpos/io/db3_log.hpp"

#include <algorithm>
#include <cstdint>

#include <fmt/format.h>

#include "bag_topics.hpp"
#include "dynpos/io/cdr_decoder.hpp"
#include "dynpos/io/db3_reader.hpp"

namespace dynpos::io {
namespace {

using detail::BagTopics;

constexpr std::string_view kMsgPathHint =
    "--msg-path DIR adds it from DIR/PKG/msg/TYPE.msg or DIR/TYPE.msg (docs/log-format.md, "
    "\"ROS 2 bags\")";

// The schema of `topic`'s type: the bag's own ros2msg definition, else the set's.
Ros2Schema topic_schema(const Db3Reader& reader, const Db3Topic& topic, const Ros2MsgSet& msgs) {
  const auto stored = reader.definitions().find(topic.type);
  if (stored != reader.definitions().end() && stored->second.encoding == "ros2msg" &&
      !stored->second.text.empty()) {
    return Ros2Schema::parse(topic.type, stored->second.text, msgs.lookup());
  }
  if (std::optional<std::string> text = msgs.find(topic.type)) {
    return Ros2Schema::parse(topic.type, *text, msgs.lookup());
  }
  const std::string stored_as =
      stored == reader.definitions().end()
          ? std::string()
          : fmt::format(" (the bag holds it as '{}', not ros2msg)", stored->second.encoding);
  throw reader.error(
      {}, fmt::format("no definition of the type {}{}: it is not built in", topic.type, stored_as),
      topic.name, std::string(kMsgPathHint));
}

// Adds the decoder of each mapped topic of the file (source: file << 32 | its index) and
// returns the topics' ids.
std::vector<std::int64_t> add_decoders(const Db3Reader& reader, std::uint64_t file,
                                       BagTopics& topics, BagTime time, const Ros2MsgSet& msgs) {
  std::vector<std::int64_t> ids;
  for (std::size_t k = 0; k < reader.topics().size(); ++k) {
    const Db3Topic& t = reader.topics()[k];
    const auto topic = topics.find(t.name);
    if (topic == topics.end()) continue;
    if (t.serialization_format != "cdr") {
      throw reader.error(
          {}, fmt::format("the topic's serialization format is '{}'", t.serialization_format),
          t.name, "dynpos reads ROS 2 bags of cdr messages");
    }
    try {
      Ros2Schema schema = topic_schema(reader, t, msgs);
      const bool header = detail::uses_header_stamp(schema, time);
      if (time == BagTime::kHeader && !header) {
        throw reader.error({}, fmt::format("{} has no header.stamp", t.type), t.name,
                           "read its receive time with --bag-time auto or receive");
      }
      detail::add_bag_decoder(topic->second, (file << 32) | k, std::move(schema), header);
    } catch (const Ros2MsgError& e) {
      throw reader.error({}, fmt::format("{} (its type {})", e.what(), t.type), t.name,
                         std::string(detail::kBagColumnHint));
    }
    ids.push_back(t.id);
  }
  return ids;
}

// Reads the mapped topics' messages of one file into `topics`.
void read_file(Db3Reader& reader, std::uint64_t file, BagTopics& topics, BagTime time,
               const Ros2MsgSet& msgs) {
  const std::vector<std::int64_t> ids = add_decoders(reader, file, topics, time, msgs);
  std::map<std::int64_t, std::pair<detail::BagTopic*, std::size_t>> by_id;
  for (std::size_t k = 0; k < reader.topics().size(); ++k) {
    const Db3Topic& t = reader.topics()[k];
    const auto topic = topics.find(t.name);
    if (topic != topics.end()) by_id[t.id] = {&topic->second, k};
  }
  reader.read_messages(ids, [&](const Db3Message& m) {
    const auto [topic, k] = by_id.at(m.topic_id);
    try {
      detail::add_bag_message(*topic, (file << 32) | k, m.data, m.timestamp_ns);
    } catch (const CdrError& e) {
      throw reader.error(fmt::format("message id {}", m.id),
                         fmt::format("the message: {} (byte {} of it)", e.what(), e.offset),
                         reader.topics()[k].name, "the message does not match its schema");
    }
  });
}

std::string file_name(const std::filesystem::path& bag, const std::filesystem::path& file) {
  return bag == file ? bag.string() : file.string();
}

}  // namespace

FileLog read_db3_bag(const std::filesystem::path& path, const ColumnMap& map, BagTime time,
                     const Ros2MsgSet& msgs) {
  const std::string name = path.string();
  const std::vector<std::filesystem::path> files = db3_files(path);
  BagTopics topics = detail::plan_bag_topics(map, name);
  std::vector<std::string> names;
  for (const std::filesystem::path& f : files) {
    const Db3Reader reader(f, file_name(path, f));
    for (const Db3Topic& t : reader.topics()) {
      if (std::find(names.begin(), names.end(), t.name) == names.end()) names.push_back(t.name);
    }
  }
  std::sort(names.begin(), names.end());
  const std::string axis = detail::bag_axis_topic(map, topics, names, name);
  for (std::size_t i = 0; i < files.size(); ++i) {
    Db3Reader reader(files[i], file_name(path, files[i]));
    read_file(reader, i, topics, time, msgs);
  }
  detail::check_bag_read(name, names, topics);
  return detail::bag_file_log(name, topics, axis, "db3", 1);
}

}  // namespace dynpos::io
