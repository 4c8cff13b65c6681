#include "dynpos/io/segments.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <string_view>

#include "bounded_line.hpp"
#include "dynpos/core/error.hpp"
#include "text_util.hpp"

namespace dynpos::io {
namespace {

std::optional<double> parse_number(std::string_view text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

// The comma-separated fields of a line, trimmed, without a trailing '#' comment.
std::vector<std::string_view> fields_of(std::string_view line) {
  line = line.substr(0, line.find('#'));
  std::vector<std::string_view> fields;
  std::size_t from = 0;
  while (true) {
    const std::size_t comma = line.find(',', from);
    fields.push_back(detail::trim(line.substr(from, comma - from)));
    if (comma == std::string_view::npos) break;
    from = comma + 1;
  }
  return fields;
}

// The longest line of a segment file: a name and two times.
constexpr std::size_t kMaxLineBytes = std::size_t{64} << 10;

}  // namespace

std::vector<Segment> read_segments(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::ifstream in(path);
  if (!in) throw core::InputError({file, {}, {}, ""}, "cannot read the segment file", "");
  const auto error = [&file](std::size_t line, std::size_t column, const std::string& what,
                             const std::string& hint) {
    return core::InputError({file, line, column, ""}, what, hint);
  };
  constexpr const char* kFormat = "a segment is 'name, start, end' with times in s";
  std::vector<Segment> segments;
  std::string text;
  bool first_row = true;
  bool ended = false;
  for (std::size_t line = 1;; ++line) {
    const detail::LineStatus status = detail::read_bounded_line(in, text, kMaxLineBytes, ended);
    if (status == detail::LineStatus::kEnd) break;
    if (status == detail::LineStatus::kTooLong) {
      throw error(line, 1, fmt::format("a line longer than {} KiB", kMaxLineBytes >> 10), kFormat);
    }
    const std::string_view row = detail::trim(text);
    if (row.empty() || row.front() == '#') continue;
    const std::vector<std::string_view> f = fields_of(row);
    const bool header = first_row && f.size() >= 2 && !parse_number(f[1]);
    first_row = false;
    if (header) continue;
    if (f.size() != 3) {
      throw error(line, f.size() < 3 ? f.size() + 1 : 4,
                  std::to_string(f.size()) + " field(s) instead of 3", kFormat);
    }
    if (f[0].empty()) throw error(line, 1, "empty segment name", kFormat);
    Segment s{std::string(f[0]), 0.0, 0.0, line};
    for (std::size_t k : {1u, 2u}) {
      const std::optional<double> v = parse_number(f[k]);
      if (!v) {
        throw error(line, k + 1, "'" + std::string(f[k]) + "' is not a finite time",
                    "give the time in s on the log's clock");
      }
      (k == 1 ? s.start_s : s.end_s) = *v;
    }
    if (!(s.start_s < s.end_s)) {
      throw error(line, 3, "the segment ends before it starts", "give start < end");
    }
    segments.push_back(s);
  }
  if (segments.empty()) {
    throw core::InputError({file, {}, {}, ""}, "no segment in the file", kFormat);
  }
  std::stable_sort(segments.begin(), segments.end(),
                   [](const Segment& a, const Segment& b) { return a.start_s < b.start_s; });
  for (std::size_t k = 1; k < segments.size(); ++k) {
    const Segment& a = segments[k - 1];
    const Segment& b = segments[k];
    if (b.start_s < a.end_s) {
      const Segment& later = a.line > b.line ? a : b;
      throw error(
          later.line, 2,
          "segment '" + later.name + "' overlaps '" + (&later == &a ? b.name : a.name) + "'",
          "segments must not overlap");
    }
  }
  return segments;
}

}  // namespace dynpos::io
