// MRU lever-arm throughput: one hour at 100 Hz (360 001 samples) with two MRUs: the signal
// preparation (Savitzky–Golay smoothing and differentiation), batch least squares with the
// excitation diagnostics, and the Luenberger observer (4.80).

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "dynpos/calib/mru_observer.hpp"

namespace {

// Rotation about a fixed origin with roll, pitch and yaw oscillations; exact accelerations
// a = ω̇ × l + ω × (ω × l) at the arms of thesis table 4.6.
dynpos::calib::MruRawSamples make_hour() {
  dynpos::calib::MruRawSamples raw;
  const Eigen::Vector3d l[2] = {{0.358, 0.804, -4.321}, {14.978, 0.039, 0.568}};
  raw.names = {"mru1", "mru2"};
  raw.a_b_mps2.resize(2);
  const std::size_t n = 360001;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 0.01 * static_cast<double>(i);
    const Eigen::Vector3d w(0.05 * std::cos(t), 0.04 * std::cos(0.8 * t + 1), 0.02);
    const Eigen::Vector3d wd(-0.05 * std::sin(t), -0.032 * std::sin(0.8 * t + 1), 0.0);
    raw.t_s.push_back(t);
    raw.theta_rad.emplace_back(0.05 * std::sin(t), 0.05 * std::sin(0.8 * t + 1), 0.02 * t);
    raw.omega_b_rps.push_back(w);
    raw.v_b_mps.emplace_back(3.0, 0.0, 0.0);
    for (int j = 0; j < 2; ++j) {
      raw.a_b_mps2[j].push_back(wd.cross(l[j]) + w.cross(w.cross(l[j])) +
                                w.cross(raw.v_b_mps.back()));
    }
  }
  return raw;
}

void BM_MruSignalsHour100Hz2Mru(benchmark::State& state) {
  const auto raw = make_hour();
  for (auto _ : state) benchmark::DoNotOptimize(dynpos::calib::mru_signals_from_samples(raw));
}
BENCHMARK(BM_MruSignalsHour100Hz2Mru)->Unit(benchmark::kMillisecond);

void BM_MruLsqHour100Hz2Mru(benchmark::State& state) {
  const auto s = dynpos::calib::mru_signals_from_samples(make_hour());
  for (auto _ : state) benchmark::DoNotOptimize(dynpos::calib::estimate_mru_arms(s));
}
BENCHMARK(BM_MruLsqHour100Hz2Mru)->Unit(benchmark::kMillisecond);

void BM_MruObserverHour100Hz2Mru(benchmark::State& state) {
  const auto s = dynpos::calib::mru_signals_from_samples(make_hour());
  dynpos::calib::MruEstimateOptions o;
  o.method = dynpos::calib::MruMethod::kObserver;
  for (auto _ : state) benchmark::DoNotOptimize(dynpos::calib::estimate_mru_arms(s, o));
}
BENCHMARK(BM_MruObserverHour100Hz2Mru)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
