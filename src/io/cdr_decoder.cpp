#include "dynpos/io/cdr_decoder.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cstring>
#include <limits>

#include <fmt/format.h>

namespace dynpos::io {
namespace {

constexpr std::size_t kHeaderBytes = 4;

std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const auto dot = path.find('.', start);
    out.push_back(path.substr(start, dot - start));
    if (dot == std::string::npos) return out;
    start = dot + 1;
  }
}

std::string field_list(const Ros2Type& type) {
  std::string out;
  for (const Ros2Field& f : type.fields) out += (out.empty() ? "" : ", ") + f.name;
  return out;
}

bool is_array(const Ros2Field& f) { return f.array != Ros2Field::Array::kNone; }

bool is_text(Ros2Primitive p) {
  return p == Ros2Primitive::kString || p == Ros2Primitive::kWstring;
}

}  // namespace

struct CdrDecoder::Reader {
  const std::uint8_t* data;  // after the encapsulation header
  std::size_t size;
  std::size_t pos = 0;
  bool swap = false;
  std::size_t max_align = 8;

  [[noreturn]] void fail(const std::string& problem) const {
    throw CdrError(problem, pos + kHeaderBytes);
  }
  void align(std::size_t n) {
    const std::size_t a = std::min(n, max_align);
    pos = (pos + a - 1) & ~(a - 1);
  }
  void need(std::uint64_t n, const char* what) const {
    if (pos > size || n > size - pos) [[unlikely]] {
      fail_need(n, what);
    }
  }
  [[noreturn, gnu::noinline, gnu::cold]] void fail_need(std::uint64_t n, const char* what) const {
    fail(fmt::format("{} needs {} bytes, only {} are left", what, n, pos > size ? 0 : size - pos));
  }
  template <class T>
  T number(const char* what) {
    align(sizeof(T));
    need(sizeof(T), what);
    T v;
    std::memcpy(&v, data + pos, sizeof(T));
    pos += sizeof(T);
    if constexpr (sizeof(T) > 1) {
      if (swap) v = std::bit_cast<T>(byteswap(std::bit_cast<unsigned_of<T>>(v)));
    }
    return v;
  }
  template <class T>
  using unsigned_of =
      std::conditional_t<sizeof(T) == 2, std::uint16_t,
                         std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>;
  template <class U>
  static U byteswap(U v) {
    U out = 0;
    for (std::size_t i = 0; i < sizeof(U); ++i) {
      out = static_cast<U>((out << 8) | ((v >> (8 * i)) & 0xFF));
    }
    return out;
  }
  // A count of elements of at least `min_bytes` each, checked against the bytes left.
  std::uint32_t count(std::size_t min_bytes, const char* what) {
    const std::uint32_t n = number<std::uint32_t>(what);
    if (static_cast<std::uint64_t>(n) * min_bytes > size - std::min(size, pos)) {
      fail(fmt::format("{} declares {} elements, more than the {} bytes left hold", what, n,
                       size - std::min(size, pos)));
    }
    return n;
  }
  // A number of type p, as a double; a string is skipped (0).
  [[gnu::always_inline]] double primitive(Ros2Primitive p) {
    switch (p) {
      case Ros2Primitive::kBool:
        return number<std::uint8_t>("a bool") != 0 ? 1.0 : 0.0;
      case Ros2Primitive::kByte:
      case Ros2Primitive::kChar:
      case Ros2Primitive::kUint8:
        return number<std::uint8_t>("a uint8");
      case Ros2Primitive::kInt8:
        return number<std::int8_t>("an int8");
      case Ros2Primitive::kInt16:
        return number<std::int16_t>("an int16");
      case Ros2Primitive::kUint16:
        return number<std::uint16_t>("a uint16");
      case Ros2Primitive::kInt32:
        return number<std::int32_t>("an int32");
      case Ros2Primitive::kUint32:
        return number<std::uint32_t>("a uint32");
      case Ros2Primitive::kInt64:
        return static_cast<double>(number<std::int64_t>("an int64"));
      case Ros2Primitive::kUint64:
        return static_cast<double>(number<std::uint64_t>("a uint64"));
      case Ros2Primitive::kFloat32:
        return number<float>("a float32");
      case Ros2Primitive::kFloat64:
        return number<double>("a float64");
      case Ros2Primitive::kString:
      case Ros2Primitive::kWstring:
        skip_string(p);
        return 0.0;
    }
    return 0.0;
  }
  void skip_string(Ros2Primitive p) {
    const std::size_t unit = p == Ros2Primitive::kWstring ? 4 : 1;
    const std::uint32_t n = count(unit, "a string's length");
    pos += std::size_t{n} * unit;
  }
};

