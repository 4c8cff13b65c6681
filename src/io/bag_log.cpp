#include "dynpos/io/bag_log.hpp"

#include <algorithm>
#include <cassert>
#include <memory>
#include <numeric>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "column_blocks.hpp"
#include "csv_cell.hpp"
#include "dynpos/io/cdr_decoder.hpp"
#include "dynpos/io/mcap_reader.hpp"
#include "dynpos/io/time_stamp.hpp"

namespace dynpos::io {
namespace {

constexpr std::string_view kColumnHint =
    "a column of a bag is TOPIC.FIELD[.FIELD…], e.g. /gps/fix.latitude or "
    "/imu.angular_velocity.z, an array element FIELD[i] (docs/log-format.md, \"ROS 2 bags\")";

// One role read from a topic: its field and how its numbers become SI.
struct RolePlan {
  std::string role;
  std::string field;  // the path in the message
  core::Unit unit;
  double scale = 1.0;
  core::Interp interp = core::Interp::kLinear;
  core::InputLocation source;
};

// What is read of one topic, and what was read.
struct TopicRead {
  std::vector<RolePlan> roles;
  std::map<std::uint16_t, std::unique_ptr<CdrDecoder>> decoders;  // by channel
  std::map<std::uint16_t, bool> header_time;                      // by channel
  detail::ColumnBlocks<std::int64_t> time_ns;
  std::vector<detail::ColumnBlocks<double>> values;  // by role
  std::vector<double> scratch;
};

RolePlan plan_role(const std::string& role, const RoleColumn& entry, std::string field) {
  const std::optional<RoleSpec> spec = find_role(role);
  assert(spec && "ColumnMap only holds known roles");
  RolePlan plan{role, std::move(field), {}, entry.scale, spec->interp, entry.source};
  if (entry.unit) {
    plan.unit = unit_for_role(*spec, *entry.unit, entry.source);
  } else {
    plan.unit = *core::find_unit(spec->default_unit);
  }
  return plan;
}

// The topics the roles of `map` read (the `time` role aside), each with its roles.
std::map<std::string, TopicRead> plan_topics(const ColumnMap& map, const std::string& file) {
  std::map<std::string, TopicRead> topics;
  for (const auto& [role, entry] : map.roles()) {
    if (role == "time" || role == "time.sec" || role == "time.nsec") continue;
    const std::string& column = entry.column;
    const auto dot = column.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == column.size()) {
      core::InputLocation where = entry.source;
      if (where.file.empty()) where.file = file;
      throw core::InputError(where,
                             fmt::format("role '{}': '{}' names no field of a topic", role, column),
                             std::string(kColumnHint));
    }
    topics[column.substr(0, dot)].roles.push_back(plan_role(role, entry, column.substr(dot + 1)));
  }
  return topics;
}

bool has_header_stamp(const Ros2Schema& schema) {
  const auto nested = [&](std::size_t type, std::string_view name) -> std::optional<std::size_t> {
    for (const Ros2Field& f : schema.types[type].fields) {
      if (f.name == name && !f.primitive && f.array == Ros2Field::Array::kNone) return f.nested;
    }
    return std::nullopt;
  };
  const auto header = nested(0, "header");
  const auto stamp = header ? nested(*header, "stamp") : std::nullopt;
  if (!stamp) return false;
  // builtin_interfaces/Time: int32 sec (uint32 in older definitions), uint32 nanosec.
  const auto& f = schema.types[*stamp].fields;
  const auto is = [](const Ros2Field& field, std::string_view name, Ros2Primitive type) {
    return field.name == name && field.primitive == type && field.array == Ros2Field::Array::kNone;
  };
  return f.size() == 2 &&
         (is(f[0], "sec", Ros2Primitive::kInt32) || is(f[0], "sec", Ros2Primitive::kUint32)) &&
         is(f[1], "nanosec", Ros2Primitive::kUint32);
}

// Reads the bag's messages into `topics`, with a decoder per channel made at its first message.
class BagRead {
 public:
  BagRead(McapReader& reader, std::map<std::string, TopicRead>& topics, BagTime time)
      : reader_(reader), topics_(topics), time_(time) {}

  void run() {
    reader_.read_messages([this](const McapChannel& c) { return topics_.contains(c.topic); },
                          [this](const McapMessage& m) { message(m); });
  }

