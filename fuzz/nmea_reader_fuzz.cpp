// libFuzzer target: the NMEA 0183 reader, every sentence kind it knows (GGA, RMC, ZDA, HDT,
// THS, ROT, PSXN, VTG, …) with and without logger time stamps before the sentences, leniently
// (skipped lines counted) and strictly (the first skipped line an error). Lenient reading must
// accept whatever strict reading accepts, with the same log.

#include <cstring>

#include "dynpos/core/error.hpp"
#include "dynpos/io/nmea_log.hpp"
#include "fuzz_input.hpp"

namespace {

using dynpos::core::InputError;
namespace io = dynpos::io;

std::optional<io::NmeaLog> read(const std::filesystem::path& path, bool strict) {
  try {
    io::NmeaLogOptions options;
    options.strict = strict;
    return io::read_nmea_log(path, options);
  } catch (const InputError&) {
    return std::nullopt;
  }
}

bool same(const dynpos::core::Log& a, const dynpos::core::Log& b) {
  if (a.size() != b.size() || a.channel_names() != b.channel_names()) return false;
  const auto bits_equal = [](const std::vector<double>& x, const std::vector<double>& y) {
    return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(double)) == 0;
  };
  if (!bits_equal(a.time(), b.time())) return false;
  for (const auto& name : a.channel_names()) {
    if (!bits_equal(a.channel(name).values, b.channel(name).values)) return false;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static dynpos::fuzz::InputFile file("capture.nmea");
  const auto& path = file.write(dynpos::fuzz::as_text(data, size));
  try {
    (void)io::looks_like_nmea(path);
  } catch (const InputError&) {
  }
  const auto lenient = read(path, false);
  const auto strict = read(path, true);
  if (strict && !(lenient && same(strict->log, lenient->log))) __builtin_trap();
  return 0;
}