std::int32_t CdrDecoder::add_path(const std::string& path, std::int32_t slot) {
  std::size_t type = 0;
  std::size_t node = 0;
  const std::vector<std::string> parts = split_path(path);
  for (std::size_t k = 0; k < parts.size(); ++k) {
    std::string name = parts[k];
    std::uint32_t element = Want::kWhole;
    if (const auto open = name.find('['); open != std::string::npos && name.ends_with(']')) {
      const std::string digits = name.substr(open + 1, name.size() - open - 2);
      const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), element);
      if (ec != std::errc() || end != digits.data() + digits.size() || element == Want::kWhole) {
        throw Ros2MsgError(fmt::format("'{}': '{}' is not an element index", path, digits));
      }
      name.resize(open);
    }
    const Ros2Type& t = schema_.types[type];
    const auto f = std::find_if(t.fields.begin(), t.fields.end(),
                                [&](const Ros2Field& x) { return x.name == name; });
    if (f == t.fields.end()) {
      throw Ros2MsgError(fmt::format("'{}': {} has no field '{}' (its fields: {})", path, t.name,
                                     name, field_list(t)));
    }
    if (is_array(*f) != (element != Want::kWhole)) {
      throw Ros2MsgError(is_array(*f) ? fmt::format("'{}': {} is an array; give an element, "
                                                    "e.g. {}[0]",
                                                    path, name, name)
                                      : fmt::format("'{}': {} is not an array", path, name));
    }
    if (f->array != Ros2Field::Array::kUnbounded && is_array(*f) && element >= f->size) {
      throw Ros2MsgError(fmt::format("'{}': {} has at most {} elements", path, name, f->size));
    }
    const bool last = k + 1 == parts.size();
    if (last != f->primitive.has_value() || f->primitive == Ros2Primitive::kString ||
        f->primitive == Ros2Primitive::kWstring) {
      throw Ros2MsgError(
          fmt::format("'{}': {} is {}, not a number", path, name,
                      f->primitive ? "text" : "a message " + schema_.types[f->nested].name));
    }
    const auto field = static_cast<std::uint32_t>(f - t.fields.begin());
    std::vector<Want>& wants = nodes_[node].wants;
    auto w = std::find_if(wants.begin(), wants.end(),
                          [&](const Want& x) { return x.field == field && x.element == element; });
    if (w == wants.end()) {
      wants.push_back({field, element, -1, -1});
      std::sort(wants.begin(), wants.end(), [](const Want& a, const Want& b) {
        return a.field != b.field ? a.field < b.field : a.element < b.element;
      });
      w = std::find_if(wants.begin(), wants.end(),
                       [&](const Want& x) { return x.field == field && x.element == element; });
    }
    if (last) {
      if (w->slot >= 0) return w->slot;  // a repeated path
      w->slot = slot;
      return slot;
    }
    if (w->node < 0) {
      w->node = static_cast<std::int32_t>(nodes_.size());
      const std::size_t next = nodes_.size();
      nodes_.emplace_back();  // invalidates `wants` and `w`
      node = next;
    } else {
      node = static_cast<std::size_t>(w->node);
    }
    type = f->nested;
  }
  return slot;
}

CdrDecoder::CdrDecoder(Ros2Schema schema, const std::vector<std::string>& paths)
    : schema_(std::move(schema)), nodes_(1) {
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const auto slot = static_cast<std::int32_t>(i);
    const std::int32_t from = add_path(paths[i], slot);
    if (from != slot) copies_.emplace_back(slot, from);
  }
  const std::vector<Want>& root = nodes_[0].wants;
  compile(0, 0, root.empty() ? 0 : root.back().field + 1);
  compile_runs(8);
  compile_runs(4);
  // Every value is read or copied unless an array's element may be missing (NaN).
  may_miss_ = std::any_of(plan_.begin(), plan_.end(),
                          [](const Op& op) { return op.kind == Op::Kind::kField; });
}

