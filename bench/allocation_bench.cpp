// Thrust allocation for a general layout (model/layout_allocator.hpp). Target: ≤ 20 µs median
// per allocation for 6 units, so the full model stays above 100 k steps/s.
//
// The layout is a DP supply vessel in outline: two bow tunnels, a retractable azimuth forward,
// two main azimuths aft that may not push into each other's wake (±30° sectors). Demands walk
// the way a DP controller's do (a small change each 0.1 s step) over the whole envelope, some
// unattainable; the per-allocation time of each is recorded and its median, mean and 99th
// percentile reported.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <random>
#include <vector>

#include "dynpos/model/layout_allocator.hpp"

namespace {

using dynpos::model::LayoutAllocator;
using dynpos::model::ThrusterUnit;
using dynpos::model::UnitType;

using dynpos::model::thruster_unit;

std::vector<ThrusterUnit> supply_vessel() {
  return {thruster_unit("bow1", UnitType::kTunnel, 32.0, 0.0, 1.1e5, 1.1e5),
          thruster_unit("bow2", UnitType::kTunnel, 29.0, 0.0, 1.1e5, 1.1e5),
          thruster_unit("retract", UnitType::kAzimuth, 22.0, 0.0, 1.0e5, 0.0),
          thruster_unit("main_port", UnitType::kAzimuth, -36.0, -6.0, 3.5e5, 0.0, {{60.0, 120.0}}),
          thruster_unit("main_stb", UnitType::kAzimuth, -36.0, 6.0, 3.5e5, 0.0, {{240.0, 300.0}}),
          thruster_unit("stern", UnitType::kTunnel, -30.0, 0.0, 8.0e4, 8.0e4)};
}

// A controller's demand: a random walk of 1 % of the envelope a step, reflected at 1.2 × it.
std::vector<Eigen::Vector3d> demands(int count) {
  std::mt19937 rng(5);
  std::normal_distribution<double> step(0.0, 1.0);
  const Eigen::Vector3d envelope{8e5, 3.5e5, 1.6e7};
  std::vector<Eigen::Vector3d> out;
  Eigen::Vector3d tau = Eigen::Vector3d::Zero();
  for (int k = 0; k < count; ++k) {
    for (int i = 0; i < 3; ++i) {
      tau(i) += 0.01 * envelope(i) * step(rng);
      tau(i) = std::clamp(tau(i), -1.2 * envelope(i), 1.2 * envelope(i));
    }
    out.push_back(tau);
  }
  return out;
}

void BM_LayoutAllocationSixUnits(benchmark::State& state) {
  const LayoutAllocator allocator(supply_vessel());
  const std::vector<Eigen::Vector3d> taus = demands(20000);
  std::vector<double> us;
  int met = 0, programmes = 0;
  std::size_t k = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto a = allocator.allocate(taus[k]);
    const auto t1 = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(a.units.data());
    us.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
    met += a.met ? 1 : 0;
    programmes += a.programmes;
    k = (k + 1) % taus.size();
  }
  std::sort(us.begin(), us.end());
  state.counters["median_us"] = us[us.size() / 2];
  state.counters["p99_us"] = us[us.size() * 99 / 100];
  state.counters["met_fraction"] = static_cast<double>(met) / static_cast<double>(us.size());
  state.counters["programmes"] = static_cast<double>(programmes) / static_cast<double>(us.size());
}
BENCHMARK(BM_LayoutAllocationSixUnits)->Iterations(20000)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
