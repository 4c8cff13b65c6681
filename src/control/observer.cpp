#include "dynpos/control/observer.hpp"

#include <Eigen/Cholesky>
#include <array>
#include <cmath>
#include <stdexcept>

#include "dynpos/core/angle.hpp"

namespace dynpos::control {
namespace {

constexpr std::array<std::pair<ObserverKind, std::string_view>, 4> kNames{{
    {ObserverKind::kIdeal, "ideal"},
    {ObserverKind::kPassive, "passive"},
    {ObserverKind::kEkf, "ekf"},
    {ObserverKind::kRaw, "raw"},
}};

}  // namespace

std::string_view observer_name(ObserverKind kind) noexcept {
  for (const auto& [k, name] : kNames) {
    if (k == kind) return name;
  }
  return "ideal";
}

std::optional<ObserverKind> parse_observer(std::string_view name) noexcept {
  for (const auto& [k, n] : kNames) {
    if (n == name) return k;
  }
  return std::nullopt;
}

void ObserverModel::validate() const {
  if (!M.isApprox(M.transpose()) || M.llt().info() != Eigen::Success) {
    throw std::invalid_argument("observer model: M must be symmetric positive definite");
  }
  if ((D.diagonal().array() < 0.0).any()) {
    throw std::invalid_argument("observer model: D must have a non-negative diagonal");
  }
  if (!(bias_time_constant_s.array() > 0.0).all() || !bias_time_constant_s.allFinite()) {
    throw std::invalid_argument("observer model: bias time constants must be finite and > 0");
  }
  if (!(wave_peak_frequency_rad_s.array() > 0.0).all() || !wave_peak_frequency_rad_s.allFinite()) {
    throw std::invalid_argument("observer model: the wave peak frequency must be > 0");
  }
  if (!(wave_damping_ratio > 0.0 && wave_damping_ratio <= 1.0)) {
    throw std::invalid_argument("observer model: the wave damping ratio must be in (0, 1]");
  }
  if (!wave_variance_share.allFinite() || (wave_variance_share.array() < 0.0).any() ||
      ((wave_variance_share.rowwise().sum().array() - 1.0).abs() > 1e-9).any()) {
    throw std::invalid_argument(
        "observer model: the wave variance shares must be >= 0 and sum to 1 in each DOF");
  }
}

Eigen::Vector3d innovation(const Eigen::Vector3d& y_n, const Eigen::Vector3d& y_hat_n) noexcept {
  Eigen::Vector3d e = y_n - y_hat_n;
  e.z() = core::wrap_pi(e.z());
  for (int i = 0; i < 3; ++i) {
    if (std::isnan(y_n[i])) e[i] = 0.0;
  }
  return e;
}

}  // namespace dynpos::control
