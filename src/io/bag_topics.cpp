#include "bag_topics.hpp"

#include <algorithm>
#include <cassert>
#include <numeric>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "csv_cell.hpp"
#include "dynpos/core/parallel_for.hpp"
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

// Notes in read.unordered whether `times`, appended next, break the strictly increasing order.
void note_order(BagTopic& read, std::span<const std::int64_t> times) {
  if (read.unordered || times.empty()) return;
  std::int64_t last = read.time_ns.empty() ? times[0] - 1 : read.time_ns[read.time_ns.size() - 1];
  for (const std::int64_t t : times) {
    read.unordered = read.unordered || t <= last;
    last = t;
  }
}

// The indices of the topic's messages in time order, a repeated time kept once; empty when
// they are in strictly increasing order already (the usual case: no copy then).
std::vector<std::size_t> time_order(const BagTopic& read) {
  if (!read.unordered) return {};
  const ColumnBlocks<std::int64_t>& time_ns = read.time_ns;
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

// A topic's messages in time order: `order` (empty when they are in order already), their
// count and the first time.
struct TopicOrder {
  std::vector<std::size_t> order;
  std::size_t messages = 0;
  std::size_t n = 0;  // kept
  std::int64_t origin_ns = 0;
};

TopicOrder topic_order(const BagTopic& read) {
  TopicOrder out{time_order(read), read.time_ns.size(), read.time_ns.size(), 0};
  if (!out.order.empty()) out.n = out.order.size();
  out.origin_ns = read.time_ns[out.order.empty() ? 0 : out.order[0]];
  return out;
}

// Column `c` of the topic in time order: its time axis [s from the first time] (c == 0) or its
// role c - 1, taken out of `read` (whose blocks are freed as they are copied).
std::vector<double> topic_column(BagTopic& read, const TopicOrder& order, std::size_t c) {
  const std::int64_t origin = order.origin_ns;
  const auto seconds = [origin](std::int64_t ns) {
    return static_cast<double>(ns - origin) * 1e-9;
  };
  if (order.order.empty()) {
    if (c == 0) return read.time_ns.take<double>(seconds);
    return read.values[c - 1].take();
  }
  std::vector<double> out;
  out.reserve(order.n);  // not zeroed first: each value is written once
  if (c == 0) {
    for (const std::size_t k : order.order) out.push_back(seconds(read.time_ns[k]));
    read.time_ns.clear();
  } else {
    for (const std::size_t k : order.order) out.push_back(read.values[c - 1][k]);
    read.values[c - 1].clear();
  }
  return out;
}

// The topic's messages as a FileLog from its columns (topic_column): ordered by time, repeated
// times dropped.
FileLog topic_log(const std::string& path, const std::string& topic, const BagTopic& read,
                  const TopicOrder& order, std::vector<std::vector<double>> columns,
                  std::string_view format, unsigned jobs) {
  FileLog out;
  out.log = core::Log(std::move(columns[0]), jobs);
  for (std::size_t r = 0; r < read.roles.size(); ++r) {
    const BagRolePlan& plan = read.roles[r];
    out.log.add_channel(plan.role, core::si_unit(plan.unit.quantity).symbol,
                        std::move(columns[r + 1]), plan.interp);
  }
  out.report.path = path;
  out.report.topic = topic;
  out.report.format = std::string(format);
  const bool header = std::any_of(read.sources.begin(), read.sources.end(),
                                  [](const auto& c) { return c.second.header; });
  out.report.time_format = header ? "header.stamp" : "receive time";
  out.report.records = order.n;
  if (order.n < order.messages) out.report.skipped.add("repeated time", order.messages - order.n);
  out.origin_ns = order.origin_ns;
  out.origin = format_iso8601(order.origin_ns, 0);
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
  BagSource& made = topic.sources[source];
  made.decoder = std::make_unique<CdrDecoder>(std::move(schema), paths);
  made.header = header;
  topic.values.resize(topic.roles.size());
}

std::int64_t decode_bag_row(const std::vector<BagRolePlan>& roles, const BagSource& source,
                            std::span<const std::uint8_t> data, std::int64_t receive_ns,
                            std::vector<double>& scratch) {
  const std::size_t n = roles.size();
  scratch.resize(n + (source.header ? 2 : 0));
  source.decoder->decode(data, scratch);
  std::int64_t ns = receive_ns;
  if (source.header) {
    ns = static_cast<std::int64_t>(scratch[n]) * 1'000'000'000 +
         static_cast<std::int64_t>(scratch[n + 1]);
  }
  for (std::size_t i = 0; i < n; ++i) {
    scratch[i] = detail::to_si(roles[i].unit, scratch[i] * roles[i].scale);
  }
  return ns;
}

void add_bag_message(BagTopic& topic, std::uint64_t source, std::span<const std::uint8_t> data,
                     std::int64_t receive_ns) {
  std::vector<double>& v = topic.scratch;
  const std::int64_t ns =
      decode_bag_row(topic.roles, topic.sources.at(source), data, receive_ns, v);
  note_order(topic, {&ns, 1});
  topic.time_ns.push_back(ns);
  for (std::size_t i = 0; i < topic.roles.size(); ++i) topic.values[i].push_back(v[i]);
}

void reserve_bag_rows(BagTopic& topic, std::uint64_t rows) {
  for (ColumnBlocks<double>& v : topic.values) {
    v.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(rows, SIZE_MAX / 8)));
  }
}

