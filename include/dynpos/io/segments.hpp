#pragma once
/// \file
/// A segment file: the named stretches of a log to analyse, e.g. the tests of a sea trial as
/// the bridge log lists them.
///
/// CSV, one segment a line: `name, start, end`, start and end in seconds on the log's clock,
/// start < end. A first line whose start is not a number is a header; blank lines and lines
/// starting with '#' are skipped, and a '#' after the fields starts a comment. Segments may
/// come in any order but must not overlap.

#include <filesystem>
#include <string>
#include <vector>

namespace dynpos::io {

/// One named stretch of a log.
struct Segment {
  std::string name;
  double start_s = 0.0;  ///< [s], log clock
  double end_s = 0.0;    ///< [s], log clock, > start_s
  std::size_t line = 0;  ///< 1-based line in the segment file, for messages
};

/// Reads a segment file, sorted by start time.
/// Throws core::InputError naming file:line:column for a row without three fields, an empty
/// name, a start or end that is not a finite number, start ≥ end, or overlapping segments; and
/// naming the file when it cannot be read or holds no segment.
std::vector<Segment> read_segments(const std::filesystem::path& path);

}  // namespace dynpos::io
