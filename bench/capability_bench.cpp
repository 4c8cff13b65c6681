// DP capability of the virtual Gunnerus (built-in vessel parameters). Targets: a level-1 rose
// (36 directions) with all five single failures and the worst case in < 1 s; a level-3 rose
// (36 directions, time-domain runs of 300 s + 1200 s judged, the default) in < 5 min on 2 cores.

#include <benchmark/benchmark.h>

#include <thread>

#include "dynpos/capability/quasi_static.hpp"
#include "dynpos/capability/time_domain.hpp"

namespace {

using namespace dynpos::capability;

// Level 1 (range 1) or 2: intact, every single failure and the worst case per direction.
void BM_QuasiStaticWithFailures(benchmark::State& state) {
  const dynpos::scenario::VesselConfig vessel;
  QuasiStaticOptions o;
  o.level = static_cast<int>(state.range(0));
  int lowest = 99;
  for (auto _ : state) {
    std::vector<std::vector<CapabilityPoint>> roses = {quasi_static_rose(vessel, {}, o)};
    for (const auto& f : single_failures()) roses.push_back(quasi_static_rose(vessel, {f}, o));
    const auto worst = worst_case(roses);
    for (const auto& p : roses.front()) lowest = std::min(lowest, p.dp_number);
    benchmark::DoNotOptimize(worst.data());
  }
  state.counters["intact_lowest_dp"] = lowest;
}
BENCHMARK(BM_QuasiStaticWithFailures)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

// Level 3, intact, 36 directions on every core (range: the judged run length [s]).
void BM_TimeDomainRose(benchmark::State& state) {
  const dynpos::scenario::VesselConfig vessel;
  TimeDomainOptions o;
  o.duration_s = static_cast<double>(state.range(0));
  int lowest = 99;
  for (auto _ : state) {
    const auto rose = time_domain_rose(vessel, {}, o);
    for (const auto& p : rose) lowest = std::min(lowest, p.dp_number);
  }
  state.counters["intact_lowest_dp"] = lowest;
  state.counters["cores"] = std::thread::hardware_concurrency();
}
BENCHMARK(BM_TimeDomainRose)->Arg(1200)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
