#include "dynpos/control/dp_controller.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dynpos/core/angle.hpp"
#include "dynpos/core/rotation.hpp"

namespace dynpos::control {
namespace {

bool positive_definite(const Eigen::Matrix3d& m) {
  if (!m.isApprox(m.transpose(), 1e-12)) return false;
  return Eigen::LLT<Eigen::Matrix3d>(m).info() == Eigen::Success;
}

bool positive_diagonal(const Eigen::Matrix3d& m) {
  const Eigen::Matrix3d off = m - Eigen::Matrix3d(m.diagonal().asDiagonal());
  return off.isZero(0.0) && (m.diagonal().array() > 0.0).all() && m.allFinite();
}

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("DpControllerParams." + what);
}

// S of (5.39): Ṙ(ψ)ᵀ = −r·S·R(ψ)ᵀ.
Eigen::Matrix3d yaw_skew() {
  Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
  s(0, 1) = -1.0;
  s(1, 0) = 1.0;
  return s;
}

}  // namespace

void DpControllerParams::validate() const {
  require(positive_definite(M), "M must be symmetric positive definite");
  require(positive_definite(D), "D must be symmetric positive definite");
  require(positive_diagonal(Kp), "Kp must be diagonal with positive entries");
  require(positive_diagonal(Kd), "Kd must be diagonal with positive entries");
  require(positive_diagonal(Ki), "Ki must be diagonal with positive entries");
  require((bias_limit.array() > 0.0).all(), "bias_limit must be > 0");
}

DpController::DpController(const DpControllerParams& params) : params_(params) {
  params_.validate();
  Ki_inv_ = params_.Ki.inverse();
}

DpCommand DpController::control(const Eigen::Vector3d& eta, const Eigen::Vector3d& nu,
                                const DpReference& ref, const Eigen::Vector3d& bias_hat_n) const {
  const DpControllerParams& p = params_;
  const double psi = eta.z();
  const Eigen::Matrix3d R = core::R_yaw(psi);
  const Eigen::Matrix3d Rt = R.transpose();
  Eigen::Vector3d eta_err = eta - ref.eta_d;
  eta_err.z() = core::wrap_pi(eta_err.z());
  DpCommand out;
  out.x1 = Rt * eta_err;                                           // (5.35)
  const Eigen::Vector3d mu = -p.Kp * out.x1 + Rt * ref.eta_d_dot;  // (5.37)
  out.x2 = nu - mu;                                                // (5.35)
  // μ̇ = −K_p ẋ₁ + Ṙᵀη̇_d + Rᵀη̈_d with ẋ₁ = −r S x₁ + ν − Rᵀη̇_d and Ṙᵀ = −r S Rᵀ.
  const double r = nu.z();
  const Eigen::Matrix3d S = yaw_skew();
  const Eigen::Vector3d x1_dot = -r * S * out.x1 + nu - Rt * ref.eta_d_dot;
  const Eigen::Vector3d mu_dot = -p.Kp * x1_dot - r * S * Rt * ref.eta_d_dot + Rt * ref.eta_d_ddot;
  out.tau_b = -out.x1 - p.Kd * out.x2 - Rt * bias_hat_n + p.D * nu + p.M * mu_dot;  // (5.38)
  return out;
}

Eigen::Vector3d DpController::bias_rate(double psi, const Eigen::Vector3d& x2) const {
  return params_.Ki * core::R_yaw(psi) * x2;  // (5.36), see the file comment for the sign
}

Eigen::Vector3d DpController::advance_bias(const Eigen::Vector3d& bias_hat_n, double psi,
                                           const Eigen::Vector3d& x2, double dt) const {
  const Eigen::Vector3d next = bias_hat_n + dt * bias_rate(psi, x2);
  return next.cwiseMax(-params_.bias_limit).cwiseMin(params_.bias_limit);
}

double DpController::lyapunov(const Eigen::Vector3d& x1, const Eigen::Vector3d& x2,
                              const Eigen::Vector3d& x3) const {
  return 0.5 * x1.dot(x1) + 0.5 * x2.dot(params_.M * x2) + 0.5 * x3.dot(Ki_inv_ * x3);  // (5.48)
}

}  // namespace dynpos::control