void BagRows::reserve_more() {
  const std::size_t n = std::max<std::size_t>(256, 2 * time_ns.capacity());
  for (std::vector<double>& v : values) v.reserve(n);
  time_ns.reserve(n);  // last: its room is never more than the values'
}

void append_bag_rows(BagTopic& topic, BagRows& rows) {
  note_order(topic, rows.time_ns);
  topic.time_ns.append(rows.time_ns);
  rows.time_ns.clear();
  for (std::size_t i = 0; i < rows.values.size(); ++i) {
    topic.values[i].append(rows.values[i]);
    rows.values[i].clear();
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
                     std::string_view format, unsigned jobs) {
  if (axis.empty()) {  // the topic with the most messages
    std::size_t most = 0;
    for (const auto& [topic, read] : topics) {
      if (read.time_ns.size() > most) {
        axis = topic;
        most = read.time_ns.size();
      }
    }
  }
  std::vector<BagTopic*> reads;
  for (auto& [topic, read] : topics) reads.push_back(&read);
  std::vector<TopicOrder> orders(reads.size());
  core::parallel_for(reads.size(), jobs,
                     [&](std::size_t k) { orders[k] = topic_order(*reads[k]); });
  // Every column of every topic, taken out on the threads.
  std::vector<std::pair<std::size_t, std::size_t>> which;  // (topic, column)
  std::vector<std::vector<std::vector<double>>> columns(reads.size());
  for (std::size_t k = 0; k < reads.size(); ++k) {
    columns[k].resize(reads[k]->roles.size() + 1);
    for (std::size_t c = 0; c < columns[k].size(); ++c) which.emplace_back(k, c);
  }
  core::parallel_for(which.size(), jobs, [&](std::size_t i) {
    const auto [k, c] = which[i];
    columns[k][c] = topic_column(*reads[k], orders[k], c);
  });
  FileLog out;
  std::size_t k = 0;
  for (auto& [topic, read] : topics) {
    FileLog log = topic_log(path, topic, read, orders[k], std::move(columns[k]), format, jobs);
    if (topic == axis) {
      std::vector<FileLog> more = std::move(out.more);
      out = std::move(log);
      out.more = std::move(more);
    } else {
      out.more.push_back(std::move(log));
    }
    ++k;
  }
  return out;
}

}  // namespace dynpos::io::detail
