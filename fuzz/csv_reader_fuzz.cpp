// libFuzzer target: the CSV reader with a column map. An input is a TOML column map, a line
// "%%", then the CSV log (fuzz_input.hpp); without the marker the whole input is a log, read
// with every numeric column (read_csv_all) and by its header. With a map the log is read
// whole, within a window, and by block parsing on two threads, which must give what the row
// reader gives (csv_blocks.hpp): the same channels, values and errors.

#include <cmath>
#include <cstring>
#include <optional>
#include <string>

#include "dynpos/core/error.hpp"
#include "dynpos/io/column_map.hpp"
#include "dynpos/io/csv_reader.hpp"
#include "fuzz_input.hpp"

namespace {

using dynpos::core::InputError;
namespace io = dynpos::io;

// The log read with `options`, or the message of the InputError it gave.
struct Outcome {
  std::optional<dynpos::core::Log> log;
  std::string error;
};

Outcome read(const std::filesystem::path& path, const io::ColumnMap& map,
             const io::CsvReadOptions& options) {
  try {
    return {io::read_csv_log(path, map, options).log, {}};
  } catch (const InputError& e) {
    return {std::nullopt, e.what()};
  }
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Block parsing on two threads against one: the reader promises the same result for any number.
void check_same(const Outcome& one, const Outcome& two) {
  if (one.error != two.error || one.log.has_value() != two.log.has_value()) __builtin_trap();
  if (!one.log) return;
  const auto& a = *one.log;
  const auto& b = *two.log;
  if (a.size() != b.size() || a.channel_names() != b.channel_names()) __builtin_trap();
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!same_bits(a.time()[i], b.time()[i])) __builtin_trap();
  }
  for (const auto& name : a.channel_names()) {
    const auto& x = a.channel(name).values;
    const auto& y = b.channel(name).values;
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (!same_bits(x[i], y[i])) __builtin_trap();
    }
  }
}

void read_with_map(const std::filesystem::path& path, std::string_view map_text) {
  io::ColumnMap map;
  try {
    map = io::parse_column_map(map_text, "map.toml");
  } catch (const InputError&) {
    return;
  }
  io::CsvReadOptions options;
  options.jobs = 1;
  const Outcome one = read(path, map, options);
  options.jobs = 2;
  check_same(one, read(path, map, options));
  options.t_from_s = 0.5;
  options.t_to_s = 2.0;
  (void)read(path, map, options);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static dynpos::fuzz::InputFile file("log.csv");
  const auto parts = dynpos::fuzz::split_at_marker(dynpos::fuzz::as_text(data, size));
  const auto& path = file.write(parts.second);
  if (!parts.first.empty()) {
    read_with_map(path, parts.first);
    return 0;
  }
  try {
    (void)io::read_csv_header(path);
  } catch (const InputError&) {
  }
  try {
    io::CsvReadOptions options;
    options.jobs = 1;
    (void)io::read_csv_all(path, options);
  } catch (const InputError&) {
  }
  return 0;
}
