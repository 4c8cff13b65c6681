// libFuzzer target: a set of .msg definitions and a CDR message. The input is split at each
// line "%%": the parts before the last are .msg files, each "pkg/Type" on its first line and its
// fields after; the last part is the message. Each type is resolved against the set (the types
// it names looked up in it, then in the built-in set, as --msg-path folders are) and every
// numeric field (up to 64) is picked from the message. Bad input must end in Ros2MsgError or
// CdrError, as the bag readers turn them into core::InputError.

#include <map>
#include <string>
#include <vector>

#include "dynpos/io/cdr_decoder.hpp"
#include "dynpos/io/ros2_msg_set.hpp"
#include "fuzz_input.hpp"

namespace io = dynpos::io;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view rest = dynpos::fuzz::as_text(data, size);
  std::vector<std::string_view> parts;
  for (auto at = rest.find("\n%%\n"); at != std::string_view::npos; at = rest.find("\n%%\n")) {
    parts.push_back(rest.substr(0, at));
    rest = rest.substr(at + 4);
  }
  const std::string_view message = rest;
  std::map<std::string, std::string> files;
  for (const std::string_view part : parts) {
    const auto line = part.find('\n');
    const std::string_view type = part.substr(0, line);
    files[io::ros2_type_name(type)] =
        line == std::string_view::npos ? std::string() : std::string(part.substr(line + 1));
  }
  const io::Ros2MsgSet builtin;
  const io::Ros2MsgLookup lookup = [&](const std::string& type) -> std::optional<std::string> {
    if (const auto f = files.find(type); f != files.end()) return f->second;
    return builtin.find(type);
  };
  for (const auto& [type, text] : files) {
    try {
      io::Ros2Schema schema = io::Ros2Schema::parse(type, text, lookup);
      std::vector<std::string> paths = io::CdrDecoder::numeric_fields(schema, 64);
      const io::CdrDecoder decoder(std::move(schema), paths);
      std::vector<double> values(paths.size());
      decoder.decode({reinterpret_cast<const std::uint8_t*>(message.data()), message.size()},
                     values);
    } catch (const io::Ros2MsgError&) {
    } catch (const io::CdrError&) {
    }
  }
  return 0;
}
