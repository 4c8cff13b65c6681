// Reading a ROS 2 bag: a vessel's recording as chunked zstd MCAP of about 1 GB
// (DYNPOS_BAG_BENCH_MB sets the size), on 1 and 2 threads (the argument), with two column maps:
//   BM_ReadVesselBag       16 fields of 7 topics, as `--col ROLE=/TOPIC.FIELD` maps them: the
//                          speed figure;
//   BM_ReadStationKeeping  what `identify station-keeping` reads of such a recording (the GNSS
//                          fix's latitude and longitude, the four thrusters' power) and a 100 Hz
//                          column (the IMU's yaw rate, where a gyro compass heading would be).
// Wall-clock time; bytes/s are of the whole file (the compressed bytes on disk). Counters: the
// decompressed rate, messages per second, the process' processor time per GB of file (user +
// system, every thread: what the read costs whatever else the machine runs), its peak resident
// memory during the case (peak_MB; /proc's high-water mark, reset before the case), the columns
// read (columns_MB: each topic's time axis and roles, 8 bytes a value), the reader's own memory
// (reader_MB = peak - columns: chunks in flight, rows decoded ahead, the program itself) and
// the resident memory before the case (start_MB).
//
// The product goal: >= 300 MB/s on 2 cores, peak memory <= 256 MB for a 1 GB file. The memory
// bound is on reading a 1 GB bag for one analysis, whose columns are that analysis' data: the
// columns of the 16 fields alone take 355 MB, so no reader holds them in 256 MB, and that case's
// peak is reported as columns + the reader's own memory; BM_ReadStationKeeping is one analysis'
// read of the same file, whose peak must stay within 256 MB.
//
// The bag, as rosbag2 records it: messages in time order, interleaved in chunks of 1 MiB of
// records, zstd level 1, a summary with schemas, channels, chunk indexes and statistics (the
// messages per channel, by which the reader reserves the columns). Per 0.1 s (and
// the fields BM_ReadVesselBag reads):
//   /imu                      sensor_msgs/Imu           100 Hz  (3 fields read)
//   /odom                     nav_msgs/Odometry          20 Hz  (2)
//   /gnss/fix                 sensor_msgs/NavSatFix      10 Hz  (3)
//   /thrusters/tK/feedback    dp_msgs/ThrusterFeedback   10 Hz each, K = 1…4  (2 each)
//   /thrusters/tK/command     dp_msgs/ThrusterCommand    10 Hz each (none read)
// Measured values carry noise (all 52 bits of their mantissas vary), covariances are constant.
//
// The file is written once into the temporary folder, one chunk at a time, and removed at the
// end unless DYNPOS_BENCH_KEEP_BAG is set (a kept file is used again, with its counts in a
// file beside it).

#include <benchmark/benchmark.h>
#include <sys/resource.h>
#include <zstd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "../tests/io/mcap_test_writer.hpp"
#include "dynpos/io/bag_log.hpp"

