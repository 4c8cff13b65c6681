#include "dynpos/hybrid/integral_jump.hpp"

#include <Eigen/LU>
#include <cmath>

#include "dynpos/core/rotation.hpp"

namespace dynpos::hybrid {

namespace {

// The scenario file's [hybrid] table (core/param_range.hpp).
template <typename P>
std::vector<core::BasicParamField<core::ParamValue<P>>> fields(P& p) {
  return {
      {{"lambda_surge_Ns_m", "N·s/m", 1e-6, 1e12}, &p.lambda.x()},
      {{"lambda_sway_Ns_m", "N·s/m", 1e-6, 1e12}, &p.lambda.y()},
      {{"lambda_yaw_Nms_rad", "N·m·s/rad", 1e-6, 1e14}, &p.lambda.z()},
      {{"epsilon1", "1", 1e-9, 1e3}, &p.epsilon1},
      {{"epsilon2", "1", 1e-9, 1e3}, &p.epsilon2},
      {{"sigma", "1", 0, 1e6}, &p.sigma},
      {{"dwell_s", "s", 1e-3, 1e4}, &p.dwell_s},
  };
}

}  // namespace

std::vector<core::ParamField> param_fields(IntegralJumpParams& params) { return fields(params); }

void IntegralJumpParams::validate() const { core::check_ranges("hybrid", fields(*this)); }

Eigen::Vector3d jump_direction(const Eigen::Vector3d& x2_b, double psi_rad) {
  return core::R_yaw(psi_rad) * x2_b;
}

Eigen::Vector3d integral_jump(const IntegralJumpParams& p, const Eigen::Vector3d& x2_b,
                              double psi_rad) {
  return p.lambda.cwiseProduct(jump_direction(x2_b, psi_rad));  // (5.47)
}

double lyapunov_change_at_jump(const IntegralJumpParams& p, const Eigen::Matrix3d& Ki,
                               const Eigen::Vector3d& x1, const Eigen::Vector3d& x2_b,
                               const Eigen::Vector3d& x3_n, double psi_rad) {
  (void)x1;  // V's x₁ and x₂ terms do not change at a jump
  const Eigen::Vector3d d = integral_jump(p, x2_b, psi_rad);
  const Eigen::Matrix3d Ki_inv = Ki.inverse();
  const Eigen::Vector3d x3_plus = x3_n - d;
  return 0.5 * x3_plus.dot(Ki_inv * x3_plus) - 0.5 * x3_n.dot(Ki_inv * x3_n);
}

bool in_integral_jump_set(const IntegralJumpParams& p, const Eigen::Matrix3d& Ki,
                          const Eigen::Vector3d& x1, const Eigen::Vector3d& x2_b,
                          const Eigen::Vector3d& x3_n, double psi_rad) {
  if (!(x1.norm() >= p.epsilon1) || !(x2_b.norm() >= p.epsilon2)) return false;  // (5.54)
  const Eigen::Vector3d d = integral_jump(p, x2_b, psi_rad);
  const Eigen::Vector3d Ki_inv_d = Ki.inverse() * d;
  const double size2 = x1.squaredNorm() + x2_b.squaredNorm() + x3_n.squaredNorm();
  return Ki_inv_d.dot(x3_n) >= 0.5 * Ki_inv_d.dot(d) + 0.5 * p.sigma * size2;  // (5.55)
}

Eigen::Vector3d estimate_integral_error(const Eigen::Matrix3d& M, const Eigen::Matrix3d& Kd,
                                        const Eigen::Vector3d& x1, const Eigen::Vector3d& x2_b,
                                        const Eigen::Vector3d& x2_dot_b, double psi_rad) {
  return core::R_yaw(psi_rad) * (M * x2_dot_b + x1 + Kd * x2_b);  // (5.64)
}

}  // namespace dynpos::hybrid
