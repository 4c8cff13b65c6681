// write_step_bags OUT: the step test's messages (a command and a first-order response with
// dead time) as a ROS 2 bag in each storage, and as CSV, for tests/cli/db3_bag.sh:
//   OUT/steps.mcap     MCAP, the definitions in its schemas
//   OUT/steps.db3      rosbag2 SQLite before Iron: type names only (test_msgs/msg/Feedback is
//                      in tests/cli/data/msgs, for --msg-path)
//   OUT/steps_bag/     a bag folder: metadata.yaml and two .db3 files with message_definitions
//   OUT/steps.csv      time, cmd, rpm (shortest round-trip decimals)

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include <fmt/format.h>

#include "../io/db3_test_writer.hpp"
#include "../io/mcap_test_writer.hpp"

namespace {

using dynpos::io::testing::Bytes;
using dynpos::io::testing::CdrWriter;
using dynpos::io::testing::Db3Writer;
using dynpos::io::testing::McapLayout;
using dynpos::io::testing::McapWriter;

constexpr std::int64_t kStart = 1'714'557'600'000'000'000;  // 2024-05-01T10:00:00Z [ns]
constexpr int kMessages = 701;                              // 70 s at 10 Hz

double step(double t, double t_step, double du) {
  const double s = t - t_step - 1.0;
  return s > 0 ? 2.0 * du * (1.0 - std::exp(-s / 3.0)) : 0.0;
}
double response(double t) { return step(t, 10.0, 1.0) + step(t, 40.0, -0.5); }
double command(double t) { return t < 10.0 ? 0.0 : (t < 40.0 ? 1.0 : 0.5); }

const std::string kFeedback = "std_msgs/Header header\nfloat64 rpm\nfloat64[3] extra\n" +
                              std::string(dynpos::io::testing::kHeaderDeps);

struct Sample {
  std::int64_t ns;
  double u;
  double y;
  Bytes cmd;
  Bytes feedback;
};

Sample sample(int k) {
  Sample s;
  s.ns = kStart + 100'000'000LL * k;
  const double t = static_cast<double>(s.ns - kStart) * 1e-9;
  s.u = command(0.1 * k);
  s.y = response(t);
  s.cmd = CdrWriter().put(s.u).bytes();
  s.feedback = CdrWriter().header(s.ns, "shaft").put(s.y).put(1.0).put(2.0).put(3.0 * k).bytes();
  return s;
}

void write_db3_files(const std::filesystem::path& out) {
  Db3Writer legacy(out / "steps.db3");
  legacy.topic(1, "/cmd", "std_msgs/msg/Float64");
  legacy.topic(2, "/feedback", "test_msgs/msg/Feedback");
  std::filesystem::create_directories(out / "steps_bag");
  Db3Writer first(out / "steps_bag" / "steps_bag_0.db3", true);
  Db3Writer second(out / "steps_bag" / "steps_bag_1.db3", true);
  for (Db3Writer* w : {&first, &second}) {
    w->topic(w == &first ? 5 : 9, "/feedback", "test_msgs/msg/Feedback");
    w->topic(w == &first ? 6 : 3, "/cmd", "std_msgs/msg/Float64");
    w->definition("test_msgs/msg/Feedback", "ros2msg", kFeedback);
    w->definition("std_msgs/msg/Float64", "ros2msg", "float64 data\n");
  }
  for (int k = 0; k < kMessages; ++k) {
    const Sample s = sample(k);
    legacy.message(1, s.ns, s.cmd);
    legacy.message(2, s.ns + 7'000'000, s.feedback);
    Db3Writer& split = k < kMessages / 2 ? first : second;
    split.message(&split == &first ? 6 : 3, s.ns, s.cmd);
    split.message(&split == &first ? 5 : 9, s.ns + 7'000'000, s.feedback);
  }
  std::ofstream metadata(out / "steps_bag" / "metadata.yaml");
  metadata << "rosbag2_bagfile_information:\n  version: 8\n  storage_identifier: sqlite3\n"
              "  relative_file_paths:\n    - steps_bag_0.db3\n    - steps_bag_1.db3\n"
              "  compression_format: \"\"\n  compression_mode: \"\"\n";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: write_step_bags OUT\n";
    return 2;
  }
  const std::filesystem::path out = argv[1];
  std::filesystem::create_directories(out);
  McapWriter mcap(McapLayout{true, "zstd", 64, true, true});
  const std::uint16_t cmd =
      mcap.channel(mcap.schema("std_msgs/msg/Float64", "float64 data\n"), "/cmd");
  const std::uint16_t fb =
      mcap.channel(mcap.schema("test_msgs/msg/Feedback", kFeedback), "/feedback");
  std::ofstream csv(out / "steps.csv");
  csv << "time,cmd,rpm\n";
  for (int k = 0; k < kMessages; ++k) {
    const Sample s = sample(k);
    mcap.message(cmd, static_cast<std::uint64_t>(s.ns), s.cmd);
    mcap.message(fb, static_cast<std::uint64_t>(s.ns + 7'000'000), s.feedback);
    csv << fmt::format("{},{},{}\n", static_cast<double>(s.ns - kStart) * 1e-9, s.u, s.y);
  }
  csv.close();
  mcap.write(out / "steps.mcap");
  write_db3_files(out);
  // A fixture the test cannot read would fail it for the wrong reason: every file must be there
  // and hold data, else the writer fails (exit 1) naming the file.
  for (const char* name : {"steps.csv", "steps.mcap", "steps.db3", "steps_bag/metadata.yaml",
                           "steps_bag/steps_bag_0.db3", "steps_bag/steps_bag_1.db3"}) {
    std::error_code ec;
    if (std::filesystem::file_size(out / name, ec) == 0 || ec) {
      std::cerr << "write_step_bags: " << (out / name).string() << " was not written\n";
      return 1;
    }
  }
  return 0;
}
