// libFuzzer target: the TOML column map, then the command-line overrides. An input is the map,
// a line "%%", then one override argument per line (up to eight), applied as --col, --unit
// and --clock-offset in turn (fuzz_input.hpp).

#include <string>

#include "dynpos/core/error.hpp"
#include "dynpos/io/column_map.hpp"
#include "fuzz_input.hpp"

namespace {

using dynpos::core::InputError;
namespace io = dynpos::io;

template <class Apply>
void apply(io::ColumnMap& map, std::string_view argument, Apply&& fn) {
  try {
    fn(map, argument);
  } catch (const InputError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto text = dynpos::fuzz::as_text(data, size);
  const auto parts = dynpos::fuzz::split_at_marker(text);
  io::ColumnMap map;
  try {
    map = io::parse_column_map(parts.first.empty() ? text : parts.first, "map.toml");
  } catch (const InputError&) {
    return 0;
  }
  if (parts.first.empty()) return 0;
  // The first eight lines: each failing override throws, and an input of hundreds of lines
  // would spend its time in exceptions rather than in new paths.
  std::string_view rest = parts.second;
  for (int n = 0; n < 8 && !rest.empty(); ++n) {
    const auto end = rest.find('\n');
    const auto line = rest.substr(0, end);
    apply(map, line, io::apply_column_override);
    apply(map, line, io::apply_unit_override);
    apply(map, line, io::apply_clock_offset_override);
    rest = end == std::string_view::npos ? std::string_view{} : rest.substr(end + 1);
  }
  return 0;
}
