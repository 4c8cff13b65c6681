// Log::resample cost: a 100 Hz log with a 1 Hz channel resampled onto a 10 Hz axis.
// Linear in rows + targets; compare the per-item time across sizes.

#include <benchmark/benchmark.h>

#include <vector>

#include "dynpos/core/log.hpp"

namespace {

dynpos::core::Log make_log(std::size_t rows) {
  std::vector<double> t(rows);
  std::vector<double> fast(rows);
  std::vector<double> slow(rows, dynpos::core::kMissing);
  for (std::size_t i = 0; i < rows; ++i) {
    t[i] = 0.01 * static_cast<double>(i);
    fast[i] = static_cast<double>(i % 1000);
    if (i % 100 == 0) slow[i] = static_cast<double>(i);
  }
  dynpos::core::Log log(t);
  log.add_channel("fast", "m", fast);
  log.add_channel("slow", "m", slow);
  return log;
}

void BM_LogResample(benchmark::State& state) {
  const auto rows = static_cast<std::size_t>(state.range(0));
  const dynpos::core::Log log = make_log(rows);
  std::vector<double> target(rows / 10);
  for (std::size_t i = 0; i < target.size(); ++i) target[i] = 0.1 * static_cast<double>(i) + 0.05;
  for (auto _ : state) {
    benchmark::DoNotOptimize(log.resample(target));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * (rows + target.size())));
}
BENCHMARK(BM_LogResample)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
