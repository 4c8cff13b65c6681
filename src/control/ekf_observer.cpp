#include "dynpos/control/ekf_observer.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dynpos::control {
namespace {

// Offsets of the blocks of the state [ξ₁; ξ₂; η; ν; b; the other wave components' ξ₁, ξ₂].
constexpr int kEta = 6, kNu = 9, kBias = 12;
constexpr int kN = EkfObserver::kStates;
// ξ₁ and ξ₂ of wave component c.
constexpr int xi1(int c) { return c == 0 ? 0 : 15 + 6 * (c - 1); }
constexpr int xi2(int c) { return xi1(c) + 3; }

// The measured rows (at most 4): fixed-capacity matrices, no allocation per step.
using RowsH = Eigen::Matrix<double, Eigen::Dynamic, kN, Eigen::RowMajor, 4, kN>;
using RowsSquare = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 4, 4>;
using RowsVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 4, 1>;
using Gain = Eigen::Matrix<double, kN, Eigen::Dynamic, 0, kN, 4>;

Eigen::Matrix3d rotation(double psi) {
  const double c = std::cos(psi), s = std::sin(psi);
  Eigen::Matrix3d R;
  R << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0;
  return R;
}

// dR/dψ.
Eigen::Matrix3d rotation_derivative(double psi) {
  const double c = std::cos(psi), s = std::sin(psi);
  Eigen::Matrix3d dR;
  dR << -s, -c, 0.0, c, -s, 0.0, 0.0, 0.0, 0.0;
  return dR;
}

void require_positive(const Eigen::Vector3d& v, const char* name) {
  if (!v.allFinite() || !(v.array() > 0.0).all()) {
    throw std::invalid_argument(std::string("EKF tuning: ") + name +
                                " must be finite and > 0 in every axis");
  }
}

void require_positive(double v, const char* name) {
  if (!std::isfinite(v) || !(v > 0.0)) {
    throw std::invalid_argument(std::string("EKF tuning: ") + name + " must be finite and > 0");
  }
}

const EkfObserverTuning& validated(const EkfObserverTuning& tuning) {
  tuning.validate();
  return tuning;
}

}  // namespace

void EkfObserverTuning::validate() const {
  require_positive(wave_motion_std, "wave_motion_std");
  require_positive(nu_accel_noise, "nu_accel_noise");
  require_positive(bias_accel_noise, "bias_accel_noise");
  require_positive(initial_nu_std, "initial_nu_std");
  require_positive(initial_bias_accel_std, "initial_bias_accel_std");
  require_positive(position_std_m, "position_std_m");
  require_positive(heading_std_rad, "heading_std_rad");
  require_positive(yaw_rate_std_rad_s, "yaw_rate_std_rad_s");
  if (!std::isfinite(measurement_lost_after_s) || measurement_lost_after_s < 0.0) {
    throw std::invalid_argument("EKF tuning: measurement_lost_after_s must be finite and >= 0");
  }
}

EkfObserver::EkfObserver(const ObserverModel& model, const EkfObserverTuning& tuning,
                         const Eigen::Vector3d& eta0_n)
    : model_(model),
      tuning_(validated(tuning)),
      coast_(model.wave_peak_frequency_rad_s, tuning_.measurement_lost_after_s) {
  model_.validate();
  M_inv_ = model_.M.inverse();
  x_.segment<3>(kEta) = eta0_n;
  estimate_.eta_n = eta0_n;
  // The wave model at rest in its stationary spread: each component's σ in ξ₂, σ/ω in ξ₁.
  const Eigen::Vector3d wave_var = tuning_.wave_motion_std.array().square();
  const Eigen::Vector3d y_var(tuning_.position_std_m * tuning_.position_std_m,
                              tuning_.position_std_m * tuning_.position_std_m,
                              tuning_.heading_std_rad * tuning_.heading_std_rad);
  for (int c = 0; c < kWaveComponents; ++c) {
    const Eigen::Vector3d w = frequency(c);
    const Eigen::Vector3d var = wave_var.cwiseProduct(model_.wave_variance_share.col(c));
    P_.diagonal().segment<3>(xi1(c)) = var.cwiseQuotient(w.cwiseProduct(w));
    P_.diagonal().segment<3>(xi2(c)) = var;
  }
  P_.diagonal().segment<3>(kEta) = y_var + wave_var;  // η₀ is a measurement, waves included
  P_.diagonal().segment<3>(kNu) = tuning_.initial_nu_std.array().square();
  const Eigen::Vector3d b_std_b = model_.M.diagonal().cwiseProduct(tuning_.initial_bias_accel_std);
  const Eigen::Matrix3d R = rotation(eta0_n.z());
  P_.block<3, 3>(kBias, kBias) = R * b_std_b.array().square().matrix().asDiagonal() * R.transpose();
}