namespace {

using dynpos::io::testing::Bytes;
using dynpos::io::testing::CdrWriter;
using W = dynpos::io::testing::McapWriter;

constexpr std::string_view kRule =
    "================================================================================\n";

std::string section(std::string_view name, std::string_view text) {
  return std::string(kRule) + "MSG: " + std::string(name) + "\n" + std::string(text);
}

const std::string kVector3 = section("geometry_msgs/Vector3", "float64 x\nfloat64 y\nfloat64 z\n");
const std::string kQuaternion =
    section("geometry_msgs/Quaternion", "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n");

const std::string kImuMsg =
    "std_msgs/Header header\n"
    "geometry_msgs/Quaternion orientation\nfloat64[9] orientation_covariance\n"
    "geometry_msgs/Vector3 angular_velocity\nfloat64[9] angular_velocity_covariance\n"
    "geometry_msgs/Vector3 linear_acceleration\nfloat64[9] linear_acceleration_covariance\n" +
    std::string(dynpos::io::testing::kHeaderDeps) + kQuaternion + kVector3;

const std::string kNavSatFixMsg =
    "std_msgs/Header header\nNavSatStatus status\nfloat64 latitude\nfloat64 longitude\n"
    "float64 altitude\nfloat64[9] position_covariance\nuint8 position_covariance_type\n" +
    std::string(dynpos::io::testing::kHeaderDeps) +
    section("sensor_msgs/NavSatStatus", "int8 status\nuint16 service\n");

const std::string kOdometryMsg =
    "std_msgs/Header header\nstring child_frame_id\n"
    "geometry_msgs/PoseWithCovariance pose\ngeometry_msgs/TwistWithCovariance twist\n" +
    std::string(dynpos::io::testing::kHeaderDeps) +
    section("geometry_msgs/PoseWithCovariance", "Pose pose\nfloat64[36] covariance\n") +
    section("geometry_msgs/Pose", "Point position\nQuaternion orientation\n") +
    section("geometry_msgs/Point", "float64 x\nfloat64 y\nfloat64 z\n") + kQuaternion +
    section("geometry_msgs/TwistWithCovariance", "Twist twist\nfloat64[36] covariance\n") +
    section("geometry_msgs/Twist", "Vector3 linear\nVector3 angular\n") + kVector3;

const std::string kFeedbackMsg =
    "std_msgs/Header header\nfloat64 rpm\nfloat64 pitch_ratio\n"
    "float64 azimuth\nfloat64 power\n" +
    std::string(dynpos::io::testing::kHeaderDeps);
const std::string kCommandMsg = "std_msgs/Header header\nfloat64 rpm\nfloat64 azimuth\n" +
                                std::string(dynpos::io::testing::kHeaderDeps);

constexpr int kThrusters = 4;
constexpr std::int64_t kStart = 1'714'557'600'000'000'000LL;  // 2024-05-01 10:00 UTC
constexpr std::int64_t kStepNs = 10'000'000;                  // 100 Hz

std::uint64_t bag_megabytes() {
  const char* mb = std::getenv("DYNPOS_BAG_BENCH_MB");
  return mb != nullptr ? std::strtoull(mb, nullptr, 10) : 1000;
}

struct BagCounts {
  std::uint64_t uncompressed = 0;
  std::uint64_t messages = 0;
  std::uint64_t imu = 0;  // messages of the most frequent topic
};

// The messages of one 10 ms step, in time order, appended as records to `plain`.
class VesselMessages {
 public:
  void step(std::int64_t k, Bytes& plain, BagCounts& counts) {
    const std::int64_t t = kStart + kStepNs * k;
    add(plain, counts, kImu, t, imu(t));
    ++counts.imu;
    if (k % 5 == 0) add(plain, counts, kOdom, t + 1'000'000, odometry(t));
    if (k % 10 != 0) return;
    add(plain, counts, kGnss, t + 2'000'000, fix(t));
    for (std::uint16_t j = 0; j < kThrusters; ++j) {
      add(plain, counts, static_cast<std::uint16_t>(kFeedback + j), t + 3'000'000, feedback(t, j));
      add(plain, counts, static_cast<std::uint16_t>(kCommand + j), t + 4'000'000, command(t, j));
    }
  }

  static constexpr std::uint16_t kImu = 1, kOdom = 2, kGnss = 3, kFeedback = 4, kCommand = 8;

  // The Statistics record of the messages added: their counts, then per channel.
  Bytes statistics(std::uint64_t messages, std::uint32_t chunks) const {
    Bytes s;
    W::u64(s, messages);
    W::u16(s, 5);  // schemas
    W::u32(s, static_cast<std::uint32_t>(per_channel_.size()));
    W::u32(s, 0);  // attachments
    W::u32(s, 0);  // metadata
    W::u32(s, chunks);
    W::u64(s, static_cast<std::uint64_t>(kStart));
    W::u64(s, static_cast<std::uint64_t>(last_));
    W::u32(s, static_cast<std::uint32_t>(per_channel_.size() * 10));
    for (const auto& [channel, n] : per_channel_) {
      W::u16(s, channel);
      W::u64(s, n);
    }
    return W::record(0x0B, s);
  }

