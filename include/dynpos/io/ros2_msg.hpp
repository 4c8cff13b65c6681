#pragma once
/// \file
/// ROS 2 message definitions (.msg text, and the `ros2msg` schemas of MCAP files): the fields
/// of a message type and of the types it nests, as CdrDecoder (io/cdr_decoder.hpp) walks them.
///
/// A schema is the root type's definition followed by each nested type's, after a line of '='
/// and a line "MSG: pkg/Type". A line "TYPE NAME" is a field (a default value after it is
/// ignored), "TYPE NAME=VALUE" a constant (ignored), '#' starts a comment. Types: bool, byte,
/// char, int8…uint64, float32, float64, string, wstring (string<=N bounded), a nested
/// "pkg/Type" or "Type" (same package, or std_msgs/Header for "Header"), each as T, T[N]
/// (fixed), T[<=N] (bounded) or T[] (unbounded sequence). builtin_interfaces/Time and Duration
/// (int32 sec, uint32 nanosec) are known without their definitions.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace dynpos::io {

/// A message definition that cannot be used: the problem (with the type and line).
class Ros2MsgError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class Ros2Primitive : std::uint8_t {
  kBool,
  kByte,
  kChar,
  kInt8,
  kUint8,
  kInt16,
  kUint16,
  kInt32,
  kUint32,
  kInt64,
  kUint64,
  kFloat32,
  kFloat64,
  kString,
  kWstring
};

/// The primitive named `name` ("float64", "string", …), or nullopt.
std::optional<Ros2Primitive> find_ros2_primitive(std::string_view name) noexcept;
/// Its bytes in CDR (an element of a string: its 4-byte length).
std::size_t ros2_primitive_bytes(Ros2Primitive p) noexcept;

struct Ros2Field {
  enum class Array : std::uint8_t { kNone, kFixed, kBounded, kUnbounded };
  std::string name;
  std::optional<Ros2Primitive> primitive;  ///< else a nested message: `nested`
  std::size_t nested = 0;                  ///< index in Ros2Schema::types
  Array array = Array::kNone;
  std::uint32_t size = 0;  ///< T[N]: N; T[<=N]: the bound
};

struct Ros2Type {
  std::string name;  ///< "pkg/Type"
  std::vector<Ros2Field> fields;
  /// The fewest bytes one value of it takes in CDR (without padding), at least 1.
  std::size_t min_bytes = 1;
};

/// The .msg text of a type ("pkg/Type") a definition refers to without holding it, or nullopt
/// (io/ros2_msg_set.hpp).
using Ros2MsgLookup = std::function<std::optional<std::string>(const std::string& type)>;

/// A root message type with every type it nests (types[0] is the root).
struct Ros2Schema {
  std::vector<Ros2Type> types;

  /// The schema of `root_name` ("pkg/msg/Type" or "pkg/Type") from its definition text (the
  /// root's, then the nested types' after their "MSG:" lines); a type the text lacks is asked of
  /// `more` when given. Throws Ros2MsgError for a line that is not a field, an unknown type, a
  /// recursive type or an array of zero elements.
  static Ros2Schema parse(std::string_view root_name, std::string_view text,
                          const Ros2MsgLookup& more = {});
};

/// "pkg/Type" from "pkg/msg/Type" (and "pkg/Type" as it is).
std::string ros2_type_name(std::string_view name);

}  // namespace dynpos::io
