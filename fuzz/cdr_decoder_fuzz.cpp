// libFuzzer target: ros2msg schema text and a CDR message, split at the first "\n%%\n": the
// schema parsed, every numeric field it has (up to 64) picked from the message. Bad input must
// end in Ros2MsgError or CdrError, as the bag reader turns them into core::InputError. The
// decoder's compiled plan must read what walking the schema reads: the same values (bit for
// bit, NaN for NaN) or the same error at the same offset.

#include <bit>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dynpos/io/cdr_decoder.hpp"
#include "fuzz_input.hpp"

namespace io = dynpos::io;

namespace {

// The values read, or the error and its offset.
struct Outcome {
  std::vector<double> values;
  std::optional<std::string> error;
};

template <class Decode>
Outcome outcome(std::size_t n, const Decode& decode) {
  Outcome out{std::vector<double>(n), std::nullopt};
  try {
    decode(out.values);
  } catch (const io::CdrError& e) {
    out.error = std::string(e.what()) + " at " + std::to_string(e.offset);
  }
  return out;
}

bool same(const Outcome& a, const Outcome& b) {
  if (a.error != b.error) return false;
  if (a.error) return true;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    if (std::bit_cast<std::uint64_t>(a.values[i]) != std::bit_cast<std::uint64_t>(b.values[i])) {
      return false;
    }
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const auto split = input.find("\n%%\n");
  const std::string_view text = input.substr(0, split);
  const std::string_view message =
      split == std::string_view::npos ? std::string_view() : input.substr(split + 4);
  const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(message.data()),
                                            message.size());
  try {
    io::Ros2Schema schema = io::Ros2Schema::parse("fuzz/msg/Root", text);
    std::vector<std::string> paths = io::CdrDecoder::numeric_fields(schema, 64);
    if (!paths.empty()) paths.push_back(paths.front());  // a repeated path
    const io::CdrDecoder decoder(std::move(schema), paths);
    const Outcome planned =
        outcome(paths.size(), [&](std::vector<double>& v) { decoder.decode(bytes, v); });
    const Outcome walked =
        outcome(paths.size(), [&](std::vector<double>& v) { decoder.decode_by_walking(bytes, v); });
    if (!same(planned, walked)) __builtin_trap();
    // Every other field alone: plans of a few wanted fields among many skipped ones.
    for (std::size_t i = 0; i + 1 < paths.size(); i += 2) {
      const io::CdrDecoder one(decoder.schema(), {paths[i]});
      const Outcome a = outcome(1, [&](std::vector<double>& v) { one.decode(bytes, v); });
      const Outcome b =
          outcome(1, [&](std::vector<double>& v) { one.decode_by_walking(bytes, v); });
      if (!same(a, b)) __builtin_trap();
    }
  } catch (const io::Ros2MsgError&) {
  }
  return 0;
}
