#include "dynpos/control/passive_observer.hpp"

#include <Eigen/LU>
#include <cmath>
#include <stdexcept>

namespace dynpos::control {
namespace {

Eigen::Matrix3d rotation(double psi) {
  const double c = std::cos(psi), s = std::sin(psi);
  Eigen::Matrix3d R;
  R << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0;
  return R;
}

void validate(const PassiveObserverTuning& tuning, const ObserverModel& model) {
  if (!(tuning.notch_damping > model.wave_damping_ratio) || !std::isfinite(tuning.notch_damping)) {
    throw std::invalid_argument(
        "passive observer tuning: the notch damping must be finite and above the wave model's "
        "damping ratio");
  }
  if (!(tuning.cutoff_ratio > 1.0) || !std::isfinite(tuning.cutoff_ratio)) {
    throw std::invalid_argument(
        "passive observer tuning: the cut-off ratio ω_c/ω₀ must be finite and > 1");
  }
  if (!(tuning.lf_bandwidth_ratio > 0.0 && tuning.lf_bandwidth_ratio < 1.0)) {
    throw std::invalid_argument(
        "passive observer tuning: the LF bandwidth ratio ω_b/ω₀ must be in (0, 1)");
  }
}

}  // namespace

PassiveObserverGains passive_observer_gains(const ObserverModel& model,
                                            const PassiveObserverTuning& tuning) {
  model.validate();
  validate(tuning, model);
  const Eigen::Vector3d w0 = model.wave_peak_frequency_rad_s;
  const Eigen::Vector3d wc = tuning.cutoff_ratio * w0;
  const Eigen::Vector3d wb = tuning.lf_bandwidth_ratio * w0;
  const double dz = tuning.notch_damping - model.wave_damping_ratio;
  PassiveObserverGains g;
  g.K1.topRows<3>() = (-2.0 * dz * wc.cwiseQuotient(w0)).asDiagonal();
  g.K1.bottomRows<3>() = (2.0 * dz * w0).asDiagonal();
  g.K2 = wc.asDiagonal();
  // The slow pair s² + K₄/(M K₂) s + K₃/(M K₂) at ω_b, critically damped, per DOF (BODY).
  const Eigen::Vector3d m = model.M.diagonal();
  g.K4 = (2.0 * wb.cwiseProduct(wc).cwiseProduct(m)).asDiagonal();
  g.K3 = (wb.cwiseProduct(wb).cwiseProduct(wc).cwiseProduct(m)).asDiagonal();
  return g;
}

PassiveObserver::PassiveObserver(const ObserverModel& model, const PassiveObserverGains& gains,
                                 const Eigen::Vector3d& eta0_n)
    : model_(model), gains_(gains), coast_(model.wave_peak_frequency_rad_s) {
  model_.validate();
  M_inv_ = model_.M.inverse();
  x_.segment<3>(6) = eta0_n;
  estimate_.eta_n = eta0_n;
}

PassiveObserver::State PassiveObserver::derivative(const State& x, const Eigen::Vector3d& y_n,
                                                   const Eigen::Vector3d& tau_b) const {
  const Eigen::Vector3d xi1 = x.segment<3>(0), xi2 = x.segment<3>(3);
  const Eigen::Vector3d eta = x.segment<3>(6), nu = x.segment<3>(9), b = x.segment<3>(12);
  // R at the measured heading; the estimate's while the heading is missing.
  const Eigen::Matrix3d R = rotation(std::isnan(y_n.z()) ? eta.z() : y_n.z());
  const Eigen::Vector3d y_tilde = innovation(y_n, eta + xi2);
  const Eigen::Vector3d y_tilde_b = R.transpose() * y_tilde;
  const Eigen::Vector3d& w0 = model_.wave_peak_frequency_rad_s;
  State d;
  d.segment<3>(0) = xi2 + gains_.K1.topRows<3>() * y_tilde;
  d.segment<3>(3) = -w0.cwiseProduct(w0).cwiseProduct(xi1) -
                    2.0 * model_.wave_damping_ratio * w0.cwiseProduct(xi2) +
                    gains_.K1.bottomRows<3>() * y_tilde;
  d.segment<3>(6) = R * nu + gains_.K2 * y_tilde;
  // K₃ and K₄ act in BODY (they scale with M's diagonal), so b̂ takes R K₃ Rᵀ ỹ.
  d.segment<3>(9) = M_inv_ * (-model_.D * nu + R.transpose() * b + tau_b + gains_.K4 * y_tilde_b);
  d.segment<3>(12) = -b.cwiseQuotient(model_.bias_time_constant_s) + R * (gains_.K3 * y_tilde_b);
  return d;
}

void PassiveObserver::step(const Eigen::Vector3d& y_n, const Eigen::Vector3d& tau_b, double dt_s) {
  // Lost now: coast from the wave-period means (coast_start.hpp).
  coast_.start_if_lost(y_n, x_.segment<3>(9), x_.segment<3>(12));
  const State k1 = derivative(x_, y_n, tau_b);
  const State k2 = derivative(x_ + 0.5 * dt_s * k1, y_n, tau_b);
  const State k3 = derivative(x_ + 0.5 * dt_s * k2, y_n, tau_b);
  const State k4 = derivative(x_ + dt_s * k3, y_n, tau_b);
  x_ += dt_s / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  estimate_.wave_n = x_.segment<3>(3);
  estimate_.eta_n = x_.segment<3>(6);
  estimate_.nu_b = x_.segment<3>(9);
  estimate_.bias_n = x_.segment<3>(12);
  coast_.track(estimate_.nu_b, estimate_.bias_n, dt_s);
}

}  // namespace dynpos::control