 private:
  double noise(double sigma) { return std::normal_distribution<double>(0.0, sigma)(engine_); }
  static void covariance(CdrWriter& m, int n, double diagonal) {
    const int side = n == 36 ? 6 : 3;
    for (int i = 0; i < n; ++i) m.put(i % (side + 1) == 0 ? diagonal : 0.0);
  }
  Bytes imu(std::int64_t t) {
    CdrWriter m;
    m.header(t, "imu_link");
    for (int i = 0; i < 4; ++i) m.put(0.5 + noise(0.001));
    covariance(m, 9, 1e-4);
    for (int i = 0; i < 3; ++i) m.put(noise(0.01));
    covariance(m, 9, 1e-6);
    for (int i = 0; i < 3; ++i) m.put((i == 2 ? 9.81 : 0.0) + noise(0.05));
    covariance(m, 9, 1e-3);
    return m.bytes();
  }
  Bytes odometry(std::int64_t t) {
    CdrWriter m;
    m.header(t, "odom");
    m.string("base_link");
    for (int i = 0; i < 3; ++i) m.put(100.0 * i + noise(0.1));
    for (int i = 0; i < 4; ++i) m.put(0.5 + noise(0.001));
    covariance(m, 36, 0.01);
    for (int i = 0; i < 6; ++i) m.put(noise(0.05));
    covariance(m, 36, 0.001);
    return m.bytes();
  }
  Bytes fix(std::int64_t t) {
    CdrWriter m;
    m.header(t, "gnss1");
    m.put(std::int8_t{2}).put(std::uint16_t{1});
    m.put(63.4305 + noise(1e-6)).put(10.3951 + noise(1e-6)).put(42.0 + noise(0.05));
    covariance(m, 9, 0.02);
    m.put(std::uint8_t{2});
    return m.bytes();
  }
  Bytes feedback(std::int64_t t, int j) {
    CdrWriter m;
    m.header(t, "thruster" + std::to_string(j + 1));
    m.put(150.0 + noise(2.0))
        .put(0.6 + noise(0.01))
        .put(90.0 * j + noise(0.5))
        .put(300.0 + noise(5.0));
    return m.bytes();
  }
  Bytes command(std::int64_t t, int j) {
    CdrWriter m;
    m.header(t, "thruster" + std::to_string(j + 1));
    m.put(150.0).put(90.0 * j);
    return m.bytes();
  }
  void add(Bytes& plain, BagCounts& counts, std::uint16_t channel, std::int64_t t,
           const Bytes& data) {
    ++per_channel_[channel];
    last_ = std::max(last_, t);
    Bytes r;
    W::u16(r, channel);
    W::u32(r, static_cast<std::uint32_t>(counts.messages++));
    W::u64(r, static_cast<std::uint64_t>(t));
    W::u64(r, static_cast<std::uint64_t>(t));
    W::append(r, data);
    W::append(plain, W::record(0x05, r));
  }

