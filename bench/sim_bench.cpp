// The full virtual Gunnerus: hull with roll/pitch, 2 propellers, 2 rudders, tunnel thruster,
// allocation at 10 Hz, current, gusty wind, Gauss–Markov bias and 60 wave components, RK4 at
// dt = 0.01 s; the truth log (33 channels) and the trial logger (every sensor at its rate, 64
// channels) both at 100 Hz. Target: 1 h of simulation in < 1.8 s (≥ 2000×
// real time) on one core. The "x_realtime" counter is simulated seconds per wall second.

#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>
#include <vector>

#include "dynpos/scenario/runner.hpp"
#include "dynpos/scenario/scenario_spec.hpp"

namespace {

dynpos::scenario::ScenarioSpec full_model_hour(double duration_s) {
  dynpos::scenario::ScenarioSpec s;
  s.name = "bench-full-model";
  s.duration_s = duration_s;
  s.dt_s = 0.01;
  s.log_rate_hz = 100.0;
  s.environment.current_speed_mps = 0.3;
  s.environment.current_to_deg = 45.0;
  s.environment.wind_speed_mps = 10.0;
  s.environment.wind_from_deg = 30.0;
  s.environment.hs_m = 2.0;
  s.environment.tp_s = 7.0;
  s.environment.wave_from_deg = 20.0;
  s.environment.wave_components = 60;
  // A joystick programme that keeps every actuator busy.
  for (int k = 0; k < 12; ++k) {
    const double t = 10.0 + k * duration_s / 12.0;
    s.joystick.push_back(
        {t, 40.0 - 10.0 * (k % 4), 30.0 * ((k % 3) - 1), 10.0 * ((k % 2) * 2 - 1)});
  }
  return s;
}

void BM_FullModel(benchmark::State& state) {
  const double duration = static_cast<double>(state.range(0));
  const dynpos::scenario::ScenarioSpec spec = full_model_hour(duration);
  const dynpos::scenario::VesselConfig vessel;
  std::size_t rows = 0;
  for (auto _ : state) {
    const dynpos::scenario::ScenarioRun run = dynpos::scenario::run_scenario(spec, vessel, 1);
    rows = run.log.size();
    benchmark::DoNotOptimize(run.log.time().data());
  }
  state.counters["rows"] = static_cast<double>(rows);
  state.counters["x_realtime"] = benchmark::Counter(
      duration * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FullModel)->Arg(600)->Arg(3600)->Unit(benchmark::kMillisecond)->UseRealTime();
// The same hour as the first run of a fresh process (what `dynpos simulate` costs): run it alone,
// `--benchmark_filter=BM_FullModelCold`, so that no earlier run has warmed the allocator.
BENCHMARK(BM_FullModel)
    ->Name("BM_FullModelCold")
    ->Arg(3600)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The same hour as `dynpos simulate` runs it: the rows handed on every kRunBlockRows rows
// (stream_scenario) and the block's memory reused, here to a sink that only reads them. Run it
// alone, `--benchmark_filter=BM_FullModelStreamedCold`, for a cold process.
void BM_FullModelStreamed(benchmark::State& state) {
  const dynpos::scenario::ScenarioSpec spec = full_model_hour(static_cast<double>(state.range(0)));
  const dynpos::scenario::VesselConfig vessel;
  std::size_t rows = 0;
  for (auto _ : state) {
    rows = 0;
    dynpos::scenario::stream_scenario(
        spec, vessel, 1, [&](const dynpos::core::Log& log, const dynpos::core::Log& truth) {
          rows += log.size();
          benchmark::DoNotOptimize(log.channels().back().values.data());
          benchmark::DoNotOptimize(truth.channels().back().values.data());
        });
  }
  state.counters["rows"] = static_cast<double>(rows);
  state.counters["x_realtime"] = benchmark::Counter(
      static_cast<double>(state.range(0) * state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FullModelStreamed)
    ->Name("BM_FullModelStreamedCold")
    ->Arg(3600)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The whole built-in test programme (every data/scenarios file), simulated without file output;
// simulated_s counts the settling before each log as well.
void BM_Campaign(benchmark::State& state) {
  const std::filesystem::path dir = std::filesystem::path(DYNPOS_SOURCE_DIR) / "data" / "scenarios";
  std::vector<dynpos::scenario::ScenarioSpec> specs;
  double simulated = 0.0;
  for (const std::string& name : dynpos::scenario::list_scenarios(dir)) {
    specs.push_back(dynpos::scenario::load_scenario(dir / (name + ".toml")));
    simulated += specs.back().settle_s + specs.back().duration_s;
  }
  const dynpos::scenario::VesselConfig vessel;
  for (auto _ : state) {
    for (const auto& spec : specs) {
      const dynpos::scenario::ScenarioRun run = dynpos::scenario::run_scenario(spec, vessel, 1);
      benchmark::DoNotOptimize(run.log.time().data());
    }
  }
  state.counters["scenarios"] = static_cast<double>(specs.size());
  state.counters["simulated_s"] = simulated;
}
BENCHMARK(BM_Campaign)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
