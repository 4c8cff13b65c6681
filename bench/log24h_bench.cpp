// A day of logging: step detection and FOPDT fits over a 24 h log at 100 Hz (8 640 000 samples)
// with a command and two responses, in memory and from a CSV file (parsing included). The
// product goal is under 5 s on one core, with memory bounded by the columns in use.
//
// The log: a command stepping every 300 s through a cycle of levels (288 steps), a fast response
// (T = 1.5 s, δ = 1.2 s: a shaft speed) and a slow one (T = 40 s, δ = 3 s: a surge speed), each
// a first-order lag with dead time (3.7) plus seeded Gaussian noise.
//
// The CSV cases write the file once (outside the timing) into the temporary folder: time, the
// three channels, and optionally unused filler columns, as a logger with many sensors would. The
// file is removed afterwards unless DYNPOS_BENCH_KEEP_CSV is set (to run the CLI on it).

#include <benchmark/benchmark.h>
#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iterator>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynpos/core/log.hpp"
#include "dynpos/ident/fopdt_fit.hpp"
#include "dynpos/ident/step_detector.hpp"
#include "dynpos/io/column_map.hpp"
#include "dynpos/io/csv_reader.hpp"

namespace {

constexpr double kDt = 0.01;           // 100 Hz
constexpr std::size_t kN = 8'640'000;  // 24 h
constexpr double kStepPeriod = 300.0;  // [s] between command steps

struct DayLog {
  std::vector<double> t, u, y_fast, y_slow;
};

// A first-order lag with dead time driven by u: y(k+1) = a·y(k) + (1 − a)·K·u(k − D), the exact
// discretisation of T·ẏ + y = K·u(t − δ) for a piecewise-constant input.
std::vector<double> fopdt_response(const std::vector<double>& u, double gain, double T,
                                   double delay, double noise, std::mt19937_64& engine) {
  const double a = std::exp(-kDt / T);
  const auto lag = static_cast<std::size_t>(std::lround(delay / kDt));
  std::normal_distribution<double> n(0.0, noise);
  std::vector<double> y(u.size());
  double state = gain * u[0];
  for (std::size_t k = 0; k < u.size(); ++k) {
    y[k] = state + n(engine);
    const double input = u[k >= lag ? k - lag : 0];
    state = a * state + (1.0 - a) * gain * input;
  }
  return y;
}

DayLog make_day() {
  static const double kLevels[] = {0.0, 2.0, 5.0, 3.0, 8.0, 1.0};
  DayLog d;
  d.t.resize(kN);
  d.u.resize(kN);
  for (std::size_t k = 0; k < kN; ++k) {
    d.t[k] = kDt * static_cast<double>(k);
    const auto cycle = static_cast<std::size_t>((d.t[k] + 0.5 * kDt) / kStepPeriod);
    d.u[k] = kLevels[cycle % std::size(kLevels)];
  }
  std::mt19937_64 engine(2014);
  d.y_fast = fopdt_response(d.u, 1.0, 1.5, 1.2, 0.02, engine);
  d.y_slow = fopdt_response(d.u, 0.4, 40.0, 3.0, 0.01, engine);
  return d;
}

const DayLog& day() {
  static const DayLog d = make_day();
  return d;
}

// Detection on the command, then one fit per step and response. Returns the number of fits.
std::size_t identify_day(const std::vector<double>& t, const std::vector<double>& u,
                         const std::vector<double>& y_fast, const std::vector<double>& y_slow,
                         dynpos::ident::FopdtMethod method) {
  dynpos::ident::FopdtFitOptions f;
  f.method = method;
  const auto steps = dynpos::ident::detect_steps(t, u).steps;
  std::size_t fits = 0;
  for (const auto& step : steps) {
    const auto a = dynpos::ident::fit_fopdt(t, y_fast, step, f);
    const auto b = dynpos::ident::fit_fopdt(t, y_slow, step, f);
    fits += (a.time_constant ? 1 : 0) + (b.time_constant ? 1 : 0);
  }
  return fits;
}

void BM_Day24hInMemory(benchmark::State& state) {
  const DayLog& d = day();
  const auto method = state.range(0) == 0 ? dynpos::ident::FopdtMethod::kSmith
                                          : dynpos::ident::FopdtMethod::kLeastSquares;
  std::size_t fits = 0;
  for (auto _ : state) {
    fits = identify_day(d.t, d.u, d.y_fast, d.y_slow, method);
    benchmark::DoNotOptimize(fits);
  }
  state.counters["fits"] = static_cast<double>(fits);
  state.SetLabel(state.range(0) == 0 ? "smith" : "lsq");
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kN));
}
BENCHMARK(BM_Day24hInMemory)->Arg(0)->Arg(1)->Unit(benchmark::kSecond)->Iterations(2);

std::filesystem::path write_day_csv(std::size_t filler_columns) {
  const auto path = std::filesystem::temp_directory_path() /
                    fmt::format("dynpos_bench_day_{}cols.csv", 4 + filler_columns);
  const DayLog& d = day();
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (f == nullptr) throw std::runtime_error("cannot write " + path.string());
  std::string line = "time [s],command [1],fast [1],slow [m/s]";
  for (std::size_t c = 0; c < filler_columns; ++c) line += fmt::format(",aux{} [1]", c);
  line += '\n';
  std::fputs(line.c_str(), f);
  for (std::size_t k = 0; k < kN; ++k) {
    line = fmt::format("{:.2f},{:g},{:.4f},{:.4f}", d.t[k], d.u[k], d.y_fast[k], d.y_slow[k]);
    // Filler: a slowly varying number of realistic width in every unused column.
    for (std::size_t c = 0; c < filler_columns; ++c) {
      line += fmt::format(",{:.3f}", d.y_slow[k] + static_cast<double>(c));
    }
    line += '\n';
    std::fputs(line.c_str(), f);
  }
  std::fclose(f);
  return path;
}

void BM_Day24hCsv(benchmark::State& state) {
  const auto filler = static_cast<std::size_t>(state.range(0));
  const std::filesystem::path path = write_day_csv(filler);
  dynpos::io::ColumnMap map;
  map.set_column("time", "time");
  map.set_column("input", "command");
  map.set_column("output", "fast");  // a generic response
  map.set_column("u", "slow");       // a surge speed
  std::size_t fits = 0;
  double read_s = 0.0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const dynpos::core::Log log = dynpos::io::read_csv(path, map);
    read_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    fits = identify_day(log.time(), log.values("input"), log.values("output"), log.values("u"),
                        dynpos::ident::FopdtMethod::kLeastSquares);
    benchmark::DoNotOptimize(fits);
  }
  state.counters["fits"] = static_cast<double>(fits);
  state.counters["csv_read_s"] = read_s / static_cast<double>(state.iterations());
  state.counters["file_MB"] = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
  state.SetLabel(fmt::format("{} columns, 4 read, lsq", 4 + filler));
  if (std::getenv("DYNPOS_BENCH_KEEP_CSV") == nullptr) std::filesystem::remove(path);
}
BENCHMARK(BM_Day24hCsv)->Arg(0)->Arg(56)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
