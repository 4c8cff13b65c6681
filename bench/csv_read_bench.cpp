// Reading a wide log: 3 mapped columns (time and two channels) of a 12-column, 1 GB CSV of 8.64 M
// rows (24 h at 100 Hz), on 1 and on 2 threads (`CsvReadOptions::jobs`). Wall-clock time, as a
// user waits for it; bytes/s are of the whole file. The product goal (docs/performance.md):
// ≥ 350 MB/s on one core, ≥ 600 MB/s on two.
//
// The file is written once into the temporary folder (about 30 s) and kept for later runs, and
// for the side-by-side runs of bench/python/read_columns.py, if DYNPOS_BENCH_KEEP_CSV is set;
// otherwise it is removed at the end.

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>

#include "dynpos/core/log.hpp"
#include "dynpos/io/column_map.hpp"
#include "dynpos/io/csv_reader.hpp"

namespace {

constexpr std::size_t kRows = 8'640'000;  // 24 h at 100 Hz
constexpr int kColumns = 12;

std::filesystem::path wide_csv() {
  const auto path = std::filesystem::temp_directory_path() / "dynpos_bench_wide_12cols.csv";
  if (std::filesystem::exists(path)) return path;
  const auto partial = path.string() + ".part";
  std::FILE* f = std::fopen(partial.c_str(), "w");
  if (f == nullptr) throw std::runtime_error("cannot write " + partial);
  std::string line = "time [s]";
  for (int c = 1; c < kColumns; ++c) line += fmt::format(",sensor{} [1]", c);
  line += '\n';
  std::fputs(line.c_str(), f);
  std::mt19937_64 engine(26);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (std::size_t k = 0; k < kRows; ++k) {
    line = fmt::format("{:.2f}", 0.01 * static_cast<double>(k));
    for (int c = 1; c < kColumns; ++c) {
      // Realistic widths: a slow signal plus noise, 4 decimals, some negative.
      const double value = 100.0 * std::sin(1e-5 * static_cast<double>(k) * c) + noise(engine);
      fmt::format_to(std::back_inserter(line), ",{:.4f}", value);
    }
    line += '\n';
    std::fputs(line.c_str(), f);
  }
  std::fclose(f);
  std::filesystem::rename(partial, path);
  return path;
}

void BM_ReadThreeOfTwelve(benchmark::State& state) {
  const std::filesystem::path path = wide_csv();
  dynpos::io::ColumnMap map;
  map.set_column("time", "time");
  map.set_column("input", "sensor3");
  map.set_column("output", "sensor8");
  dynpos::io::CsvReadOptions options;
  options.jobs = static_cast<unsigned>(state.range(0));
  std::size_t rows = 0;
  for (auto _ : state) {
    const dynpos::core::Log log = dynpos::io::read_csv(path, map, options);
    rows = log.size();
    benchmark::DoNotOptimize(log.values("output").data());
  }
  const auto bytes = static_cast<std::int64_t>(std::filesystem::file_size(path));
  state.SetBytesProcessed(state.iterations() * bytes);
  state.counters["rows"] = static_cast<double>(rows);
  state.counters["file_MB"] = static_cast<double>(bytes) / 1e6;
  state.SetLabel(fmt::format("{} thread{}", options.jobs, options.jobs == 1 ? "" : "s"));
}
BENCHMARK(BM_ReadThreeOfTwelve)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kSecond)
    ->Iterations(3)
    ->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  if (std::getenv("DYNPOS_BENCH_KEEP_CSV") == nullptr) {
    std::filesystem::remove(std::filesystem::temp_directory_path() /
                            "dynpos_bench_wide_12cols.csv");
  }
  return 0;
}