Eigen::Vector3d EkfObserver::frequency(int component) const {
  return kWaveComponentRatio[static_cast<std::size_t>(component)] *
         model_.wave_peak_frequency_rad_s;
}

EkfObserver::State EkfObserver::derivative(const State& x, const Eigen::Vector3d& tau_b) const {
  const Eigen::Vector3d nu = x.segment<3>(kNu), b = x.segment<3>(kBias);
  const Eigen::Matrix3d R = rotation(x(kEta + 2));
  State d;
  for (int c = 0; c < kWaveComponents; ++c) {
    const Eigen::Vector3d w = frequency(c);
    d.segment<3>(xi1(c)) = x.segment<3>(xi2(c));
    d.segment<3>(xi2(c)) = -w.cwiseProduct(w).cwiseProduct(x.segment<3>(xi1(c))) -
                           2.0 * model_.wave_damping_ratio * w.cwiseProduct(x.segment<3>(xi2(c)));
  }
  d.segment<3>(kEta) = R * nu;                                                // (2.20)
  d.segment<3>(kNu) = M_inv_ * (-model_.D * nu + R.transpose() * b + tau_b);  // (2.21)
  d.segment<3>(kBias) = -b.cwiseQuotient(model_.bias_time_constant_s);        // (2.22)
  return d;
}

EkfObserver::Covariance EkfObserver::jacobian(const State& x) const {
  const double psi = x(kEta + 2);
  const Eigen::Matrix3d R = rotation(psi), dR = rotation_derivative(psi);
  Covariance A = Covariance::Zero();
  for (int c = 0; c < kWaveComponents; ++c) {
    const Eigen::Vector3d w = frequency(c);
    A.block<3, 3>(xi1(c), xi2(c)) = Eigen::Matrix3d::Identity();
    A.block<3, 3>(xi2(c), xi1(c)) = (-w.cwiseProduct(w)).asDiagonal();
    A.block<3, 3>(xi2(c), xi2(c)) = (-2.0 * model_.wave_damping_ratio * w).asDiagonal();
  }
  A.block<3, 3>(kEta, kNu) = R;
  A.block<3, 1>(kEta, kEta + 2) = dR * x.segment<3>(kNu);
  A.block<3, 3>(kNu, kNu) = -M_inv_ * model_.D;
  A.block<3, 3>(kNu, kBias) = M_inv_ * R.transpose();
  A.block<3, 1>(kNu, kEta + 2) = M_inv_ * dR.transpose() * x.segment<3>(kBias);
  A.block<3, 3>(kBias, kBias) = (-model_.bias_time_constant_s.cwiseInverse()).asDiagonal();
  return A;
}

EkfObserver::Covariance EkfObserver::process_noise(double psi_rad) const {
  const double lambda = model_.wave_damping_ratio;
  const Eigen::Vector3d m = model_.M.diagonal();
  Covariance Q = Covariance::Zero();
  // q = 4λωσ² gives each component its stationary σ in ξ₂ (and σ/ω in ξ₁).
  for (int c = 0; c < kWaveComponents; ++c) {
    Q.diagonal().segment<3>(xi2(c)) = 4.0 * lambda * frequency(c).array() *
                                      tuning_.wave_motion_std.array().square() *
                                      model_.wave_variance_share.col(c).array();
  }
  const Eigen::Vector3d force = m.cwiseProduct(tuning_.nu_accel_noise);
  Q.block<3, 3>(kNu, kNu) =
      M_inv_ * force.array().square().matrix().asDiagonal() * M_inv_.transpose();
  const Eigen::Vector3d bias = m.cwiseProduct(tuning_.bias_accel_noise);
  const Eigen::Matrix3d R = rotation(psi_rad);
  Q.block<3, 3>(kBias, kBias) = R * bias.array().square().matrix().asDiagonal() * R.transpose();
  return Q;
}