// Groups the plan's skips and reads into runs at fixed offsets: a run starts aligned to its first
// step's alignment `a`, and takes the steps after it whose alignment divides `a` (their offsets
// from its start then do not depend on where it starts), up to a string or an array.
void CdrDecoder::compile_runs(std::size_t max_align) {
  Runs& out = runs_[max_align == 8 ? 0 : 1];
  bool open = false;
  Run run;
  std::uint64_t at = 0;  // from the run's start
  const auto close = [&] {
    if (!open) return;
    run.bytes = at;
    out.runs.push_back(run);
    open = false;
  };
  for (std::size_t i = 0; i < plan_.size(); ++i) {
    const Op& op = plan_[i];
    if (op.kind != Op::Kind::kSkip && op.kind != Op::Kind::kRead) {
      close();
      out.runs.push_back(
          {Run::Kind::kOp, 1, 0, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(i + 1)});
      continue;
    }
    const std::size_t size =
        op.kind == Op::Kind::kRead ? ros2_primitive_bytes(op.primitive) : op.align;
    const std::size_t align = std::min(size, max_align);
    if (!open || align > run.align) {
      close();
      const auto first = static_cast<std::uint32_t>(out.reads.size());
      run = {Run::Kind::kFixed, static_cast<std::uint8_t>(align), 0, first, first};
      at = 0;
      open = true;
    }
    at = (at + align - 1) & ~std::uint64_t{align - 1};
    if (op.kind == Op::Kind::kRead) {
      out.reads.push_back({at, op.primitive, op.slot});
      run.end = static_cast<std::uint32_t>(out.reads.size());
      at += size;
    } else {
      at += op.bytes;
    }
  }
  close();
}

void CdrDecoder::add_skip(std::size_t align, std::uint64_t bytes) {
  // After a skip that starts aligned to `a` and covers a multiple of `align` bytes, with
  // align <= a, the position is aligned to `align` (for either maximum alignment) already.
  if (!plan_.empty() && plan_.back().kind == Op::Kind::kSkip && align <= plan_.back().align &&
      plan_.back().bytes % align == 0) {
    plan_.back().bytes += bytes;
    return;
  }
  Op op;
  op.align = static_cast<std::uint8_t>(align);
  op.bytes = bytes;
  plan_.push_back(op);
}

// The steps of walk(type, node) over its first `fields` fields.
void CdrDecoder::compile(std::size_t type, std::int32_t node, std::size_t fields) {
  const std::vector<Want> none;
  const std::vector<Want>& wants = node >= 0 ? nodes_[static_cast<std::size_t>(node)].wants : none;
  std::size_t want = 0;
  for (std::uint32_t i = 0; i < fields; ++i) {
    const Ros2Field& field = schema_.types[type].fields[i];
    const std::size_t first = want;
    while (want < wants.size() && wants[want].field == i) ++want;
    const bool wanted = first != want;
    const bool number = field.primitive && !is_text(*field.primitive);
    const std::size_t bytes = number ? ros2_primitive_bytes(*field.primitive) : 0;
    if (is_array(field) && number && field.array == Ros2Field::Array::kFixed) {
      std::uint64_t at = 0;  // as read_array: skip to each wanted element, read it, skip the rest
      for (std::size_t w = first; w < want; ++w) {
        add_skip(bytes, (wants[w].element - at) * bytes);
        Op read;
        read.kind = Op::Kind::kRead;
        read.primitive = *field.primitive;
        read.slot = wants[w].slot;
        plan_.push_back(read);
        at = wants[w].element + 1;
      }
      add_skip(bytes, (field.size - at) * bytes);
    } else if (is_array(field)) {
      Op walked;
      walked.kind = Op::Kind::kField;
      walked.type = static_cast<std::uint32_t>(type);
      walked.field = i;
      walked.node = wanted ? node : -1;
      walked.first = static_cast<std::uint32_t>(first);
      walked.end = static_cast<std::uint32_t>(want);
      plan_.push_back(walked);
    } else if (field.primitive && !number) {
      Op text;
      text.kind = Op::Kind::kString;
      text.primitive = *field.primitive;
      plan_.push_back(text);
    } else if (field.primitive && wanted) {
      Op read;
      read.kind = Op::Kind::kRead;
      read.primitive = *field.primitive;
      read.slot = wants[first].slot;
      plan_.push_back(read);
    } else if (field.primitive) {
      add_skip(bytes, bytes);
    } else {  // a nested message, walked whole
      compile(field.nested, wanted ? wants[first].node : -1,
              schema_.types[field.nested].fields.size());
    }
  }
}

void CdrDecoder::run(Reader& r, std::span<double> values) const {
  for (const Op& op : plan_) run_op(op, r, values);
}

void CdrDecoder::run_op(const Op& op, Reader& r, std::span<double> values) const {
  {
    switch (op.kind) {
      case Op::Kind::kSkip:
        r.align(op.align);
        r.need(op.bytes, "a field");
        r.pos += static_cast<std::size_t>(op.bytes);
        break;
      case Op::Kind::kRead:
        values[static_cast<std::size_t>(op.slot)] = r.primitive(op.primitive);
        break;
      case Op::Kind::kString:
        r.skip_string(op.primitive);
        break;
      case Op::Kind::kField: {
        const Ros2Field& field = schema_.types[op.type].fields[op.field];
        if (op.node < 0) {
          skip_array(field, r);
        } else {
          const Want* wants = nodes_[static_cast<std::size_t>(op.node)].wants.data();
          read_array(field, wants + op.first, wants + op.end, r, values);
        }
        break;
      }
    }
  }
}

