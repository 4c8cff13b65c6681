// Reading a ROS 2 bag: 3 fields (and header.stamp) of an IMU topic from a chunked zstd MCAP file
// of about 100 MB (DYNPOS_BAG_BENCH_MB sets the size), as `--col ROLE=/imu.FIELD` reads it.
// Wall-clock time; bytes/s are of the whole file (the compressed bytes on disk), and the
// counters give the decompressed rate, the messages per second and the process' peak memory.
// The product goal: ≥ 300 MB/s on 2 cores, peak memory ≤ 256 MB for a 1 GB file.
//
// The file is written once into the temporary folder, one chunk at a time, and removed at the
// end unless DYNPOS_BENCH_KEEP_BAG is set.

#include <benchmark/benchmark.h>
#include <sys/resource.h>
#include <zstd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>

#include "../tests/io/mcap_test_writer.hpp"
#include "dynpos/io/bag_log.hpp"

namespace {

using dynpos::io::testing::Bytes;
using dynpos::io::testing::CdrWriter;
using W = dynpos::io::testing::McapWriter;

const std::string kImuMsg =
    "std_msgs/Header header\n"
    "geometry_msgs/Quaternion orientation\nfloat64[9] orientation_covariance\n"
    "geometry_msgs/Vector3 angular_velocity\nfloat64[9] angular_velocity_covariance\n"
    "geometry_msgs/Vector3 linear_acceleration\nfloat64[9] linear_acceleration_covariance\n" +
    std::string(dynpos::io::testing::kHeaderDeps) +
    "================================================================================\n"
    "MSG: geometry_msgs/Quaternion\nfloat64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n"
    "================================================================================\n"
    "MSG: geometry_msgs/Vector3\nfloat64 x\nfloat64 y\nfloat64 z\n";

std::uint64_t bag_megabytes() {
  const char* mb = std::getenv("DYNPOS_BAG_BENCH_MB");
  return mb != nullptr ? std::strtoull(mb, nullptr, 10) : 100;
}

// One IMU message at `k` (100 Hz): noisy measurements, constant covariances.
Bytes imu_message(std::int64_t k, std::mt19937_64& engine) {
  std::normal_distribution<double> noise(0.0, 0.01);
  CdrWriter m;
  m.header(1'714'557'600'000'000'000LL + 10'000'000LL * k, "imu_link");
  for (int i = 0; i < 4; ++i) m.put(0.5 + noise(engine));
  for (int i = 0; i < 9; ++i) m.put(i % 4 == 0 ? 1e-4 : 0.0);
  for (int i = 0; i < 3; ++i) m.put(noise(engine));
  for (int i = 0; i < 9; ++i) m.put(i % 4 == 0 ? 1e-6 : 0.0);
  for (int i = 0; i < 3; ++i) m.put((i == 2 ? 9.81 : 0.0) + noise(engine));
  for (int i = 0; i < 9; ++i) m.put(i % 4 == 0 ? 1e-3 : 0.0);
  return m.bytes();
}

void put(std::FILE* f, const Bytes& b) { std::fwrite(b.data(), 1, b.size(), f); }

std::uint64_t g_uncompressed = 0;
std::uint64_t g_messages = 0;

// Writes the bag chunk by chunk (1 MiB of records each, zstd level 1) with a summary.
std::filesystem::path imu_bag() {
  const auto path = std::filesystem::temp_directory_path() /
                    ("dynpos_bench_imu_" + std::to_string(bag_megabytes()) + "MB.mcap");
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) throw std::runtime_error("cannot write " + path.string());
  Bytes head = {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};
  Bytes h;
  W::str(h, "ros2");
  W::str(h, "dynpos bench");
  W::append(head, W::record(0x01, h));
  put(f, head);
  std::uint64_t offset = head.size();
  Bytes schema, channel, indexes;
  W::u16(schema, 1);
  W::str(schema, "sensor_msgs/msg/Imu");
  W::str(schema, "ros2msg");
  W::str(schema, kImuMsg);
  W::u16(channel, 1);
  W::u16(channel, 1);
  W::str(channel, "/imu");
  W::str(channel, "cdr");
  W::u32(channel, 0);
  std::mt19937_64 engine(7);
  Bytes packed;
  std::int64_t k = 0;
  while (offset < bag_megabytes() << 20) {
    Bytes plain;
    if (k == 0) {
      W::append(plain, W::record(0x03, schema));
      W::append(plain, W::record(0x04, channel));
    }
    const std::uint64_t t0 = static_cast<std::uint64_t>(k);
    while (plain.size() < (1U << 20)) {
      Bytes m;
      W::u16(m, 1);
      W::u32(m, static_cast<std::uint32_t>(k));
      W::u64(m, static_cast<std::uint64_t>(k));
      W::u64(m, static_cast<std::uint64_t>(k));
      W::append(m, imu_message(k++, engine));
      W::append(plain, W::record(0x05, m));
    }
    packed.resize(ZSTD_compressBound(plain.size()));
    packed.resize(ZSTD_compress(packed.data(), packed.size(), plain.data(), plain.size(), 1));
    Bytes c;
    W::u64(c, t0);
    W::u64(c, static_cast<std::uint64_t>(k));
    W::u64(c, plain.size());
    W::u32(c, dynpos::io::testing::test_crc32(plain));
    W::str(c, "zstd");
    W::u64(c, packed.size());
    W::append(c, packed);
    const Bytes chunk = W::record(0x06, c);
    put(f, chunk);
    Bytes i;
    W::u64(i, t0);
    W::u64(i, static_cast<std::uint64_t>(k));
    W::u64(i, offset);
    W::u64(i, chunk.size());
    W::u32(i, 10);
    W::u16(i, 1);
    W::u64(i, 0);
    W::u64(i, 0);
    W::str(i, "zstd");
    W::u64(i, packed.size());
    W::u64(i, plain.size());
    W::append(indexes, W::record(0x08, i));
    offset += chunk.size();
    g_uncompressed += plain.size();
  }
  g_messages = static_cast<std::uint64_t>(k);
  Bytes tail;
  Bytes end;
  W::u32(end, 0);
  W::append(tail, W::record(0x0F, end));
  const std::uint64_t summary = offset + tail.size();
  W::append(tail, W::record(0x03, schema));
  W::append(tail, W::record(0x04, channel));
  W::append(tail, indexes);
  Bytes footer;
  W::u64(footer, summary);
  W::u64(footer, 0);
  W::u32(footer, 0);
  W::append(tail, W::record(0x02, footer));
  W::append(tail, Bytes{0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'});
  put(f, tail);
  std::fclose(f);
  return path;
}

void BM_ReadImuBag(benchmark::State& state) {
  static const std::filesystem::path path = imu_bag();
  dynpos::io::ColumnMap map;
  map.set_column("time", "time");
  map.set_column("r", "/imu.angular_velocity.z");
  map.set_column("input", "/imu.linear_acceleration.x");
  map.set_column("output", "/imu.orientation_covariance[8]");
  std::size_t rows = 0;
  for (auto _ : state) {
    const dynpos::io::FileLog log =
        dynpos::io::read_bag_file(path, map, dynpos::io::BagTime::kAuto);
    rows = log.log.size();
    benchmark::DoNotOptimize(rows);
  }
  if (rows != g_messages) state.SkipWithError("not every message was read");
  const auto iterations = static_cast<double>(state.iterations());
  state.SetBytesProcessed(static_cast<std::int64_t>(std::filesystem::file_size(path)) *
                          state.iterations());
  state.counters["uncompressed_B/s"] = benchmark::Counter(
      static_cast<double>(g_uncompressed) * iterations, benchmark::Counter::kIsRate);
  state.counters["messages/s"] =
      benchmark::Counter(static_cast<double>(g_messages) * iterations, benchmark::Counter::kIsRate);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  state.counters["peak_MB"] = static_cast<double>(usage.ru_maxrss) / 1024.0;
  state.counters["file_MB"] = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
  if (std::getenv("DYNPOS_BENCH_KEEP_BAG") == nullptr) std::filesystem::remove(path);
}
BENCHMARK(BM_ReadImuBag)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
