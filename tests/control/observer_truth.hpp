#pragma once
// A simulated truth for the observer tests: the LF model of observer.hpp with a constant NED
// bias, a synthetic wave motion (a sum of sinusoids near ω₀) and white measurement noise.

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "dynpos/control/observer.hpp"
#include "dynpos/core/angle.hpp"

namespace dynpos::control::testing {

/// A supply vessel: M = diag(4.83e5, 8.3e5, 4.05e7), D = diag(5e3, 2.5e4, 2e6), T_p = 8 s.
inline ObserverModel vessel_model() {
  ObserverModel model;
  model.M = Eigen::Vector3d(4.83e5, 8.3e5, 4.05e7).asDiagonal();
  model.D = Eigen::Vector3d(5e3, 2.5e4, 2e6).asDiagonal();
  model.wave_peak_frequency_rad_s = Eigen::Vector3d::Constant(2.0 * std::numbers::pi / 8.0);
  return model;
}

struct TruthOptions {
  double heading_rad = core::deg_to_rad(30.0);
  Eigen::Vector3d bias_n{2e4, -1e4, 1e5};  ///< [N, N, N·m], constant but for one change:
  Eigen::Vector3d bias_change_n = Eigen::Vector3d::Zero();  ///< added to bias_n at
  double bias_change_at_s = 1e9;                            ///< this time [s]
  /// A slow excitation on top of −Rᵀb (BODY) [N, N, N·m], period lf_period_s: LF motion of
  /// ≈ 2 m, 1 m and 2.5°, ≈ 0.05 m/s at most.
  Eigen::Vector3d lf_force_b{500.0, 800.0, 2e3};
  double lf_period_s = 300.0;
  Eigen::Vector3d wave_rms{1.0, 1.0, core::deg_to_rad(1.0)};  ///< [m, m, rad]
  /// The wave motion's sinusoids per DOF, at these multiples of ω₀, of equal amplitude.
  std::vector<double> wave_ratios{0.8, 0.9, 1.0, 1.1, 1.25};
  Eigen::Vector3d noise_std{0.1, 0.1, core::deg_to_rad(0.1)};  ///< [m, m, rad]
  double duration_s = 600.0;
  double dt_s = 0.1;
  std::uint64_t seed = 1;
};

/// One sample at t = k·dt: the truth, the measurement (heading wrapped to [0, 2π), as a gyro
/// compass gives it) and the thrust held over [t, t + dt].
struct TruthSample {
  double t_s = 0.0;
  Eigen::Vector3d eta_n, nu_b, bias_n, wave_n, y_n, tau_b;
};

/// Seeded standard normal samples (Box–Muller on a 64-bit Mersenne twister: the same with every
/// standard library).
class Normal {
 public:
  explicit Normal(std::uint64_t seed) : engine_(seed) {}
  double operator()() {
    const double u1 = uniform(), u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }
  double uniform() { return (static_cast<double>(engine_() >> 11) + 0.5) * 0x1.0p-53; }