  std::mt19937_64 engine_{7};
  std::map<std::uint16_t, std::uint64_t> per_channel_;  // messages added
  std::int64_t last_ = kStart;                          // the latest time added
};

void put(std::FILE* f, const Bytes& b) {
  if (std::fwrite(b.data(), 1, b.size(), f) != b.size()) throw std::runtime_error("disk full?");
}

// The schemas' and channels' records.
Bytes definitions() {
  Bytes out;
  const auto schema = [&](std::uint16_t id, std::string_view name, const std::string& text) {
    Bytes s;
    W::u16(s, id);
    W::str(s, name);
    W::str(s, "ros2msg");
    W::str(s, text);
    W::append(out, W::record(0x03, s));
  };
  const auto channel = [&](std::uint16_t id, std::uint16_t schema_id, const std::string& topic) {
    Bytes c;
    W::u16(c, id);
    W::u16(c, schema_id);
    W::str(c, topic);
    W::str(c, "cdr");
    W::u32(c, 0);
    W::append(out, W::record(0x04, c));
  };
  schema(1, "sensor_msgs/msg/Imu", kImuMsg);
  schema(2, "nav_msgs/msg/Odometry", kOdometryMsg);
  schema(3, "sensor_msgs/msg/NavSatFix", kNavSatFixMsg);
  schema(4, "dp_msgs/msg/ThrusterFeedback", kFeedbackMsg);
  schema(5, "dp_msgs/msg/ThrusterCommand", kCommandMsg);
  channel(VesselMessages::kImu, 1, "/imu");
  channel(VesselMessages::kOdom, 2, "/odom");
  channel(VesselMessages::kGnss, 3, "/gnss/fix");
  for (std::uint16_t j = 0; j < kThrusters; ++j) {
    const std::string name = "/thrusters/t" + std::to_string(j + 1);
    channel(static_cast<std::uint16_t>(VesselMessages::kFeedback + j), 4, name + "/feedback");
    channel(static_cast<std::uint16_t>(VesselMessages::kCommand + j), 5, name + "/command");
  }
  return out;
}

// The chunk record of `plain` and its ChunkIndex record (the chunk at `offset`).
std::pair<Bytes, Bytes> chunk_records(const Bytes& plain, std::uint64_t t0, std::uint64_t t1,
                                      std::uint64_t offset) {
  Bytes packed(ZSTD_compressBound(plain.size()));
  packed.resize(ZSTD_compress(packed.data(), packed.size(), plain.data(), plain.size(), 1));
  Bytes c;
  W::u64(c, t0);
  W::u64(c, t1);
  W::u64(c, plain.size());
  W::u32(c, dynpos::io::testing::test_crc32(plain));
  W::str(c, "zstd");
  W::u64(c, packed.size());
  W::append(c, packed);
  Bytes chunk = W::record(0x06, c);
  Bytes i;
  W::u64(i, t0);
  W::u64(i, t1);
  W::u64(i, offset);
  W::u64(i, chunk.size());
  constexpr std::uint16_t kChannels = VesselMessages::kCommand + kThrusters - 1;
  W::u32(i, 10U * kChannels);
  for (std::uint16_t id = 1; id <= kChannels; ++id) {
    W::u16(i, id);
    W::u64(i, 0);
  }
  W::u64(i, 0);
  W::str(i, "zstd");
  W::u64(i, packed.size());
  W::u64(i, plain.size());
  return {std::move(chunk), W::record(0x08, i)};
}

std::filesystem::path bag_path() {
  return std::filesystem::temp_directory_path() /
         ("dynpos_bench_vessel_stats_" + std::to_string(bag_megabytes()) + "MB.mcap");
}

// Writes the bag chunk by chunk with a summary; returns its counts.
BagCounts write_vessel_bag(const std::filesystem::path& path) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) throw std::runtime_error("cannot write " + path.string());
  Bytes head = {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};
  Bytes h;
  W::str(h, "ros2");
  W::str(h, "dynpos bench");
  W::append(head, W::record(0x01, h));
  put(f, head);
  std::uint64_t offset = head.size();
  const Bytes defs = definitions();
  Bytes indexes;
  BagCounts counts;
  VesselMessages messages;
  std::int64_t k = 0;
  std::uint32_t chunks = 0;
  while (offset < bag_megabytes() * 1'000'000) {
    Bytes plain;
    if (k == 0) W::append(plain, defs);
    const auto t0 = static_cast<std::uint64_t>(kStart + kStepNs * k);
    while (plain.size() < (1U << 20)) messages.step(k++, plain, counts);
    const auto t1 = static_cast<std::uint64_t>(kStart + kStepNs * k);
    const auto [chunk, index] = chunk_records(plain, t0, t1, offset);
    put(f, chunk);
    W::append(indexes, index);
    ++chunks;
    offset += chunk.size();
    counts.uncompressed += plain.size();
  }
  Bytes tail;
  Bytes end;
  W::u32(end, 0);
  W::append(tail, W::record(0x0F, end));
  const std::uint64_t summary = offset + tail.size();
  W::append(tail, defs);
  W::append(tail, indexes);
  W::append(tail, messages.statistics(counts.messages, chunks));
  Bytes footer;
  W::u64(footer, summary);
  W::u64(footer, 0);
  W::u32(footer, 0);
  W::append(tail, W::record(0x02, footer));
  W::append(tail, Bytes{0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'});
  put(f, tail);
  std::fclose(f);
  return counts;
}

// The bag, written unless a kept one is there; its counts.
const BagCounts& vessel_bag() {
  static const BagCounts counts = [] {
    const std::filesystem::path path = bag_path();
    const std::filesystem::path side = path.string() + ".counts";
    BagCounts c;
    if (std::filesystem::exists(path) &&
        std::ifstream(side) >> c.uncompressed >> c.messages >> c.imu) {
      return c;
    }
    c = write_vessel_bag(path);
    std::ofstream(side) << c.uncompressed << ' ' << c.messages << ' ' << c.imu << '\n';
    return c;
  }();
  return counts;
}

// The process' processor time so far (user + system, every thread) [s].
double cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
  };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

dynpos::io::ColumnMap vessel_map() {
  dynpos::io::ColumnMap map;
  map.set_column("time", "time");
  map.set_column("gnss1.lat", "/gnss/fix.latitude");
  map.set_column("gnss1.lon", "/gnss/fix.longitude");
  map.set_column("gnss1.height", "/gnss/fix.altitude");
  map.set_column("r", "/imu.angular_velocity.z");
  map.set_column("mru1.ax", "/imu.linear_acceleration.x");
  map.set_column("mru1.ay", "/imu.linear_acceleration.y");
  map.set_column("u", "/odom.twist.twist.linear.x");
  map.set_column("v", "/odom.twist.twist.linear.y");
  for (int j = 1; j <= kThrusters; ++j) {
    const std::string topic = "/thrusters/t" + std::to_string(j) + "/feedback";
    map.set_column("rpm.t" + std::to_string(j), topic + ".rpm");
    map.set_column("azimuth.t" + std::to_string(j), topic + ".azimuth");
  }
  return map;
}

