// libFuzzer target: the time-stamp parsers. Each line of the input is given to every parser,
// and the lines as one column to the format detection. A stamp that parses must come back the
// same through format_iso8601: the same instant and the same zone.

#include <string>
#include <vector>

#include "dynpos/io/time_stamp.hpp"
#include "fuzz_input.hpp"

namespace {

namespace io = dynpos::io;

void parse_every_way(std::string_view cell) {
  if (const auto stamp = io::parse_iso8601(cell)) {
    const std::string shown = io::format_iso8601(stamp->ns, stamp->utc_offset_min);
    const auto again = io::parse_iso8601(shown);
    if (!again || again->ns != stamp->ns || again->utc_offset_min != stamp->utc_offset_min) {
      __builtin_trap();
    }
  }
  (void)io::parse_date_days(cell);
  (void)io::parse_time_of_day_ns(cell);
  for (const int exponent : {0, 3, 6, 9}) (void)io::parse_decimal_ns(cell, exponent);
  (void)io::parse_unpadded_ns(cell);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string_view> cells;
  std::string_view rest = dynpos::fuzz::as_text(data, size);
  while (!rest.empty()) {
    const auto end = rest.find('\n');
    cells.push_back(rest.substr(0, end));
    rest = end == std::string_view::npos ? std::string_view{} : rest.substr(end + 1);
  }
  for (const auto cell : cells) parse_every_way(cell);
  (void)io::detect_time_format(cells);
  (void)io::looks_like_unpadded_ns(cells);
  return 0;
}