 private:
  std::mt19937_64 engine_;
};

inline Eigen::Matrix3d rotation(double psi) {
  const double c = std::cos(psi), s = std::sin(psi);
  Eigen::Matrix3d R;
  R << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0;
  return R;
}

/// The observers' state [ξ₁; ξ₂; η; ν; b].
using ObserverState = Eigen::Matrix<double, 15, 1>;

/// The model f(x, τ) of observer.hpp, written out again.
inline ObserverState model_derivative(const ObserverModel& model, const ObserverState& x,
                                      const Eigen::Vector3d& tau_b) {
  const Eigen::Matrix3d R = rotation(x(8));
  const double w0 = model.wave_peak_frequency_rad_s.x(), lambda = model.wave_damping_ratio;
  ObserverState d;
  d.segment<3>(0) = x.segment<3>(3);
  d.segment<3>(3) = -w0 * w0 * x.segment<3>(0) - 2.0 * lambda * w0 * x.segment<3>(3);
  d.segment<3>(6) = R * x.segment<3>(9);
  d.segment<3>(9) =
      model.M.inverse() * (-model.D * x.segment<3>(9) + R.transpose() * x.segment<3>(12) + tau_b);
  d.segment<3>(12) = -x.segment<3>(12).cwiseQuotient(model.bias_time_constant_s);
  return d;
}

/// One RK4 step of the model with τ held.
inline ObserverState model_step(const ObserverModel& model, const ObserverState& x,
                                const Eigen::Vector3d& tau_b, double dt_s) {
  const auto f = [&](const ObserverState& s) { return model_derivative(model, s, tau_b); };
  const ObserverState k1 = f(x), k2 = f(x + 0.5 * dt_s * k1), k3 = f(x + 0.5 * dt_s * k2);
  const ObserverState k4 = f(x + dt_s * k3);
  return x + dt_s / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

/// The state of an estimate, ξ₁ = 0 (not in the estimate; η, ν and b do not depend on it).
inline ObserverState state_of(const ObserverEstimate& e) {
  ObserverState x;
  x << Eigen::Vector3d::Zero(), e.wave_n, e.eta_n, e.nu_b, e.bias_n;
  return x;
}

/// The truth: η̇ = R ν, M ν̇ = −D ν + Rᵀ b + τ with τ = −Rᵀ b + the slow excitation, one RK4
/// step per sample; the wave motion per DOF sinusoids at wave_ratios·ω₀ of equal amplitude and
/// random phase, scaled to wave_rms.
inline std::vector<TruthSample> simulate_truth(const ObserverModel& model,
                                               const TruthOptions& opt) {
  Normal rng(opt.seed);
  const auto sines = static_cast<Eigen::Index>(opt.wave_ratios.size());
  Eigen::Matrix<double, 3, Eigen::Dynamic> phase(3, sines);
  for (int i = 0; i < 3; ++i) {
    for (Eigen::Index j = 0; j < sines; ++j) phase(i, j) = 2.0 * std::numbers::pi * rng.uniform();
  }
  const double w0 = model.wave_peak_frequency_rad_s.x();
  // The rms of n sinusoids of amplitude a is a·√(n/2).
  const Eigen::Vector3d amplitude = opt.wave_rms / std::sqrt(0.5 * static_cast<double>(sines));
  const Eigen::Matrix3d M_inv = model.M.inverse();
  const auto bias = [&](double t) -> Eigen::Vector3d {
    return t >= opt.bias_change_at_s ? (opt.bias_n + opt.bias_change_n).eval() : opt.bias_n;
  };
  const auto thrust = [&](double t, double psi) -> Eigen::Vector3d {
    const double a = 2.0 * std::numbers::pi * t / opt.lf_period_s;
    const Eigen::Vector3d slow(std::sin(a), std::sin(a + 1.0), std::sin(a + 2.0));
    return -rotation(psi).transpose() * bias(t) + opt.lf_force_b.cwiseProduct(slow);
  };
  using X = Eigen::Matrix<double, 6, 1>;  // η, ν
  const auto f = [&](const X& x, const Eigen::Vector3d& b, const Eigen::Vector3d& tau) -> X {
    const Eigen::Matrix3d R = rotation(x(2));
    X d;
    d.head<3>() = R * x.tail<3>();
    d.tail<3>() = M_inv * (-model.D * x.tail<3>() + R.transpose() * b + tau);
    return d;
  };
  X x = X::Zero();
  x(2) = opt.heading_rad;
  const auto n = static_cast<std::size_t>(std::lround(opt.duration_s / opt.dt_s));
  std::vector<TruthSample> out(n);
  for (std::size_t k = 0; k < n; ++k) {
    TruthSample& s = out[k];
    s.t_s = static_cast<double>(k) * opt.dt_s;
    s.eta_n = x.head<3>();
    s.nu_b = x.tail<3>();
    for (int i = 0; i < 3; ++i) {
      double w = 0.0;
      for (Eigen::Index j = 0; j < sines; ++j) {
        w += std::sin(opt.wave_ratios[static_cast<std::size_t>(j)] * w0 * s.t_s + phase(i, j));
      }
      s.wave_n[i] = amplitude[i] * w;
      s.y_n[i] = s.eta_n[i] + s.wave_n[i] + opt.noise_std[i] * rng();
    }
    s.y_n.z() = core::wrap_2pi(s.y_n.z());
    s.bias_n = bias(s.t_s);
    s.tau_b = thrust(s.t_s, x(2));
    const double h = opt.dt_s;
    const X k1 = f(x, s.bias_n, s.tau_b), k2 = f(x + 0.5 * h * k1, s.bias_n, s.tau_b);
    const X k3 = f(x + 0.5 * h * k2, s.bias_n, s.tau_b), k4 = f(x + h * k3, s.bias_n, s.tau_b);
    x += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  return out;
}

/// The estimates of `observer` run over `truth` (est[k] at t_k; est[0] the start), on the
/// measurements `measure(sample)` (default: the sample's y).
template <class Observer, class Measure>
std::vector<ObserverEstimate> run(Observer& observer, const std::vector<TruthSample>& truth,
                                  Measure measure, double dt_s = 0.1) {
  std::vector<ObserverEstimate> est(truth.size());
  est[0] = observer.estimate();
  for (std::size_t k = 0; k + 1 < truth.size(); ++k) {
    observer.step(measure(truth[k]), truth[k].tau_b, dt_s);
    est[k + 1] = observer.estimate();
  }
  return est;
}

template <class Observer>
std::vector<ObserverEstimate> run(Observer& observer, const std::vector<TruthSample>& truth) {
  return run(observer, truth, [](const TruthSample& s) { return s.y_n; });
}

/// rms over k in [from, to) of the horizontal LF position error |η̂ − η| (N, E) [m].
inline double lf_position_rms(const std::vector<ObserverEstimate>& est,
                              const std::vector<TruthSample>& truth, std::size_t from,
                              std::size_t to) {
  double sum = 0.0;
  for (std::size_t k = from; k < to; ++k) {
    sum += (est[k].eta_n - truth[k].eta_n).head<2>().squaredNorm();
  }
  return std::sqrt(sum / static_cast<double>(to - from));
}

/// rms over k in [from, to) of the horizontal wave motion |η_w| (N, E) [m].
inline double wave_motion_rms(const std::vector<TruthSample>& truth, std::size_t from,
                              std::size_t to) {
  double sum = 0.0;
  for (std::size_t k = from; k < to; ++k) sum += truth[k].wave_n.head<2>().squaredNorm();
  return std::sqrt(sum / static_cast<double>(to - from));
}

/// rms over k in [from, to) of the horizontal LF velocity error |ν̂ − ν| (u, v) [m/s].
inline double lf_velocity_rms(const std::vector<ObserverEstimate>& est,
                              const std::vector<TruthSample>& truth, std::size_t from,
                              std::size_t to) {
  double sum = 0.0;
  for (std::size_t k = from; k < to; ++k) {
    sum += (est[k].nu_b - truth[k].nu_b).head<2>().squaredNorm();
  }
  return std::sqrt(sum / static_cast<double>(to - from));
}

/// rms over k in [from, to) of the LF heading error, wrapped [rad].
inline double lf_heading_rms(const std::vector<ObserverEstimate>& est,
                             const std::vector<TruthSample>& truth, std::size_t from,
                             std::size_t to) {
  double sum = 0.0;
  for (std::size_t k = from; k < to; ++k) {
    sum += std::pow(core::angle_diff(est[k].eta_n.z(), truth[k].eta_n.z()), 2);
  }
  return std::sqrt(sum / static_cast<double>(to - from));
}

/// The largest error of b̂ averaged over `window` samples (the wave ripple averaged out), over
/// the windows that end at k in [from, to], per component relative to the true |b| (N and E to
/// the horizontal |b_NE|) [-].
inline Eigen::Vector3d bias_error(const std::vector<ObserverEstimate>& est,
                                  const std::vector<TruthSample>& truth, std::size_t from,
                                  std::size_t to, std::size_t window) {
  Eigen::Vector3d worst = Eigen::Vector3d::Zero();
  for (std::size_t k = std::max(from, window); k <= std::min(to, est.size()); ++k) {
    Eigen::Vector3d error = Eigen::Vector3d::Zero();
    for (std::size_t j = k - window; j < k; ++j) error += est[j].bias_n - truth[j].bias_n;
    const Eigen::Vector3d b = truth[k - 1].bias_n;
    const Eigen::Vector3d scale(b.head<2>().norm(), b.head<2>().norm(), std::abs(b.z()));
    worst = worst.cwiseMax((error / static_cast<double>(window)).cwiseAbs().cwiseQuotient(scale));
  }
  return worst;
}

}  // namespace dynpos::control::testing
