// GNSS lever-arm estimators on a long log: one hour of motion at 100 Hz with three antennas at
// 1 Hz. The target is under 1 s for the Luenberger observer (4.26) on one core.

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "dynpos/calib/gnss_lever_arm.hpp"
#include "dynpos/core/rotation.hpp"

namespace {

using Vec3 = Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;

struct Data {
  dynpos::calib::MotionSeries motion;
  std::vector<dynpos::calib::GnssSeries> gnss;
};

// A slow turn with wave-like roll and pitch; P₀ on a circle, ν = Rᵀ·Ṗ₀ (4.6), fixes (4.2).
Data make_data(double duration_s) {
  const std::vector<Vec3> arms = {
      {0.202, -0.611, -13.891}, {1.571, 0.691, -13.520}, {-0.924, 0.574, -13.567}};
  const double r = 0.02;
  auto theta = [&](double t) {
    return Vec3(0.05 * std::sin(2 * kPi * t / 6.0), 0.02 * std::sin(2 * kPi * t / 8.0 + 1), r * t);
  };
  auto theta_dot = [&](double t) {
    return Vec3(0.05 * 2 * kPi / 6.0 * std::cos(2 * kPi * t / 6.0),
                0.02 * 2 * kPi / 8.0 * std::cos(2 * kPi * t / 8.0 + 1), r);
  };
  auto p0 = [&](double t) { return Vec3(100 * std::sin(r * t), 100 * (1 - std::cos(r * t)), 0); };
  auto p0_dot = [&](double t) {
    return Vec3(100 * r * std::cos(r * t), 100 * r * std::sin(r * t), 0);
  };
  Data d;
  const auto n = static_cast<std::size_t>(duration_s * 100.0) + 1;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * 0.01;
    const Vec3 th = theta(t);
    const Eigen::Matrix3d R = dynpos::core::R_nb_zyx(th(0), th(1), th(2));
    d.motion.t_s.push_back(t);
    d.motion.theta_rad.push_back(th);
    d.motion.omega_b_rps.push_back(dynpos::core::euler_rate_matrix_inverse(th(0), th(1)) *
                                   theta_dot(t));
    d.motion.v_b_mps.push_back(R.transpose() * p0_dot(t));
  }
  for (std::size_t k = 0; k < arms.size(); ++k) {
    dynpos::calib::GnssSeries g;
    g.name = "gnss" + std::to_string(k + 1);
    for (double t = 0; t <= duration_s; t += 1.0) {
      const Vec3 th = theta(t);
      g.t_s.push_back(t);
      g.p_n_m.push_back(p0(t) + dynpos::core::R_nb_zyx(th(0), th(1), th(2)) * arms[k]);
    }
    d.gnss.push_back(std::move(g));
  }
  return d;
}

void run(benchmark::State& state, dynpos::calib::GnssArmMethod method) {
  const Data d = make_data(3600.0);
  dynpos::calib::GnssArmOptions o;
  o.method = method;
  for (auto _ : state) {
    benchmark::DoNotOptimize(dynpos::calib::estimate_gnss_arms(d.motion, d.gnss, o));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(d.motion.size()));
}

void BM_GnssLuenberger1h(benchmark::State& state) {
  run(state, dynpos::calib::GnssArmMethod::kLuenberger);
}
void BM_GnssAdaptive1h(benchmark::State& state) {
  run(state, dynpos::calib::GnssArmMethod::kAdaptive);
}
void BM_GnssLsq1h(benchmark::State& state) { run(state, dynpos::calib::GnssArmMethod::kLsq); }
BENCHMARK(BM_GnssLuenberger1h)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GnssAdaptive1h)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GnssLsq1h)->Unit(benchmark::kMillisecond);

}  // namespace
BENCHMARK_MAIN();