namespace {

// The little-endian number of type p at `at`, as a double (as Reader::primitive reads it).
[[gnu::always_inline]] inline double number_at(Ros2Primitive p, const std::uint8_t* at) {
  const auto as = [at]<class T>(T) {
    T v;
    std::memcpy(&v, at, sizeof(T));
    return v;
  };
  switch (p) {
    case Ros2Primitive::kFloat64:
      return as(double{});
    case Ros2Primitive::kFloat32:
      return as(float{});
    case Ros2Primitive::kBool:
      return as(std::uint8_t{}) != 0 ? 1.0 : 0.0;
    case Ros2Primitive::kByte:
    case Ros2Primitive::kChar:
    case Ros2Primitive::kUint8:
      return as(std::uint8_t{});
    case Ros2Primitive::kInt8:
      return as(std::int8_t{});
    case Ros2Primitive::kInt16:
      return as(std::int16_t{});
    case Ros2Primitive::kUint16:
      return as(std::uint16_t{});
    case Ros2Primitive::kInt32:
      return as(std::int32_t{});
    case Ros2Primitive::kUint32:
      return as(std::uint32_t{});
    case Ros2Primitive::kInt64:
      return static_cast<double>(as(std::int64_t{}));
    case Ros2Primitive::kUint64:
      return static_cast<double>(as(std::uint64_t{}));
    case Ros2Primitive::kString:
    case Ros2Primitive::kWstring:
      break;
  }
  return 0.0;
}

}  // namespace

void CdrDecoder::run_fixed(Reader& r, std::span<double> values) const {
  const Runs& runs = runs_[r.max_align == 8 ? 0 : 1];
  double* const out = values.data();
  for (const Run& run : runs.runs) {
    if (run.kind == Run::Kind::kOp) {
      run_op(plan_[run.first], r, values);
      continue;
    }
    r.align(run.align);
    r.need(run.bytes, "a field");
    const std::uint8_t* const base = r.data + r.pos;
    for (std::uint32_t k = run.first; k < run.end; ++k) {
      const FixedRead& read = runs.reads[k];
      const std::uint8_t* const at = base + read.offset;
      double& value = out[static_cast<std::size_t>(read.slot)];
      if (read.primitive == Ros2Primitive::kFloat64) {  // the usual one, without the switch
        std::memcpy(&value, at, sizeof(double));
      } else {
        value = number_at(read.primitive, at);
      }
    }
    r.pos += static_cast<std::size_t>(run.bytes);
  }
}

void CdrDecoder::skip(const Ros2Field& field, std::uint64_t n, Reader& r) const {
  if (n == 0) return;  // no element: no padding before it either
  if (field.primitive && *field.primitive != Ros2Primitive::kString &&
      *field.primitive != Ros2Primitive::kWstring) {
    const std::size_t bytes = ros2_primitive_bytes(*field.primitive);
    r.align(bytes);
    r.need(n * bytes, "an array");
    r.pos += static_cast<std::size_t>(n * bytes);
    return;
  }
  for (std::uint64_t i = 0; i < n; ++i) {
    if (field.primitive) {
      r.skip_string(*field.primitive);
    } else {
      walk(field.nested, nullptr, r, {});
    }
  }
}

void CdrDecoder::read_array(const Ros2Field& field, const Want* want, const Want* end, Reader& r,
                            std::span<double> values) const {
  const std::size_t min_bytes = field.primitive ? ros2_primitive_bytes(*field.primitive)
                                                : schema_.types[field.nested].min_bytes;
  std::uint64_t n = field.size;
  if (field.array == Ros2Field::Array::kFixed) {
    if (n * min_bytes > r.size - std::min(r.size, r.pos)) {
      r.fail(fmt::format("the array {}[{}] needs more than the bytes left", field.name, n));
    }
  } else {
    n = r.count(min_bytes, "a sequence");
    if (field.array == Ros2Field::Array::kBounded && n > field.size) {
      r.fail(fmt::format("the sequence {} has {} elements, more than its bound {}", field.name, n,
                         field.size));
    }
  }
  std::uint64_t at = 0;
  for (; want != end && want->element < n; ++want) {
    skip(field, want->element - at, r);
    if (want->slot >= 0) {
      values[static_cast<std::size_t>(want->slot)] = r.primitive(*field.primitive);
    } else {
      walk(field.nested, &nodes_[static_cast<std::size_t>(want->node)], r, values);
    }
    at = want->element + 1;
  }
  skip(field, n - at, r);
}