// What `identify station-keeping` reads of the bag: the position (the GNSS fix's latitude and
// longitude) and the thrusters' power, with the IMU's yaw rate at 100 Hz where a recording with
// a gyro compass would have its heading (the bag has none; a 100 Hz heading takes as much).
dynpos::io::ColumnMap station_keeping_map() {
  dynpos::io::ColumnMap map;
  map.set_column("time", "time");
  map.set_column("lat", "/gnss/fix.latitude");
  map.set_column("lon", "/gnss/fix.longitude");
  map.set_column("r", "/imu.angular_velocity.z");
  for (int j = 1; j <= kThrusters; ++j) {
    map.set_column("power.t" + std::to_string(j),
                   "/thrusters/t" + std::to_string(j) + "/feedback.power");
  }
  return map;
}

// The bytes of the columns read: each topic's time axis and its roles, 8 bytes a value.
double column_bytes(const dynpos::io::FileLog& log) {
  double bytes = 0;
  const auto add = [&](const dynpos::io::FileLog& f) {
    bytes += 8.0 * static_cast<double>(f.log.size()) *
             static_cast<double>(1 + f.log.channel_names().size());
  };
  add(log);
  for (const auto& more : log.more) add(more);
  return bytes;
}

// The process' resident memory now and at its peak since reset_peak_memory() [bytes], from
// /proc/self/status (VmRSS, VmHWM); the peak from getrusage where there is no /proc (it cannot
// be reset there: the peak of the whole process).
struct Memory {
  double now = 0;
  double peak = 0;
};
Memory memory() {
  Memory m;
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    const auto kb = [&line] { return 1024.0 * std::strtod(line.c_str() + 6, nullptr); };
    if (line.starts_with("VmRSS:")) m.now = kb();
    if (line.starts_with("VmHWM:")) m.peak = kb();
  }
  if (m.peak == 0) {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    m.peak = static_cast<double>(usage.ru_maxrss) * 1024.0;
  }
  return m;
}
// Sets the peak resident memory to the memory now (Linux: clear_refs 5).
void reset_peak_memory() { std::ofstream("/proc/self/clear_refs") << "5\n"; }

// Reads the vessel bag with `map` on state.range(0) threads.
void read_vessel_bag(benchmark::State& state, const dynpos::io::ColumnMap& map) {
  const BagCounts& counts = vessel_bag();
  const std::filesystem::path path = bag_path();
  const auto jobs = static_cast<unsigned>(state.range(0));
  std::size_t rows = 0;
  double columns = 0;
  reset_peak_memory();
  const Memory before = memory();
  const double cpu_before = cpu_seconds();
  for (auto _ : state) {
    const dynpos::io::FileLog log =
        dynpos::io::read_bag_file(path, map, dynpos::io::BagTime::kAuto, jobs);
    rows = log.log.size();
    columns = column_bytes(log);
    benchmark::DoNotOptimize(rows);
  }
  const double cpu = cpu_seconds() - cpu_before;
  const Memory after = memory();
  if (rows != counts.imu) state.SkipWithError("not every message was read");
  const auto iterations = static_cast<double>(state.iterations());
  const auto file_bytes = static_cast<std::int64_t>(std::filesystem::file_size(path));
  state.SetBytesProcessed(file_bytes * state.iterations());
  state.counters["uncompressed_B/s"] = benchmark::Counter(
      static_cast<double>(counts.uncompressed) * iterations, benchmark::Counter::kIsRate);
  state.counters["messages/s"] = benchmark::Counter(
      static_cast<double>(counts.messages) * iterations, benchmark::Counter::kIsRate);
  state.counters["peak_MB"] = after.peak / 1e6;
  state.counters["columns_MB"] = columns / 1e6;
  state.counters["reader_MB"] = (after.peak - columns) / 1e6;
  state.counters["start_MB"] = before.now / 1e6;
  state.counters["file_MB"] = static_cast<double>(file_bytes) / 1e6;
  state.counters["cpu_s/GB"] = cpu / iterations / (static_cast<double>(file_bytes) / 1e9);
  state.counters["ratio"] =
      static_cast<double>(counts.uncompressed) / static_cast<double>(file_bytes);
}

void BM_ReadVesselBag(benchmark::State& state) { read_vessel_bag(state, vessel_map()); }
BENCHMARK(BM_ReadVesselBag)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

void BM_ReadStationKeeping(benchmark::State& state) {
  read_vessel_bag(state, station_keeping_map());
}
BENCHMARK(BM_ReadStationKeeping)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  if (std::getenv("DYNPOS_BENCH_KEEP_BAG") == nullptr) {
    std::filesystem::remove(bag_path());
    std::filesystem::remove(bag_path().string() + ".counts");
  }
  return 0;
}
