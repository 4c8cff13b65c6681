#include "dynpos/io/ros2_msg.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <map>

#include <fmt/format.h>

#include "text_util.hpp"

namespace dynpos::io {
namespace {

struct PrimitiveName {
  std::string_view name;
  Ros2Primitive type;
  std::size_t bytes;
};
constexpr std::array<PrimitiveName, 15> kPrimitives = {{
    {"bool", Ros2Primitive::kBool, 1},
    {"byte", Ros2Primitive::kByte, 1},
    {"char", Ros2Primitive::kChar, 1},
    {"int8", Ros2Primitive::kInt8, 1},
    {"uint8", Ros2Primitive::kUint8, 1},
    {"int16", Ros2Primitive::kInt16, 2},
    {"uint16", Ros2Primitive::kUint16, 2},
    {"int32", Ros2Primitive::kInt32, 4},
    {"uint32", Ros2Primitive::kUint32, 4},
    {"int64", Ros2Primitive::kInt64, 8},
    {"uint64", Ros2Primitive::kUint64, 8},
    {"float32", Ros2Primitive::kFloat32, 4},
    {"float64", Ros2Primitive::kFloat64, 8},
    {"string", Ros2Primitive::kString, 4},
    {"wstring", Ros2Primitive::kWstring, 4},
}};

// A field as written: its type text (without array suffix or string bound) and array.
struct RawField {
  std::string type;
  Ros2Field field;
  std::size_t line = 0;
};

struct RawType {
  std::string name;
  std::vector<RawField> fields;
};

constexpr std::string_view kBuiltinTime = "int32 sec\nuint32 nanosec\n";

std::string package_of(std::string_view type) {
  const auto slash = type.find('/');
  return slash == std::string_view::npos ? std::string() : std::string(type.substr(0, slash));
}

std::uint32_t array_size(std::string_view digits, const std::string& where) {
  std::uint32_t n = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), n);
  if (ec != std::errc() || end != digits.data() + digits.size()) {
    throw Ros2MsgError(fmt::format("{}: the array size '{}' is not a number", where, digits));
  }
  if (n == 0) throw Ros2MsgError(fmt::format("{}: an array of no element", where));
  return n;
}

// The field of one line "TYPE NAME", or nullopt for a constant.
std::optional<RawField> parse_field(std::string_view line, const std::string& where) {
  const auto space = line.find_first_of(" \t");
  if (space == std::string_view::npos) {
    throw Ros2MsgError(fmt::format("{}: '{}' is not a field \"TYPE NAME\"", where, line));
  }
  std::string_view type = line.substr(0, space);
  std::string_view rest = detail::trim(line.substr(space));
  const auto name_end = rest.find_first_of(" \t=");
  const std::string_view name = rest.substr(0, name_end);
  if (name.empty()) throw Ros2MsgError(fmt::format("{}: a field without a name", where));
  if (name_end != std::string_view::npos && detail::trim(rest.substr(name_end)).starts_with('=')) {
    return std::nullopt;  // a constant
  }
  RawField out;
  out.field.name = std::string(name);
  if (const auto open = type.find('['); open != std::string_view::npos) {
    if (!type.ends_with(']')) throw Ros2MsgError(fmt::format("{}: bad array '{}'", where, type));
    std::string_view inside = type.substr(open + 1, type.size() - open - 2);
    type = type.substr(0, open);
    if (inside.empty()) {
      out.field.array = Ros2Field::Array::kUnbounded;
    } else if (inside.starts_with("<=")) {
      out.field.array = Ros2Field::Array::kBounded;
      out.field.size = array_size(inside.substr(2), where);
    } else {
      out.field.array = Ros2Field::Array::kFixed;
      out.field.size = array_size(inside, where);
    }
  }
  if (const auto bound = type.find("<="); bound != std::string_view::npos) {
    type = type.substr(0, bound);  // string<=N: the bound is not needed to read it
  }
  out.type = std::string(type);
  out.field.primitive = find_ros2_primitive(type);
  return out;
}

RawType parse_type(std::string name, std::string_view text) {
  RawType out{std::move(name), {}};
  std::size_t line_number = 0;
  std::size_t start = 0;
  while (start <= text.size()) {
    const auto end = std::min(text.find('\n', start), text.size());
    ++line_number;
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    if (const auto hash = line.find('#'); hash != std::string_view::npos) {
      line = line.substr(0, hash);
    }
    line = detail::trim(line);
    if (line.empty()) continue;
    const std::string where = fmt::format("{} line {}", out.name, line_number);
    if (std::optional<RawField> f = parse_field(line, where)) {
      f->line = line_number;
      out.fields.push_back(std::move(*f));
    }
  }
  return out;
}

