#include "dynpos/core/rotation.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "dynpos/core/angle.hpp"

namespace dynpos::core {

Eigen::Matrix3d R_nb_zyx(double roll_rad, double pitch_rad, double yaw_rad) {
  const double cphi = std::cos(roll_rad);
  const double sphi = std::sin(roll_rad);
  const double cth = std::cos(pitch_rad);
  const double sth = std::sin(pitch_rad);
  const double cpsi = std::cos(yaw_rad);
  const double spsi = std::sin(yaw_rad);
  Eigen::Matrix3d R;
  R << cpsi * cth, -spsi * cphi + cpsi * sth * sphi, spsi * sphi + cpsi * cphi * sth,  //
      spsi * cth, cpsi * cphi + sphi * sth * spsi, -cpsi * sphi + sth * spsi * cphi,   //
      -sth, cth * sphi, cth * cphi;
  return R;
}

Eigen::Matrix3d R_nb_zyx(const EulerAngles& theta) {
  return R_nb_zyx(theta.roll_rad, theta.pitch_rad, theta.yaw_rad);
}

Eigen::Matrix3d R_yaw(double yaw_rad) {
  const double c = std::cos(yaw_rad);
  const double s = std::sin(yaw_rad);
  Eigen::Matrix3d R;
  R << c, -s, 0.0,  //
      s, c, 0.0,    //
      0.0, 0.0, 1.0;
  return R;
}

Eigen::Matrix3d skew(const Eigen::Vector3d& omega) {
  const double p = omega.x();
  const double q = omega.y();
  const double r = omega.z();
  Eigen::Matrix3d S;
  S << 0.0, -r, q,  //
      r, 0.0, -p,   //
      -q, p, 0.0;
  return S;
}

Eigen::Matrix3d euler_rate_matrix(double roll_rad, double pitch_rad) {
  const double cth = std::cos(pitch_rad);
  if (!(std::abs(cth) >= kGimbalCosTolerance)) {  // also rejects NaN
    throw std::domain_error("euler_rate_matrix: pitch " + std::to_string(rad_to_deg(pitch_rad)) +
                            " deg is at the gimbal-lock singularity (|cos(pitch)| < " +
                            std::to_string(kGimbalCosTolerance) +
                            "); Euler rates are undefined there");
  }
  const double cphi = std::cos(roll_rad);
  const double sphi = std::sin(roll_rad);
  const double tth = std::sin(pitch_rad) / cth;
  Eigen::Matrix3d T;
  T << 1.0, sphi * tth, cphi * tth,  //
      0.0, cphi, -sphi,              //
      0.0, sphi / cth, cphi / cth;
  return T;
}

Eigen::Matrix3d euler_rate_matrix_inverse(double roll_rad, double pitch_rad) {
  const double cphi = std::cos(roll_rad);
  const double sphi = std::sin(roll_rad);
  const double cth = std::cos(pitch_rad);
  const double sth = std::sin(pitch_rad);
  Eigen::Matrix3d T_inv;
  T_inv << 1.0, 0.0, -sth,    //
      0.0, cphi, cth * sphi,  //
      0.0, -sphi, cth * cphi;
  return T_inv;
}

EulerAngles euler_from_R(const Eigen::Matrix3d& R_nb) {
  // cos θ from the first column; atan2 keeps θ accurate near ±90°, where asin(−R₃₁) is not.
  const double cth = std::hypot(R_nb(0, 0), R_nb(1, 0));
  EulerAngles theta;
  theta.pitch_rad = std::atan2(-R_nb(2, 0), cth);
  if (cth < kGimbalCosTolerance) {
    // With cos θ = 0, R₁₂ = −sin(ψ ∓ φ) and R₂₂ = cos(ψ ∓ φ) for θ = ±90°: put it all in yaw.
    theta.roll_rad = 0.0;
    theta.yaw_rad = wrap_pi(std::atan2(-R_nb(0, 1), R_nb(1, 1)));
  } else {
    theta.roll_rad = wrap_pi(std::atan2(R_nb(2, 1), R_nb(2, 2)));
    theta.yaw_rad = wrap_pi(std::atan2(R_nb(1, 0), R_nb(0, 0)));
  }
  return theta;
}

}  // namespace dynpos::core
