#pragma once
/// \file
/// CdrDecoder: numbers picked by field path from ROS 2 messages serialised as CDR.
///
/// A message is the 4-byte encapsulation header (XCDR1 big or little endian: 00 00 / 00 01;
/// plain XCDR2: 00 06 / 00 07) then the fields in order, each aligned to its size (at most 8
/// bytes in XCDR1, 4 in XCDR2) counted from the byte after the header; a string is a uint32
/// length (with its terminating NUL) and the bytes, a sequence a uint32 count and the elements,
/// a fixed array its elements only. Every count and length is checked against the bytes left
/// before it is used. Only the fields up to the last wanted one are walked.
///
/// The walk is compiled once per schema and paths into a plan: runs of fields that are skipped
/// become one aligned skip, nested messages are laid out in line, and only sequences and arrays
/// of messages are walked field by field. For little-endian data (ROS 2's), the plan's steps
/// between two strings or arrays are grouped into runs at fixed offsets from an aligned start:
/// one bounds check a run, its numbers read where they lie. A message the plan cannot read is
/// walked again by the schema, so that its error (problem and offset) is the walk's; values and
/// errors are those of decode_by_walking().

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynpos/io/ros2_msg.hpp"

namespace dynpos::io {

/// A message whose bytes do not hold what its type declares: the problem and the byte offset
/// in the message (its header included).
class CdrError : public std::runtime_error {
 public:
  CdrError(const std::string& problem, std::uint64_t offset)
      : std::runtime_error(problem), offset(offset) {}
  std::uint64_t offset;
};

class CdrDecoder {
 public:
  /// Picks the fields `paths` of schema.types[0]: "a.b.c", an element "a[2]" or "a[2].b".
  /// Throws Ros2MsgError for an unknown field (naming the fields there), a path that ends at a
  /// message or a string, an element of a field that is not an array or out of a fixed array.
  CdrDecoder(Ros2Schema schema, const std::vector<std::string>& paths);

  /// Decodes `message` into values[i] for paths[i] (values.size() == paths.size()), NaN for an
  /// element past the end of its sequence. Throws CdrError.
  void decode(std::span<const std::uint8_t> message, std::span<double> values) const;
  /// The same by walking the schema field by field for every message (the reference the plan
  /// is checked against).
  void decode_by_walking(std::span<const std::uint8_t> message, std::span<double> values) const;

  const Ros2Schema& schema() const noexcept { return schema_; }

  /// The numeric fields of schema.types[0] as paths, an array by its first element ("a[0]"),
  /// at most `max` of them.
  static std::vector<std::string> numeric_fields(const Ros2Schema& schema, std::size_t max);

  struct Want {
    std::uint32_t field = 0;
    std::uint32_t element = kWhole;  ///< of an array field; kWhole for a field that is not one
    std::int32_t slot = -1;          ///< a number: its index in values
    std::int32_t node = -1;          ///< a message: what is wanted inside it
    static constexpr std::uint32_t kWhole = 0xFFFFFFFFU;
  };
  /// What is wanted of one message value: sorted by field and element.
  struct Node {
    std::vector<Want> wants;
  };

 private:
  struct Reader;
  /// One step of the plan.
  struct Op {
    enum class Kind : std::uint8_t { kSkip, kRead, kString, kField };
    Kind kind = Kind::kSkip;
    std::uint8_t align = 1;  ///< kSkip, kRead: of its first (or only) value
    Ros2Primitive primitive = Ros2Primitive::kUint8;  ///< kRead; kString: string or wstring
    std::uint64_t bytes = 0;                          ///< kSkip
    std::int32_t slot = -1;                           ///< kRead
    // kField, an array walked as before: schema_.types[type].fields[field], and what is wanted
    // of it, nodes_[node].wants[first, end) (node -1: nothing).
    std::uint32_t type = 0;
    std::uint32_t field = 0;
    std::int32_t node = -1;
    std::uint32_t first = 0;
    std::uint32_t end = 0;
  };
  /// A step of the plan grouped for little-endian data (compile_runs): kFixed, skips and reads
  /// at fixed offsets from the step's start, aligned to `align`, `bytes` long, whose reads are
  /// reads[first, end); kOp, plan_[first] (a string or an array) as it is.
  struct Run {
    enum class Kind : std::uint8_t { kFixed, kOp };
    Kind kind = Kind::kFixed;
    std::uint8_t align = 1;
    std::uint64_t bytes = 0;
    std::uint32_t first = 0;
    std::uint32_t end = 0;
  };
  struct FixedRead {
    std::uint64_t offset = 0;  ///< from the run's start
    Ros2Primitive primitive = Ros2Primitive::kUint8;
    std::int32_t slot = -1;
  };
  struct Runs {
    std::vector<Run> runs;
    std::vector<FixedRead> reads;
  };
  /// The reader of `message` after its header; values all NaN when `fill`.
  Reader start(std::span<const std::uint8_t> message, std::span<double> values, bool fill) const;
  void finish(std::span<double> values) const;
  void compile(std::size_t type, std::int32_t node, std::size_t fields);
  void add_skip(std::size_t align, std::uint64_t bytes);
  void compile_runs(std::size_t max_align);
  void run(Reader& r, std::span<double> values) const;
  void run_op(const Op& op, Reader& r, std::span<double> values) const;
  void run_fixed(Reader& r, std::span<double> values) const;
  void skip_array(const Ros2Field& field, Reader& r) const;
  void walk(std::size_t type, const Node* node, Reader& r, std::span<double> values) const;
  void read_array(const Ros2Field& field, const Want* want, const Want* end, Reader& r,
                  std::span<double> values) const;
  void skip(const Ros2Field& field, std::uint64_t n, Reader& r) const;
  std::int32_t add_path(const std::string& path, std::int32_t slot);

  Ros2Schema schema_;
  std::vector<Node> nodes_;                                    // nodes_[0]: the root
  std::vector<std::pair<std::int32_t, std::int32_t>> copies_;  // a repeated path: to ← from
  std::vector<Op> plan_;
  bool may_miss_ = false;     ///< whether the plan walks an array (whose element may be missing)
  std::array<Runs, 2> runs_;  ///< for little-endian data, a maximum alignment of 8 (XCDR1), 4
};

}  // namespace dynpos::io