void CdrDecoder::skip_array(const Ros2Field& field, Reader& r) const {
  const std::uint64_t n = field.array == Ros2Field::Array::kFixed
                              ? field.size
                              : r.count(field.primitive ? ros2_primitive_bytes(*field.primitive)
                                                        : schema_.types[field.nested].min_bytes,
                                        "a sequence");
  skip(field, n, r);
}

void CdrDecoder::walk(std::size_t type, const Node* node, Reader& r,
                      std::span<double> values) const {
  const Ros2Type& t = schema_.types[type];
  const Want* want = node != nullptr ? node->wants.data() : nullptr;
  const Want* const end = node != nullptr ? want + node->wants.size() : nullptr;
  // The root stops after its last wanted field; a nested value is walked whole.
  const bool root = node == nodes_.data();
  const std::size_t fields =
      root ? (node->wants.empty() ? 0 : node->wants.back().field + 1) : t.fields.size();
  for (std::uint32_t i = 0; i < fields; ++i) {
    const Ros2Field& field = t.fields[i];
    const Want* first = want;
    while (want != end && want->field == i) ++want;
    if (is_array(field)) {
      if (first == want) {
        skip_array(field, r);
      } else {
        read_array(field, first, want, r, values);
      }
    } else if (field.primitive) {
      const double v = r.primitive(*field.primitive);
      if (first != want) values[static_cast<std::size_t>(first->slot)] = v;
    } else {
      walk(field.nested, first != want ? &nodes_[static_cast<std::size_t>(first->node)] : nullptr,
           r, values);
    }
  }
}

namespace {

[[noreturn, gnu::noinline, gnu::cold]] void bad_header(std::span<const std::uint8_t> message) {
  if (message.size() < kHeaderBytes) {
    throw CdrError(
        fmt::format("a message of {} bytes, without its 4-byte CDR header", message.size()), 0);
  }
  throw CdrError(fmt::format("the CDR encapsulation {:02x} {:02x} is not XCDR1 or plain XCDR2",
                             message[0], message[1]),
                 0);
}

}  // namespace

CdrDecoder::Reader CdrDecoder::start(std::span<const std::uint8_t> message,
                                     std::span<double> values, bool fill) const {
  if (message.size() < kHeaderBytes) bad_header(message);
  Reader r{message.data() + kHeaderBytes, message.size() - kHeaderBytes};
  const std::uint8_t kind = message[1];
  if (message[0] != 0 || (kind != 0 && kind != 1 && kind != 6 && kind != 7)) bad_header(message);
  r.swap = (kind & 1) == 0;  // big endian on this little-endian host
  r.max_align = kind >= 6 ? 4 : 8;
  if (fill) std::fill(values.begin(), values.end(), std::numeric_limits<double>::quiet_NaN());
  return r;
}

void CdrDecoder::finish(std::span<double> values) const {
  for (const auto& [to, from] : copies_) {
    values[static_cast<std::size_t>(to)] = values[static_cast<std::size_t>(from)];
  }
}

void CdrDecoder::decode(std::span<const std::uint8_t> message, std::span<double> values) const {
  Reader r = start(message, values, may_miss_);
  try {
    if (r.swap) {
      run(r, values);
    } else {
      run_fixed(r, values);
    }
  } catch (const CdrError&) {
    decode_by_walking(message, values);  // the walk's own error
    return;
  }
  finish(values);
}

void CdrDecoder::decode_by_walking(std::span<const std::uint8_t> message,
                                   std::span<double> values) const {
  Reader r = start(message, values, true);
  walk(0, nodes_.data(), r, values);
  finish(values);
}

std::vector<std::string> CdrDecoder::numeric_fields(const Ros2Schema& schema, std::size_t max) {
  std::vector<std::string> out;
  const auto visit = [&](const auto& self, std::size_t type, const std::string& prefix,
                         int depth) -> void {
    if (depth > 64) return;
    for (const Ros2Field& f : schema.types[type].fields) {
      if (out.size() >= max) return;
      const std::string name = prefix + f.name + (is_array(f) ? "[0]" : "");
      if (!f.primitive) {
        self(self, f.nested, name + ".", depth + 1);
      } else if (*f.primitive != Ros2Primitive::kString &&
                 *f.primitive != Ros2Primitive::kWstring) {
        out.push_back(name);
      }
    }
  };
  visit(visit, 0, "", 0);
  return out;
}

}  // namespace dynpos::io