// The root's text and each "MSG: pkg/Type" section after a line of '='.
std::map<std::string, RawType> split_sections(const std::string& root, std::string_view text) {
  std::map<std::string, RawType> out;
  std::string name = root;
  std::size_t section = 0;
  std::size_t start = 0;
  const auto close = [&](std::size_t end) {
    if (!name.empty()) out.try_emplace(name, parse_type(name, text.substr(section, end - section)));
  };
  while (start < text.size()) {
    const auto end = std::min(text.find('\n', start), text.size());
    const std::string_view line = detail::trim(text.substr(start, end - start));
    if (line.size() >= 3 && line.find_first_not_of('=') == std::string_view::npos) {
      close(start);
      name.clear();
      section = std::min(end + 1, text.size());
    } else if (name.empty() && line.starts_with("MSG:")) {
      name = ros2_type_name(detail::trim(line.substr(4)));
      section = std::min(end + 1, text.size());
    }
    start = end + 1;
  }
  close(text.size());
  return out;
}

class Resolver {
 public:
  Resolver(std::map<std::string, RawType> raw, const Ros2MsgLookup& more)
      : raw_(std::move(raw)), more_(more) {}

  // The index of `name` in schema.types, resolved with the types it nests.
  std::size_t resolve(const std::string& name, Ros2Schema& schema, int depth = 0) {
    constexpr int kMaxDepth = 64;
    if (depth > kMaxDepth) {
      throw Ros2MsgError(fmt::format("{} nests types more than {} deep", name, kMaxDepth));
    }
    if (const auto done = index_.find(name); done != index_.end()) {
      if (schema.types[done->second].min_bytes == 0) {
        throw Ros2MsgError(fmt::format("{} contains itself", name));
      }
      return done->second;
    }
    auto raw = raw_.find(name);
    if (raw == raw_.end() &&
        (name == "builtin_interfaces/Time" || name == "builtin_interfaces/Duration")) {
      raw = raw_.emplace(name, parse_type(name, kBuiltinTime)).first;
    }
    if (raw == raw_.end() && more_) {
      if (std::optional<std::string> text = more_(name)) {
        raw = raw_.emplace(name, parse_type(name, *text)).first;
      }
    }
    if (raw == raw_.end()) {
      throw Ros2MsgError(more_ ? fmt::format("no definition of {} (not in the bag, not built in, "
                                             "not in the --msg-path folders)",
                                             name)
                               : fmt::format("the definition of {} is not in the schema", name));
    }
    const std::size_t index = schema.types.size();
    index_.emplace(name, index);
    schema.types.push_back({name, {}, 0});  // min_bytes 0: being resolved
    std::vector<Ros2Field> fields;
    for (const RawField& f : raw->second.fields) {
      Ros2Field field = f.field;
      if (!field.primitive) field.nested = resolve(nested_name(f.type, name), schema, depth + 1);
      fields.push_back(std::move(field));
    }
    if (fields.empty()) {  // as rosidl makes an empty message
      fields.push_back({"structure_needs_at_least_one_member", Ros2Primitive::kUint8});
    }
    Ros2Type& type = schema.types[index];
    type.fields = std::move(fields);
    type.min_bytes = min_bytes(type, schema);
    return index;
  }

 private:
  std::string nested_name(const std::string& type, const std::string& parent) const {
    if (type.find('/') != std::string::npos) return ros2_type_name(type);
    const std::string local = package_of(parent) + "/" + type;
    if (type == "Header" && !raw_.contains(local)) return "std_msgs/Header";
    return local;
  }

  static std::size_t min_bytes(const Ros2Type& type, const Ros2Schema& schema) {
    constexpr std::size_t kCap = std::size_t{1} << 40;
    std::size_t sum = 0;
    for (const Ros2Field& f : type.fields) {
      const std::size_t one =
          f.primitive ? ros2_primitive_bytes(*f.primitive) : schema.types[f.nested].min_bytes;
      std::size_t bytes = one;
      if (f.array == Ros2Field::Array::kFixed) bytes = std::min(kCap, one * f.size);
      if (f.array == Ros2Field::Array::kBounded || f.array == Ros2Field::Array::kUnbounded) {
        bytes = 4;
      }
      sum = std::min(kCap, sum + bytes);
    }
    return std::max<std::size_t>(sum, 1);
  }

  std::map<std::string, RawType> raw_;
  const Ros2MsgLookup& more_;
  std::map<std::string, std::size_t> index_;
};

}  // namespace

std::optional<Ros2Primitive> find_ros2_primitive(std::string_view name) noexcept {
  for (const PrimitiveName& p : kPrimitives) {
    if (p.name == name) return p.type;
  }
  return std::nullopt;
}

std::size_t ros2_primitive_bytes(Ros2Primitive p) noexcept {
  for (const PrimitiveName& n : kPrimitives) {
    if (n.type == p) return n.bytes;
  }
  return 1;
}

std::string ros2_type_name(std::string_view name) {
  const auto first = name.find('/');
  const auto last = name.rfind('/');
  if (first == std::string_view::npos || first == last) return std::string(name);
  return std::string(name.substr(0, first)) + std::string(name.substr(last));
}

Ros2Schema Ros2Schema::parse(std::string_view root_name, std::string_view text,
                             const Ros2MsgLookup& more) {
  const std::string root = ros2_type_name(root_name);
  Resolver resolver(split_sections(root, text), more);
  Ros2Schema schema;
  resolver.resolve(root, schema);
  return schema;
}

}  // namespace dynpos::io
