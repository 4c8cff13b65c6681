#include "bag_topics.hpp"

#include <algorithm>
#include <cassert>
#include <numeric>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "csv_cell.hpp"
#include "dynpos/io/time_stamp.hpp"

namespace dynpos::io::detail {
namespace {

BagRolePlan plan_role(const std::string& role, const RoleColumn& entry, std::string field) {
  const std::optional<RoleSpec> spec = find_role(role);
  assert(spec && "ColumnMap only holds known roles");
  BagRolePlan plan{role, std::move(field), {}, entry.scale, spec->interp, entry.source};
  if (entry.unit) {
    plan.unit = unit_for_role(*spec, *entry.unit, entry.source);
  } else {
    plan.unit = *core::find_unit(spec->default_unit);
  }
  return plan;
}

// The indices of the topic's messages in time order, a repeated time kept once; empty when
// they are in strictly increasing order already (the usual case: no copy then).
std::vector<std::size_t> time_order(const ColumnBlocks<std::int64_t>& time_ns) {
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
FileLog topic_log(const std::string& path, const std::string& topic, BagTopic& read,
                  std::string_view format) {
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
    const BagRolePlan& plan = read.roles[r];
    out.log.add_channel(plan.role, core::si_unit(plan.unit.quantity).symbol, std::move(v),
                        plan.interp);
  }
  out.report.path = path;
  out.report.topic = topic;
  out.report.format = std::string(format);
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

}  // namespace

BagTopics plan_bag_topics(const ColumnMap& map, const std::string& file) {
  BagTopics topics;
  for (const auto& [role, entry] : map.roles()) {
    if (role == "time" || role == "time.sec" || role == "time.nsec") continue;
    const std::string& column = entry.column;
    const auto dot = column.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == column.size()) {
      core::InputLocation where = entry.source;
      if (where.file.empty()) where.file = file;
      throw core::InputError(where,
                             fmt::format("role '{}': '{}' names no field of a topic", role, column),
                             std::string(kBagColumnHint));
    }
    topics[column.substr(0, dot)].roles.push_back(plan_role(role, entry, column.substr(dot + 1)));
  }
  return topics;
}

std::string bag_axis_topic(const ColumnMap& map, BagTopics& topics,
                           const std::vector<std::string>& names, const std::string& file) {
  std::string axis;
  if (const RoleColumn* t = map.find("time"); t != nullptr) {
    if (topics.contains(t->column) ||
        std::find(names.begin(), names.end(), t->column) != names.end() ||
        t->column.starts_with('/')) {
      axis = t->column;
      topics[axis];  // its times, even without a role
    }
  }
  if (topics.empty()) {
    throw core::InputError({file, {}, {}, {}}, "no role is mapped to a field of the bag",
                           std::string(kBagColumnHint));
  }
  return axis;
}

bool uses_header_stamp(const Ros2Schema& schema, BagTime time) {
  if (time == BagTime::kReceive) return false;
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

void add_bag_decoder(BagTopic& topic, std::uint64_t source, Ros2Schema schema, bool header) {
  std::vector<std::string> paths;
  for (const BagRolePlan& r : topic.roles) paths.push_back(r.field);
  if (header) {
    paths.emplace_back("header.stamp.sec");
    paths.emplace_back("header.stamp.nanosec");
  }
  auto decoder = std::make_unique<CdrDecoder>(std::move(schema), paths);
  topic.header_time[source] = header;
  topic.scratch.resize(paths.size());
  topic.values.resize(topic.roles.size());
  topic.decoders[source] = std::move(decoder);
}

void add_bag_message(BagTopic& topic, std::uint64_t source, std::span<const std::uint8_t> data,
                     std::int64_t receive_ns) {
  std::vector<double>& v = topic.scratch;
  topic.decoders.at(source)->decode(data, v);
  std::int64_t ns = receive_ns;
  if (topic.header_time.at(source)) {
    const std::size_t n = topic.roles.size();
    ns = static_cast<std::int64_t>(v[n]) * 1'000'000'000 + static_cast<std::int64_t>(v[n + 1]);
  }
  topic.time_ns.push_back(ns);
  for (std::size_t i = 0; i < topic.roles.size(); ++i) {
    const BagRolePlan& plan = topic.roles[i];
    topic.values[i].push_back(detail::to_si(plan.unit, v[i] * plan.scale));
  }
}

void check_bag_read(const std::string& path, const std::vector<std::string>& names,
                    const BagTopics& topics) {
  for (const auto& [topic, read] : topics) {
    if (!read.time_ns.empty()) continue;
    const bool known = std::find(names.begin(), names.end(), topic) != names.end();
    throw core::InputError({path, {}, {}, topic},
                           known
                               ? fmt::format("the topic has no message")
                               : fmt::format("the bag has no topic '{}' (role '{}')", topic,
                                             read.roles.empty() ? "time" : read.roles.front().role),
                           fmt::format("its topics: {}", fmt::join(names, ", ")));
  }
}

FileLog bag_file_log(const std::string& path, BagTopics& topics, std::string axis,
                     std::string_view format) {
  if (axis.empty()) {  // the topic with the most messages
    std::size_t most = 0;
    for (const auto& [topic, read] : topics) {
      if (read.time_ns.size() > most) {
        axis = topic;
        most = read.time_ns.size();
      }
    }
  }
  FileLog out = topic_log(path, axis, topics.at(axis), format);
  for (auto& [topic, read] : topics) {
    if (topic != axis) out.more.push_back(topic_log(path, topic, read, format));
  }
  return out;
}

}  // namespace dynpos::io::detail