 private:
  // Where a channel's messages go, found once.
  struct Route {
    const McapChannel* channel = nullptr;
    TopicRead* topic = nullptr;
    const CdrDecoder* decoder = nullptr;
    bool header = false;
  };

  void message(const McapMessage& m) {
    if (m.channel_id >= routes_.size()) routes_.resize(std::size_t{m.channel_id} + 1);
    Route& route = routes_[m.channel_id];
    if (route.decoder == nullptr) {
      const McapChannel& channel = reader_.channels().at(m.channel_id);
      TopicRead& topic = topics_.at(channel.topic);
      auto decoder = topic.decoders.find(m.channel_id);
      if (decoder == topic.decoders.end()) decoder = add_decoder(topic, channel, m);
      route = {&channel, &topic, decoder->second.get(), topic.header_time.at(m.channel_id)};
    }
    TopicRead& topic = *route.topic;
    std::vector<double>& v = topic.scratch;
    try {
      route.decoder->decode(m.data, v);
    } catch (const CdrError& e) {
      throw reader_.error(m.position(),
                          fmt::format("the message: {} (byte {} of it)", e.what(), e.offset),
                          route.channel->topic, "the message does not match its schema");
    }
    std::int64_t ns = 0;
    if (route.header) {
      const std::size_t n = topic.roles.size();
      ns = static_cast<std::int64_t>(v[n]) * 1'000'000'000 + static_cast<std::int64_t>(v[n + 1]);
    } else if (m.log_time_ns <= static_cast<std::uint64_t>(INT64_MAX)) {
      ns = static_cast<std::int64_t>(m.log_time_ns);
    } else {
      throw reader_.error(m.position(),
                          fmt::format("the log time {} ns is past 2262", m.log_time_ns),
                          route.channel->topic);
    }
    topic.time_ns.push_back(ns);
    for (std::size_t i = 0; i < topic.roles.size(); ++i) {
      const RolePlan& plan = topic.roles[i];
      topic.values[i].push_back(detail::to_si(plan.unit, v[i] * plan.scale));
    }
  }

  using Decoders = std::map<std::uint16_t, std::unique_ptr<CdrDecoder>>;
  Decoders::iterator add_decoder(TopicRead& topic, const McapChannel& channel,
                                 const McapMessage& m) {
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
      Ros2Schema parsed = Ros2Schema::parse(schema->second.name, schema->second.data);
      const bool header = time_ != BagTime::kReceive && has_header_stamp(parsed);
      if (time_ == BagTime::kHeader && !header) {
        throw reader_.error(m.position(),
                            fmt::format("{} has no header.stamp", schema->second.name),
                            channel.topic, "read its receive time with --bag-time auto or receive");
      }
      std::vector<std::string> paths;
      for (const RolePlan& r : topic.roles) paths.push_back(r.field);
      if (header) {
        paths.emplace_back("header.stamp.sec");
        paths.emplace_back("header.stamp.nanosec");
      }
      topic.header_time[m.channel_id] = header;
      topic.scratch.resize(paths.size());
      topic.values.resize(topic.roles.size());
      return topic.decoders
          .emplace(m.channel_id, std::make_unique<CdrDecoder>(std::move(parsed), paths))
          .first;
    } catch (const Ros2MsgError& e) {
      throw reader_.error(
          m.position(),
          fmt::format("{} (the first message of type {})", e.what(), schema->second.name),
          channel.topic, std::string(kColumnHint));
    }
  }

  McapReader& reader_;
  std::map<std::string, TopicRead>& topics_;
  BagTime time_;
  std::vector<Route> routes_;  // by channel id
};

// The indices of the topic's messages in time order, a repeated time kept once; empty when
// they are in strictly increasing order already (the usual case: no copy then).
std::vector<std::size_t> time_order(const detail::ColumnBlocks<std::int64_t>& time_ns) {
  bool increasing = true;
  for (std::size_t k = 1; k < time_ns.size() && increasing; ++k) {
    increasing = time_ns[k - 1] < time_ns[k];
  }
  if (increasing) return {};
  std::vector<std::size_t> order(time_ns.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return time_ns[a] < time_ns[b]; });
  const auto repeated = std::unique(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return time_ns[a] == time_ns[b];
  });
  order.erase(repeated, order.end());
  return order;
}

