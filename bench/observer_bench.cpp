// One step of the DP observers at the DP loop's 10 Hz: the passive observer (15 states, one RK4
// step) and the EKF (27 states: three wave components per DOF; a correction on the position,
// heading and yaw rate, an RK4 step and the covariance's propagation). A 900 s run of the
// virtual trial takes 9000 of them. And the inertial bridge's step (3 states per axis) that
// the DP system takes before each: with a fix, and dead reckoning without one.

#include <benchmark/benchmark.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "dynpos/control/ekf_observer.hpp"
#include "dynpos/control/inertial_position.hpp"
#include "dynpos/control/passive_observer.hpp"

namespace {

using dynpos::control::ObserverModel;

// A supply vessel in T_p 8 s with its WF variance spread over the components.
ObserverModel vessel_model() {
  ObserverModel m;
  m.M = Eigen::Vector3d(4.83e5, 8.3e5, 4.05e7).asDiagonal();
  m.D = Eigen::Vector3d(5e3, 2.5e4, 2e6).asDiagonal();
  m.wave_peak_frequency_rad_s = Eigen::Vector3d(0.78, 0.78, 0.80);
  m.wave_variance_share.rowwise() = Eigen::RowVector3d(0.6, 0.3, 0.1);
  return m;
}

// The measurement at step k: a slow swing and a wave at 0.8 rad/s.
Eigen::Vector3d measurement(long k) {
  const double t = 0.1 * static_cast<double>(k);
  return {0.5 * std::sin(0.8 * t) + 0.1 * std::sin(0.01 * t), 0.4 * std::sin(0.8 * t + 1.0),
          0.3 + 0.01 * std::sin(0.8 * t + 2.0)};
}

void BM_PassiveObserverStep(benchmark::State& state) {
  const ObserverModel model = vessel_model();
  dynpos::control::PassiveObserver o(model, dynpos::control::passive_observer_gains(model),
                                     Eigen::Vector3d(0.0, 0.0, 0.3));
  const Eigen::Vector3d tau(1e4, -5e3, 2e4);
  long k = 0;
  for (auto _ : state) {
    o.step(measurement(k++), tau, 0.1);
    benchmark::DoNotOptimize(o.estimate());
  }
}
BENCHMARK(BM_PassiveObserverStep);

void BM_EkfObserverStep(benchmark::State& state) {
  const ObserverModel model = vessel_model();
  dynpos::control::EkfObserver o(model, dynpos::control::EkfObserverTuning{},
                                 Eigen::Vector3d(0.0, 0.0, 0.3));
  const Eigen::Vector3d tau(1e4, -5e3, 2e4);
  long k = 0;
  for (auto _ : state) {
    const double t = 0.1 * static_cast<double>(k);
    o.step(measurement(k++), tau, 0.1, 0.008 * std::cos(0.8 * t + 2.0));
    benchmark::DoNotOptimize(o.estimate());
  }
}
BENCHMARK(BM_EkfObserverStep);

// state.range(0): 1 with a fix every step, 0 without (dead reckoning; the bridge is restarted
// on a fix whenever its σ passes its limit, once in about 650 steps).
void BM_InertialPositionStep(benchmark::State& state) {
  dynpos::control::InertialPosition ins;
  const bool fixes = state.range(0) == 1;
  long k = 0;
  for (auto _ : state) {
    const double t = 0.1 * static_cast<double>(k++);
    const Eigen::Vector2d accel(-0.32 * std::sin(0.8 * t), -0.26 * std::sin(0.8 * t + 1.0));
    const Eigen::Vector3d y = measurement(k);
    const bool fix = fixes || !ins.bridging();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    benchmark::DoNotOptimize(
        ins.step(fix ? Eigen::Vector2d(y.head<2>()) : Eigen::Vector2d(nan, nan), accel, 0.1));
  }
}
BENCHMARK(BM_InertialPositionStep)->Arg(1)->Arg(0);

}  // namespace

BENCHMARK_MAIN();
