// `identify vessel` on the virtual programme: the logs of seed 1 of surge-steps-forward,
// sway-steps-port, yaw-steps, turning-circle and zig-zag (as tests/validation/vessel_id_test.cpp
// simulates them), simulated once into the temporary folder, then identified from the built-in
// Gunnerus with the cross-validation's fit, as the command line does by default. The argument
// is the number of threads. Target: under 30 s on 2 threads (the requirement: 60 s on 2 cores).

#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>
#include <vector>

#include "dynpos/analysis/data_dir.hpp"
#include "dynpos/analysis/vessel_id.hpp"
#include "dynpos/core/parallel_for.hpp"
#include "dynpos/scenario/run_files.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace {

namespace fs = std::filesystem;

// The programme's log.csv files, simulated on the first call (two scenarios at a time).
const std::vector<fs::path>& programme() {
  static const std::vector<fs::path> logs = [] {
    const std::vector<std::string> names{"surge-steps-forward", "sway-steps-port", "yaw-steps",
                                         "turning-circle", "zig-zag"};
    const fs::path data = dynpos::analysis::find_data_dir();
    const fs::path dir = fs::temp_directory_path() / "dynpos_bench_vessel_id";
    const dynpos::scenario::VesselConfig vessel =
        dynpos::scenario::load_vessel_config(data / "vessels" / "gunnerus.toml");
    std::vector<fs::path> out(names.size());
    dynpos::core::parallel_for(names.size(), 2, [&](std::size_t k) {
      const dynpos::scenario::ScenarioSpec spec =
          dynpos::scenario::load_scenario(data / "scenarios" / (names[k] + ".toml"));
      dynpos::scenario::write_scenario_run(dynpos::scenario::run_scenario(spec, vessel, 1),
                                           dir / names[k]);
      out[k] = dir / names[k] / "log.csv";
    });
    return out;
  }();
  return logs;
}

void BM_IdentifyVesselProgramme(benchmark::State& state) {
  dynpos::analysis::VesselIdRequest request;
  for (const fs::path& log : programme()) {
    dynpos::analysis::LogSource source;
    source.log = log;
    request.logs.push_back(source);
  }
  request.jobs = static_cast<unsigned>(state.range(0));
  int iterations = 0;
  std::size_t determined = 0;
  for (auto _ : state) {
    const dynpos::analysis::VesselIdReport report = dynpos::analysis::run_vessel_id(request);
    iterations = report.iterations;
    determined = 0;
    for (const auto& p : report.parameters) determined += p.determined ? 1 : 0;
    benchmark::DoNotOptimize(report.parameters.data());
  }
  state.counters["solver_iterations"] = iterations;
  state.counters["determined"] = static_cast<double>(determined);
}
BENCHMARK(BM_IdentifyVesselProgramme)
    ->Arg(2)
    ->Arg(1)
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
