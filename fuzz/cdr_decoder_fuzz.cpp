// libFuzzer target: ros2msg schema text and a CDR message, split at the first "\n%%\n": the
// schema parsed, every numeric field it has (up to 64) picked from the message. Bad input must
// end in Ros2MsgError or CdrError, as the bag reader turns them into core::InputError.

#include <string>
#include <vector>

#include "dynpos/io/cdr_decoder.hpp"
#include "fuzz_input.hpp"

namespace io = dynpos::io;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const auto split = input.find("\n%%\n");
  const std::string_view text = input.substr(0, split);
  const std::string_view message =
      split == std::string_view::npos ? std::string_view() : input.substr(split + 4);
  try {
    io::Ros2Schema schema = io::Ros2Schema::parse("fuzz/msg/Root", text);
    std::vector<std::string> paths = io::CdrDecoder::numeric_fields(schema, 64);
    if (!paths.empty()) paths.push_back(paths.front());  // a repeated path
    const io::CdrDecoder decoder(std::move(schema), paths);
    std::vector<double> values(paths.size());
    decoder.decode({reinterpret_cast<const std::uint8_t*>(message.data()), message.size()}, values);
  } catch (const io::Ros2MsgError&) {
  } catch (const io::CdrError&) {
  }
  return 0;
}