// The topic's messages as a FileLog: ordered by time, repeated times dropped.
FileLog topic_log(const std::string& path, const std::string& topic, TopicRead& read) {
  const std::size_t messages = read.time_ns.size();
  const std::vector<std::size_t> order = time_order(read.time_ns);
  const std::size_t n = order.empty() ? messages : order.size();
  const auto at = [&](std::size_t k) { return order.empty() ? k : order[k]; };
  const std::int64_t origin = read.time_ns[at(0)];
  const auto seconds = [origin](std::int64_t ns) {
    return static_cast<double>(ns - origin) * 1e-9;
  };
  std::vector<double> t;
  if (order.empty()) {
    t = read.time_ns.take<double>(seconds);
  } else {
    t.resize(n);
    for (std::size_t k = 0; k < n; ++k) t[k] = seconds(read.time_ns[order[k]]);
    read.time_ns.clear();
  }
  FileLog out;
  out.log = core::Log(std::move(t));
  for (std::size_t r = 0; r < read.roles.size(); ++r) {
    std::vector<double> v;
    if (order.empty()) {
      v = read.values[r].take<double>([](double x) { return x; });
    } else {
      v.resize(n);
      for (std::size_t k = 0; k < n; ++k) v[k] = read.values[r][order[k]];
      read.values[r].clear();
    }
    const RolePlan& plan = read.roles[r];
    out.log.add_channel(plan.role, core::si_unit(plan.unit.quantity).symbol, std::move(v),
                        plan.interp);
  }
  out.report.path = path;
  out.report.topic = topic;
  out.report.format = "mcap";
  const bool header = std::any_of(read.header_time.begin(), read.header_time.end(),
                                  [](const auto& c) { return c.second; });
  out.report.time_format = header ? "header.stamp" : "receive time";
  out.report.records = n;
  if (n < messages) out.report.skipped.add("repeated time", messages - n);
  out.origin_ns = origin;
  out.origin = format_iso8601(origin, 0);
  out.origin_zone = "UTC";
  out.first_row_s = out.log.time().front();
  out.last_row_read_s = out.log.time().back();
  return out;
}

std::vector<std::string> topic_names(const McapReader& reader) {
  std::vector<std::string> names;
  for (const auto& [id, c] : reader.channels()) {
    if (std::find(names.begin(), names.end(), c.topic) == names.end()) names.push_back(c.topic);
  }
  std::sort(names.begin(), names.end());
  return names;
}

// Throws unless every topic has a message.
void check_read(const std::string& path, const McapReader& reader,
                const std::map<std::string, TopicRead>& topics) {
  for (const auto& [topic, read] : topics) {
    if (!read.time_ns.empty()) continue;
    const std::vector<std::string> names = topic_names(reader);
    const bool known = std::find(names.begin(), names.end(), topic) != names.end();
    throw core::InputError({path, {}, {}, topic},
                           known
                               ? fmt::format("the topic has no message")
                               : fmt::format("the bag has no topic '{}' (role '{}')", topic,
                                             read.roles.empty() ? "time" : read.roles.front().role),
                           fmt::format("its topics: {}", fmt::join(names, ", ")));
  }
}

}  // namespace

FileLog read_bag_file(const std::filesystem::path& path, const ColumnMap& map, BagTime time,
                      unsigned jobs) {
  const std::string file = path.string();
  std::map<std::string, TopicRead> topics = plan_topics(map, file);
  McapReader reader(path, jobs);
  std::string axis;
  if (const RoleColumn* t = map.find("time"); t != nullptr) {
    const std::vector<std::string> names = topic_names(reader);
    if (topics.contains(t->column) ||
        std::find(names.begin(), names.end(), t->column) != names.end() ||
        t->column.starts_with('/')) {
      axis = t->column;
      topics[axis];  // its times, even without a role
    }
  }
  if (topics.empty()) {
    throw core::InputError({file, {}, {}, {}}, "no role is mapped to a field of the bag",
                           std::string(kColumnHint));
  }
  BagRead(reader, topics, time).run();
  check_read(file, reader, topics);
  if (axis.empty()) {  // the topic with the most messages
    std::size_t most = 0;
    for (const auto& [topic, read] : topics) {
      if (read.time_ns.size() > most) {
        axis = topic;
        most = read.time_ns.size();
      }
    }
  }
  FileLog out = topic_log(file, axis, topics.at(axis));
  for (auto& [topic, read] : topics) {
    if (topic != axis) out.more.push_back(topic_log(file, topic, read));
  }
  return out;
}

}  // namespace dynpos::io