void EkfObserver::correct(const Eigen::Vector3d& y_n, double yaw_rate_rad_s) {
  std::array<int, 3> rows{};
  int m = 0;
  for (int i = 0; i < 3; ++i) {
    if (!std::isnan(y_n[i])) rows[m++] = i;
  }
  const bool rate = !std::isnan(yaw_rate_rad_s);
  if (m == 0 && !rate) return;                  // nothing measured: coast
  Eigen::Vector3d y_hat = x_.segment<3>(kEta);  // y = η + Σ ξ₂
  for (int c = 0; c < kWaveComponents; ++c) y_hat += x_.segment<3>(xi2(c));
  const Eigen::Vector3d y_tilde_all = innovation(y_n, y_hat);
  const Eigen::Vector3d sigma(tuning_.position_std_m, tuning_.position_std_m,
                              tuning_.heading_std_rad);
  const int n = m + (rate ? 1 : 0);
  RowsH H = RowsH::Zero(n, kN);
  RowsSquare Rm = RowsSquare::Zero(n, n);
  RowsVector y_tilde(n);
  for (int r = 0; r < m; ++r) {
    for (int c = 0; c < kWaveComponents; ++c) H(r, xi2(c) + rows[r]) = 1.0;
    H(r, kEta + rows[r]) = 1.0;
    Rm(r, r) = sigma[rows[r]] * sigma[rows[r]];
    y_tilde[r] = y_tilde_all[rows[r]];
  }
  if (rate) {
    // The rate gyro: r plus the wave model's yaw rate Σ ξ̇₂ = Σ (−ω²ξ₁ − 2λωξ₂).
    H(m, kNu + 2) = 1.0;
    for (int c = 0; c < kWaveComponents; ++c) {
      const double w = frequency(c).z();
      H(m, xi1(c) + 2) = -w * w;
      H(m, xi2(c) + 2) = -2.0 * model_.wave_damping_ratio * w;
    }
    Rm(m, m) = tuning_.yaw_rate_std_rad_s * tuning_.yaw_rate_std_rad_s;
    y_tilde[m] = yaw_rate_rad_s - H.row(m).dot(x_);
  }
  const Gain PHt = P_ * H.transpose();
  const RowsSquare S = H * PHt + Rm;
  const Gain K = S.llt().solve(PHt.transpose()).transpose();  // P Hᵀ S⁻¹
  x_ += K * y_tilde;
  const Covariance I_KH = Covariance::Identity() - K * H;
  P_ = I_KH * P_ * I_KH.transpose() + K * Rm * K.transpose();  // Joseph form
  P_ = 0.5 * (P_ + P_.transpose()).eval();
}

void EkfObserver::predict(const Eigen::Vector3d& tau_b, double dt_s) {
  const Covariance A = jacobian(x_);
  const Covariance Phi = Covariance::Identity() + A * dt_s + 0.5 * dt_s * dt_s * A * A;
  const Covariance Q = process_noise(x_(kEta + 2));
  const State k1 = derivative(x_, tau_b);
  const State k2 = derivative(x_ + 0.5 * dt_s * k1, tau_b);
  const State k3 = derivative(x_ + 0.5 * dt_s * k2, tau_b);
  const State k4 = derivative(x_ + dt_s * k3, tau_b);
  x_ += dt_s / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  P_ = Phi * P_ * Phi.transpose() + Q * dt_s;
  P_ = 0.5 * (P_ + P_.transpose()).eval();
}

void EkfObserver::step(const Eigen::Vector3d& y_n, const Eigen::Vector3d& tau_b, double dt_s,
                       double yaw_rate_rad_s) {
  if (!std::isfinite(dt_s) || !(dt_s > 0.0)) {
    throw std::invalid_argument("EKF observer: the step dt must be finite and > 0");
  }
  coast_.start_if_lost(y_n, x_.segment<3>(kNu), x_.segment<3>(kBias));  // coast_start.hpp
  correct(y_n, yaw_rate_rad_s);
  predict(tau_b, dt_s);
  estimate_.wave_n.setZero();
  for (int c = 0; c < kWaveComponents; ++c) estimate_.wave_n += x_.segment<3>(xi2(c));
  estimate_.eta_n = x_.segment<3>(kEta);
  estimate_.nu_b = x_.segment<3>(kNu);
  estimate_.bias_n = x_.segment<3>(kBias);
  coast_.track(estimate_.nu_b, estimate_.bias_n, dt_s);
}

}  // namespace dynpos::control
