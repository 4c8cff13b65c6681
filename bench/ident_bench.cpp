// Identification throughput: the least-squares FOPDT fit (3.7) of one 600 s step window
// logged at 100 Hz (60 001 samples), and Smith's two-point method on the same window.

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "dynpos/ident/fopdt_fit.hpp"
#include "dynpos/ident/step_detector.hpp"

namespace {

struct Window {
  std::vector<double> t;
  std::vector<double> y;
  dynpos::ident::Step step;
};

// A surge-speed-like step: T = 60 s, δ = 3 s, step at 60 s, noise 2 % of the change (seeded).
Window make_window() {
  Window w;
  const dynpos::ident::FopdtModel truth{60.0, 0.5, 1.0, 60.0, 3.0};
  std::mt19937_64 engine(42);
  const auto uniform = [&engine] {
    return (static_cast<double>(engine() >> 11) + 0.5) * 0x1.0p-53;
  };
  const std::size_t n = 60001;
  w.t.resize(n);
  w.y.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    w.t[k] = 0.01 * static_cast<double>(k);
    // Box–Muller, so the data do not depend on the standard library's normal distribution.
    const double z =
        std::sqrt(-2.0 * std::log(uniform())) * std::cos(6.283185307179586 * uniform());
    w.y[k] = truth(w.t[k]) + 0.02 * z;
  }
  w.step.t_step = 60.0;
  w.step.t_ramp_end = 60.0;
  w.step.t_begin = 0.0;
  w.step.t_end = w.t.back();
  w.step.u_before = 0.0;
  w.step.u_after = 0.25;
  return w;
}

void BM_FopdtLeastSquares600s100Hz(benchmark::State& state) {
  const Window w = make_window();
  for (auto _ : state) {
    const dynpos::ident::FopdtFitResult r = dynpos::ident::fit_fopdt(w.t, w.y, w.step);
    benchmark::DoNotOptimize(r.time_constant);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(w.t.size()));
}
BENCHMARK(BM_FopdtLeastSquares600s100Hz)->Unit(benchmark::kMillisecond);

void BM_FopdtSmith600s100Hz(benchmark::State& state) {
  const Window w = make_window();
  dynpos::ident::FopdtFitOptions options;
  options.method = dynpos::ident::FopdtMethod::kSmith;
  for (auto _ : state) {
    const dynpos::ident::FopdtFitResult r = dynpos::ident::fit_fopdt(w.t, w.y, w.step, options);
    benchmark::DoNotOptimize(r.time_constant);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(w.t.size()));
}
BENCHMARK(BM_FopdtSmith600s100Hz)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
