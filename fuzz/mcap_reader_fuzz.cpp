// libFuzzer target: the MCAP reader (records, chunks in every compression, summary and chunk
// indexes), then the bag reader on top of it (ros2msg schemas, CDR messages) with a role on a
// field of topic /a. Bad input must end in core::InputError. The reader must hand on the same
// messages at the same positions, or throw the same error, on worker threads as on the calling
// thread alone; the bag reader (its messages decoded ahead on the chunks' threads) must give the
// same columns, or the same error, on one thread and on three. Each field is also read alone on
// one thread; the three-thread comparison reads the three fields at once (starting and joining
// threads is most of an execution's cost under the sanitizers).

#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "dynpos/core/error.hpp"
#include "dynpos/io/bag_log.hpp"
#include "dynpos/io/mcap_reader.hpp"
#include "fuzz_input.hpp"

namespace io = dynpos::io;

namespace {

// What a read hands on: per message its channel, log time, size, first byte and position; then
// the error, if any.
std::string read_all(const std::filesystem::path& path, unsigned jobs, std::size_t& bytes) {
  std::string out;
  try {
    io::McapReader reader(path, jobs);
    reader.read_messages(
        [](const io::McapChannel& c) { return c.topic != "/b"; },
        [&](const io::McapMessage& m) {
          bytes += m.data.size();
          out += std::to_string(m.channel_id) + ' ' + std::to_string(m.log_time_ns) + ' ' +
                 std::to_string(m.data.size()) + ' ' +
                 std::to_string(m.data.empty() ? 0 : m.data[0]) + ' ' + m.position() + '\n';
        });
  } catch (const dynpos::core::InputError& e) {
    out += e.what();
  }
  return out;
}

using Roles = std::vector<std::pair<const char*, const char*>>;  // role, column

// What the bag reader gives with `roles`: each topic's times and values, bit for bit, or the
// error.
std::string read_bag(const std::filesystem::path& path, const Roles& roles, unsigned jobs) {
  std::string out;
  const auto add = [&out](double x) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits);
    out += std::to_string(bits) + ' ';
  };
  try {
    io::ColumnMap map;
    map.set_column("time", "time");
    for (const auto& [role, column] : roles) map.set_column(role, column);
    const io::FileLog log = io::read_bag_file(path, map, io::BagTime::kAuto, jobs);
    for (const io::FileLog* f = &log; f != nullptr;) {
      out += f->report.topic + '\n';
      for (const double t : f->log.time()) add(t);
      for (const auto& [role, column] : roles) {
        if (!f->log.has(role)) continue;
        for (const double v : f->log.values(role)) add(v);
      }
      f = f != &log || log.more.empty() ? nullptr : &log.more[0];
    }
  } catch (const dynpos::core::InputError& e) {
    out += e.what();
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static dynpos::fuzz::InputFile file("bag.mcap");
  const auto& path = file.write(std::string_view(reinterpret_cast<const char*>(data), size));
  std::size_t bytes = 0;
  const std::string alone = read_all(path, 1, bytes);
  if (bytes > size * 4096 + (std::size_t{1} << 24)) __builtin_trap();
  if (read_all(path, 3, bytes) != alone) __builtin_trap();
  const Roles all{{"input", "/a.data"}, {"output", "/a.header.stamp.sec"}, {"heading", "/a.v[1]"}};
  for (const auto& role : all) (void)read_bag(path, {{"input", role.second}}, 1);
  if (read_bag(path, all, 1) != read_bag(path, all, 3)) __builtin_trap();
  return 0;
}
