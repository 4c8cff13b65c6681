// libFuzzer target: the MCAP reader (records, chunks in every compression, summary and chunk
// indexes), then the bag reader on top of it (ros2msg schemas, CDR messages) with a role on a
// field of topic /a. Bad input must end in core::InputError.

#include "dynpos/core/error.hpp"
#include "dynpos/io/bag_log.hpp"
#include "dynpos/io/mcap_reader.hpp"
#include "fuzz_input.hpp"

namespace io = dynpos::io;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static dynpos::fuzz::InputFile file("bag.mcap");
  const auto& path = file.write(std::string_view(reinterpret_cast<const char*>(data), size));
  try {
    io::McapReader reader(path);
    std::size_t bytes = 0;
    reader.read_messages([](const io::McapChannel&) { return true; },
                         [&](const io::McapMessage& m) { bytes += m.data.size(); });
    if (bytes > size * 4096 + (std::size_t{1} << 24)) __builtin_trap();
  } catch (const dynpos::core::InputError&) {
  }
  for (const char* column : {"/a.data", "/a.header.stamp.sec", "/a.v[1]"}) {
    try {
      io::ColumnMap map;
      map.set_column("time", "time");
      map.set_column("input", column);
      (void)io::read_bag_file(path, map, io::BagTime::kAuto);
    } catch (const dynpos::core::InputError&) {
    }
  }
  return 0;
}
