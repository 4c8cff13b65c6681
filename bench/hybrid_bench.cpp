// The DP case study of thesis section 5.3.2: 60 s of the closed loop (plant, backstepping
// controller, hybrid integral action) at dt = 1 ms with RK4, every tick checked against the jump
// set and measured, a trace row every 10 ms. Target: one run (the ideal jump set) in < 50 ms.
// Also the conventional and sampled variants and the first-order case study for comparison.

#include <benchmark/benchmark.h>

#include "dynpos/hybrid/case_study.hpp"

namespace {

using dynpos::hybrid::JumpSet;

void BM_DpCase(benchmark::State& state) {
  dynpos::hybrid::DpCaseOptions options;
  options.params.jump_set = static_cast<JumpSet>(state.range(0));
  int jumps = 0;
  for (auto _ : state) {
    const dynpos::hybrid::CaseResult r = dynpos::hybrid::run_dp_case(options);
    jumps = r.metrics.jumps;
    benchmark::DoNotOptimize(r.trace.t.data());
  }
  state.SetLabel(to_string(options.params.jump_set));
  state.counters["jumps"] = jumps;
  state.counters["x_realtime"] =
      benchmark::Counter(options.timing.end_time_s * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}
BENCHMARK(BM_DpCase)
    ->Arg(static_cast<int>(JumpSet::kIdeal))
    ->Arg(static_cast<int>(JumpSet::kNone))
    ->Arg(static_cast<int>(JumpSet::kSampled))
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_FirstOrderCase(benchmark::State& state) {
  dynpos::hybrid::FirstOrderCaseOptions options;
  options.params.jump_set = static_cast<JumpSet>(state.range(0));
  for (auto _ : state) {
    const dynpos::hybrid::CaseResult r = dynpos::hybrid::run_first_order_case(options);
    benchmark::DoNotOptimize(r.trace.t.data());
  }
  state.SetLabel(to_string(options.params.jump_set));
}
BENCHMARK(BM_FirstOrderCase)
    ->Arg(static_cast<int>(JumpSet::kIdeal))
    ->Arg(static_cast<int>(JumpSet::kSampled))
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
