// DP capability of the virtual Gunnerus (built-in vessel parameters). Targets: a level-1 rose
// (36 directions) with all five single failures and the worst case in < 1 s; a level-3 rose
// (36 directions, time-domain runs of 300 s + 1200 s judged, the default) in < 5 min on 2 cores;
// the level-1 rose of an 8-unit [[thruster]] layout with every case (each unit, each group) and
// the worst in ≤ 0.5 s on one core.

#include <benchmark/benchmark.h>

#include <thread>

#include "dynpos/capability/quasi_static.hpp"
#include "dynpos/capability/time_domain.hpp"
#include "dynpos/model/thruster_unit.hpp"

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
    for (const auto& f : single_failures(vessel))
      roses.push_back(quasi_static_rose(vessel, {f}, o));
    const auto worst = worst_case(roses);
    for (const auto& p : roses.front()) lowest = std::min(lowest, p.dp_number);
    benchmark::DoNotOptimize(worst.data());
  }
  state.counters["intact_lowest_dp"] = lowest;
}
BENCHMARK(BM_QuasiStaticWithFailures)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

// Eight units of every type on the virtual Gunnerus's hull, sized so that the rose stays inside
// the DNV table (a stronger layout holds every row, and a rose beyond the table costs nothing):
// two bow tunnels and a retractable azimuth (switchboard A), two azimuths aft with sectors into
// each other's wake (one on each switchboard), a stern tunnel and two propellers with rudders
// (switchboard B).
dynpos::scenario::VesselConfig eight_unit_vessel() {
  using dynpos::model::UnitType;
  const auto unit = [](std::string group, std::string name, UnitType type, double x_m, double y_m,
                       double ahead_N, double astern_N,
                       std::vector<dynpos::model::AngleSector> forbidden = {}) {
    dynpos::model::ThrusterUnit u = dynpos::model::thruster_unit(
        std::move(name), type, x_m, y_m, ahead_N, astern_N, std::move(forbidden));
    u.group = std::move(group);
    if (type == UnitType::kPropellerRudder) u.rudder_lift_per_thrust = 0.65;
    return u;
  };
  dynpos::scenario::VesselConfig v;
  v.thrusters = {unit("A", "bow1", UnitType::kTunnel, 13.0, 0.0, 10e3, 9e3),
                 unit("A", "bow2", UnitType::kTunnel, 11.5, 0.0, 10e3, 9e3),
                 unit("A", "retract", UnitType::kAzimuth, 8.0, 0.0, 12e3, 0.0),
                 unit("A", "az_port", UnitType::kAzimuth, -12.0, -2.7, 30e3, 0.0, {{75, 105}}),
                 unit("B", "az_stb", UnitType::kAzimuth, -12.0, 2.7, 30e3, 0.0, {{255, 285}}),
                 unit("B", "stern", UnitType::kTunnel, -10.0, 0.0, 8e3, 8e3),
                 unit("B", "prop_port", UnitType::kPropellerRudder, -14.0, -1.5, 15e3, 10e3),
                 unit("B", "prop_stb", UnitType::kPropellerRudder, -14.0, 1.5, 15e3, 10e3)};
  return v;
}

void BM_LayoutRoseEveryCase(benchmark::State& state) {
  const dynpos::scenario::VesselConfig vessel = eight_unit_vessel();
  QuasiStaticOptions o;
  int lowest = 99, highest = 0;
  for (auto _ : state) {
    std::vector<std::vector<CapabilityPoint>> roses;
    const auto intact = quasi_static_rose(vessel, {}, o);
    for (const auto& f : single_failures(vessel))
      roses.push_back(quasi_static_rose(vessel, {f}, o));
    const auto worst = worst_case(roses);
    for (const auto& p : intact) highest = std::max(highest, p.dp_number);
    for (const auto& p : worst) lowest = std::min(lowest, p.dp_number);
    benchmark::DoNotOptimize(worst.data());
  }
  state.counters["cases"] = static_cast<double>(single_failures(vessel).size());
  state.counters["intact_highest_dp"] = highest;
  state.counters["worst_lowest_dp"] = lowest;
}
BENCHMARK(BM_LayoutRoseEveryCase)->Unit(benchmark::kMillisecond);

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
