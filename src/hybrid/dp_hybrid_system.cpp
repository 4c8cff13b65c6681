#include "dynpos/hybrid/dp_hybrid_system.hpp"

#include <Eigen/LU>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dynpos/core/rotation.hpp"

namespace dynpos::hybrid {

control::DpControllerParams case_study_dp_controller() {
  control::DpControllerParams p;
  p.M = Eigen::Vector3d(450.0, 450.0, 100.0).asDiagonal();   // (5.84)
  p.D = 0.1 * p.M;                                           // cancelled by (5.38); see the header
  p.Kp = Eigen::Vector3d(100.0, 100.0, 50.0).asDiagonal();   // (5.85)
  p.Ki = Eigen::Vector3d(10.0, 10.0, 5.0).asDiagonal();      // (5.86)
  p.Kd = Eigen::Vector3d(500.0, 500.0, 200.0).asDiagonal();  // (5.87)
  return p;
}

DpCheck DpHybridParams::check() const {
  return check_dp_conditions(controller.M, controller.Kp, controller.Kd, controller.Ki, lambda,
                             epsilon1, epsilon2, sigma);
}

void DpHybridParams::validate() const {
  if (!eta_d.allFinite()) throw std::invalid_argument("DpHybridParams: eta_d must be finite");
  const DpCheck c = check();
  if (!c.ok()) throw std::invalid_argument("DpHybridParams: " + c.reason);
  controller.validate();
}

DpHybridSystem::DpHybridSystem(const DpHybridParams& params)
    : params_((params.validate(), params)), controller_(params_.controller) {
  reference_.eta_d = params_.eta_d;
  M_inv_ = params_.controller.M.inverse();
  Ki_inv_ = params_.controller.Ki.inverse();
}

DpErrors DpHybridSystem::errors(const sim::ConstVectorRef& x) const {
  const Eigen::Vector3d eta = x.segment<3>(kEta);
  const Eigen::Vector3d nu = x.segment<3>(kNu);
  const Eigen::Vector3d b_hat = x.segment<3>(kBiasHat);
  const control::DpCommand cmd = controller_.control(eta, nu, reference_, b_hat);
  DpErrors e;
  e.x1 = cmd.x1;
  e.x2 = cmd.x2;
  e.x3 = x.segment<3>(kBias) - b_hat;  // (5.35)
  e.psi = eta.z();
  return e;
}

void DpHybridSystem::flow(double, const sim::ConstVectorRef& x, const sim::ConstVectorRef&,
                          sim::VectorRef dxdt) const {
  const Eigen::Vector3d eta = x.segment<3>(kEta);
  const Eigen::Vector3d nu = x.segment<3>(kNu);
  const Eigen::Vector3d b_hat = x.segment<3>(kBiasHat);
  const Eigen::Vector3d b = x.segment<3>(kBias);
  const Eigen::Matrix3d R = core::R_yaw(eta.z());
  const control::DpCommand cmd = controller_.control(eta, nu, reference_, b_hat);  // (5.38)
  const control::DpControllerParams& p = params_.controller;
  dxdt.segment<3>(kEta) = R * nu;                                               // (5.32)
  dxdt.segment<3>(kNu) = M_inv_ * (-p.D * nu + R.transpose() * b + cmd.tau_b);  // (5.33)
  dxdt.segment<3>(kBiasHat) = p.Ki * (R * cmd.x2);                              // (5.36)
  dxdt.segment<3>(kBias).setZero();                                             // (5.34)
  dxdt(kLastJump) = 0.0;
}

Eigen::Vector3d DpHybridSystem::jump_direction(const DpErrors& e) const {
  return params_.jump_frame == JumpFrame::kNed ? Eigen::Vector3d(core::R_yaw(e.psi) * e.x2) : e.x2;
}

bool DpHybridSystem::in_ideal_jump_set(const DpErrors& e) const {
  const double lambda = params_.lambda;
  if (!(e.x1.norm() >= params_.epsilon1)) return false;  // (5.54)
  if (!(e.x2.norm() >= params_.epsilon2)) return false;  // (5.54)
  const Eigen::Vector3d w = jump_direction(e);
  const Eigen::Vector3d Kw = Ki_inv_ * w;
  const double size2 = e.x1.squaredNorm() + e.x2.squaredNorm() + e.x3.squaredNorm();
  return Kw.dot(e.x3) >=
         0.5 * lambda * Kw.dot(w) + params_.sigma / (2.0 * lambda) * size2;  // (5.55)
}

Eigen::Vector3d DpHybridSystem::estimate_x3(const DpErrors& e,
                                            const Eigen::Vector3d& x2_dot) const {
  const control::DpControllerParams& p = params_.controller;
  return core::R_yaw(e.psi) * (p.M * x2_dot + e.x1 + p.Kd * e.x2);  // (5.64)
}

bool DpHybridSystem::in_jump_set(double, const sim::ConstVectorRef& x,
                                 const sim::ConstVectorRef& u) const {
  switch (params_.jump_set) {
    case JumpSet::kNone:
      return false;
    case JumpSet::kIdeal:
      return in_ideal_jump_set(errors(x));
    case JumpSet::kSampled: {
      // An estimate across the last jump mixes two slopes; NaN (no estimate) fails the test.
      if (!(u(kOlderSampleTime) >= x(kLastJump))) return false;
      DpErrors e = errors(x);
      e.x3 = estimate_x3(e, u.segment<3>(kX2DotHat));  // (5.64)–(5.67)
      return in_ideal_jump_set(e);
    }
  }
  return false;
}

void DpHybridSystem::jump(double t, const sim::ConstVectorRef& x, const sim::ConstVectorRef&,
                          sim::VectorRef x_plus) const {
  x_plus = x;
  const DpErrors e = errors(x);
  x_plus.segment<3>(kBiasHat) += params_.lambda * jump_direction(e);  // (5.47)
  x_plus(kLastJump) = t;
}

Eigen::VectorXd DpHybridSystem::initial_state(const Eigen::Vector3d& b0, double t0) const {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(kStateSize);
  x.segment<3>(kEta) = params_.eta_d;
  x.segment<3>(kBiasHat) = b0;
  x.segment<3>(kBias) = b0;
  x(kLastJump) = t0;
  return x;
}

}  // namespace dynpos::hybrid
