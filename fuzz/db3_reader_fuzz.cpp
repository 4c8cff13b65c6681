// libFuzzer target: a rosbag2 SQLite bag (.db3 file image) read by the bag reader with roles on
// fields of topics /cmd (std_msgs/msg/Float64) and /imu (sensor_msgs/msg/Imu, header stamps: a
// nested field and an element of a fixed array), their types from the bag's message_definitions
// or the built-in set. One read per input: opening SQLite is most of an execution's cost, so the
// three roles share it. Bad input must end in core::InputError.

#include "dynpos/core/error.hpp"
#include "dynpos/io/db3_log.hpp"
#include "fuzz_input.hpp"

namespace io = dynpos::io;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static dynpos::fuzz::InputFile file("bag.db3");
  const auto& path = file.write(dynpos::fuzz::as_text(data, size));
  try {
    io::ColumnMap map;
    map.set_column("time", "time");
    map.set_column("input", "/cmd.data");
    map.set_column("output", "/imu.angular_velocity.z");
    map.set_column("heading", "/imu.orientation_covariance[8]");
    (void)io::read_db3_bag(path, map, io::BagTime::kAuto);
  } catch (const dynpos::core::InputError&) {
  }
  return 0;
}
