// The logger-only lever-arm estimator (GNSS/INS fusion) on a long log: one hour of MRU data at
// 100 Hz (with white noise: 0.01 m/s², 0.02°, 0.03 °/s) and three antennas at 5 Hz with RTK
// noise (1 cm / 2 cm). The target is under 2 s on one core.

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "dynpos/calib/ins_arms.hpp"
#include "dynpos/core/rotation.hpp"

namespace {

using Vec3 = Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;

struct Data {
  dynpos::calib::ImuSeries imu;
  std::vector<dynpos::calib::GnssSeries> gnss;
};

// A turn at a slowly changing rate with wave-like roll, pitch and heave; P on a circle.
Vec3 theta(double t) {
  return {0.05 * std::sin(2 * kPi * t / 6.0), 0.02 * std::sin(2 * kPi * t / 8.0 + 1),
          0.02 * t + 0.5 * std::sin(2 * kPi * t / 600.0)};
}
Vec3 theta_dot(double t) {
  return {0.05 * 2 * kPi / 6.0 * std::cos(2 * kPi * t / 6.0),
          0.02 * 2 * kPi / 8.0 * std::cos(2 * kPi * t / 8.0 + 1),
          0.02 + 0.5 * 2 * kPi / 600.0 * std::cos(2 * kPi * t / 600.0)};
}
Vec3 p(double t) {
  return {100 * std::sin(0.02 * t), 100 * (1 - std::cos(0.02 * t)), 0.5 * std::sin(1.1 * t)};
}
Vec3 p_ddot(double t) {
  return {-0.04 * std::sin(0.02 * t), 0.04 * std::cos(0.02 * t), -0.605 * std::sin(1.1 * t)};
}

Data make_data(double duration_s) {
  const std::vector<Vec3> arms = {
      {-0.156, -1.415, -9.570}, {1.213, -0.113, -9.199}, {-1.282, -0.230, -9.246}};
  std::mt19937_64 rng(1);
  std::normal_distribution<double> n01;
  auto noise = [&](double s) { return Vec3(s * n01(rng), s * n01(rng), s * n01(rng)); };
  Data d;
  d.imu.name = "mru1";
  const auto n = static_cast<std::size_t>(duration_s * 100.0) + 1;
  const double deg = kPi / 180.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * 0.01;
    const Vec3 th = theta(t);
    const Eigen::Matrix3d R = dynpos::core::R_nb_zyx(th(0), th(1), th(2));
    d.imu.t_s.push_back(t);
    d.imu.theta_rad.push_back(th + noise(0.02 * deg));
    d.imu.omega_b_rps.push_back(
        dynpos::core::euler_rate_matrix_inverse(th(0), th(1)) * theta_dot(t) + noise(0.03 * deg));
    d.imu.accel_b_mps2.push_back(R.transpose() * p_ddot(t) + noise(0.01));
  }
  for (std::size_t k = 0; k < arms.size(); ++k) {
    dynpos::calib::GnssSeries g;
    g.name = "gnss" + std::to_string(k + 1);
    for (std::size_t i = 0; i <= static_cast<std::size_t>(duration_s * 5.0); ++i) {
      const double t = 0.2 * static_cast<double>(i);
      const Vec3 th = theta(t);
      g.t_s.push_back(t);
      g.p_n_m.push_back(p(t) + dynpos::core::R_nb_zyx(th(0), th(1), th(2)) * arms[k] +
                        Vec3(0.01 * n01(rng), 0.01 * n01(rng), 0.02 * n01(rng)));
    }
    d.gnss.push_back(std::move(g));
  }
  return d;
}

void BM_InsArms(benchmark::State& state) {
  const Data d = make_data(static_cast<double>(state.range(0)));
  for (auto _ : state) {
    auto r = dynpos::calib::estimate_ins_arms(d.imu, d.gnss);
    if (r.status != dynpos::core::Status::kOk) state.SkipWithError(r.message.c_str());
    benchmark::DoNotOptimize(r);
  }
  state.counters["fixes"] = static_cast<double>(3 * (5 * state.range(0) + 1));
}
BENCHMARK(BM_InsArms)->Arg(400)->Arg(3600)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
