#include "dynpos/control/reference_model.hpp"

#include <cmath>
#include <stdexcept>

#include "dynpos/core/angle.hpp"

namespace dynpos::control {

void ReferenceModelParams::validate() const {
  if (!((omega.array() > 0.0).all() && omega.allFinite())) {
    throw std::invalid_argument("ReferenceModelParams.omega must be > 0");
  }
  if (!(zeta > 0.0)) throw std::invalid_argument("ReferenceModelParams.zeta must be > 0");
  if (!((max_rate.array() > 0.0).all())) {
    throw std::invalid_argument("ReferenceModelParams.max_rate must be > 0");
  }
}

ReferenceModel::ReferenceModel(const ReferenceModelParams& params, const Eigen::Vector3d& eta0)
    : params_(params) {
  params_.validate();
  reset(eta0);
}

void ReferenceModel::reset(const Eigen::Vector3d& eta) {
  x_ = eta;
  v_.setZero();
  a_.setZero();
}

void ReferenceModel::step(const Eigen::Vector3d& setpoint, double dt) {
  Eigen::Vector3d r = setpoint;
  r.z() = x_.z() + core::wrap_pi(setpoint.z() - x_.z());  // the short way round
  const int substeps = 10;
  const double h = dt / substeps;
  const double k = 2.0 * params_.zeta + 1.0;
  for (int s = 0; s < substeps; ++s) {
    for (int i = 0; i < 3; ++i) {
      const double w = params_.omega[i];
      // Explicit Euler on the jerk with a small substep (h·ω ≤ 0.01): the filter is smooth.
      const double jerk = w * w * w * (r[i] - x_[i]) - k * w * w * v_[i] - k * w * a_[i];
      a_[i] += h * jerk;
      v_[i] += h * a_[i];
      const double vmax = params_.max_rate[i];
      if (std::abs(v_[i]) > vmax) {
        v_[i] = std::copysign(vmax, v_[i]);
        a_[i] = 0.0;
      }
      x_[i] += h * v_[i];
    }
  }
}

DpReference ReferenceModel::reference() const {
  DpReference ref;
  ref.eta_d = x_;
  ref.eta_d.z() = core::wrap_pi(x_.z());
  ref.eta_d_dot = v_;
  ref.eta_d_ddot = a_;
  return ref;
}

bool ReferenceModel::at_rest(double fraction) const noexcept {
  return (v_.array().abs() <= fraction * params_.max_rate.array()).all();
}

bool OperatingCircle::reached(const Eigen::Vector3d& eta, const Eigen::Vector3d& setpoint) const {
  const double distance = std::hypot(eta.x() - setpoint.x(), eta.y() - setpoint.y());
  return distance <= radius_m && std::abs(core::wrap_pi(eta.z() - setpoint.z())) <= heading_tol_rad;
}

}  // namespace dynpos::control
