#pragma once
/// \file
/// Rotations between BODY and NED, the skew-symmetric matrix, and Euler-angle rates.
///
/// Frames: NED (x north, y east, z down) and BODY (x forward, y starboard, z down). Attitude is
/// the ZYX Euler angles Θ = (φ, θ, ψ) = (roll, pitch, yaw) of (2.2); R_nb = R(Θ) rotates BODY
/// vectors into NED, v_n = R_nb·v_b, as in (2.1). ω = (p, q, r) is the angular velocity of BODY
/// relative to NED, in BODY coordinates (ω_nb_b), as in (2.3).
///
/// The Euler rates Θ̇ = T(Θ)·ω are singular at pitch θ = ±90° (gimbal lock), where cos θ = 0:
/// euler_rate_matrix() throws std::domain_error there (|cos θ| < kGimbalCosTolerance). Its
/// inverse ω = T⁻¹(Θ)·Θ̇ and the rotation matrix itself are defined for every angle.

#include <Eigen/Core>

namespace dynpos::core {

/// ZYX Euler angles [rad] of BODY relative to NED.
struct EulerAngles {
  double roll_rad = 0.0;   ///< φ, about BODY x; euler_from_R() returns it in (−π, π]
  double pitch_rad = 0.0;  ///< θ, about the once-rotated y; euler_from_R(): [−π/2, π/2]
  double yaw_rad = 0.0;    ///< ψ, heading about NED z; euler_from_R(): (−π, π]
};

/// |cos θ| below which euler_rate_matrix() refuses to divide (θ within ≈1e-9 rad of ±90°),
/// and below which euler_from_R() treats the attitude as gimbal-locked.
inline constexpr double kGimbalCosTolerance = 1e-9;

/// The BODY→NED rotation from ZYX Euler angles [rad], (2.4): R(Θ) = R_z(ψ)·R_y(θ)·R_x(φ) =
/// [cψcθ, −sψcφ + cψsθsφ, sψsφ + cψcφsθ; sψcθ, cψcφ + sφsθsψ, −cψsφ + sθsψcφ; −sθ, cθsφ, cθcφ].
Eigen::Matrix3d R_nb_zyx(double roll_rad, double pitch_rad, double yaw_rad);

/// The BODY→NED rotation from ZYX Euler angles, (2.4); see R_nb_zyx(double, double, double).
Eigen::Matrix3d R_nb_zyx(const EulerAngles& theta);

/// The BODY→NED rotation for yaw only (roll = pitch = 0), (2.19):
/// R(ψ) = [cos ψ, −sin ψ, 0; sin ψ, cos ψ, 0; 0, 0, 1].
Eigen::Matrix3d R_yaw(double yaw_rad);

/// The skew-symmetric cross-product matrix, (2.6): S(ω) = [0, −r, q; r, 0, −p; −q, p, 0],
/// so that S(ω)·x = ω × x and Ṙ(Θ) = R(Θ)·S(ω) (2.5).
Eigen::Matrix3d skew(const Eigen::Vector3d& omega);

/// The Euler-rate matrix T(Θ) with Θ̇ = T(Θ)·ω (ω = (p, q, r) in BODY) [rad], Fossen (2011):
/// T(Θ) = [1, sφ·tθ, cφ·tθ; 0, cφ, −sφ; 0, sφ/cθ, cφ/cθ]. Independent of yaw.
/// Throws std::domain_error at gimbal lock, |cos θ| < kGimbalCosTolerance (θ ≈ ±90°).
Eigen::Matrix3d euler_rate_matrix(double roll_rad, double pitch_rad);

/// The inverse Euler-rate matrix, ω = T⁻¹(Θ)·Θ̇ [rad]: T⁻¹(Θ) = [1, 0, −sθ; 0, cφ, cθsφ;
/// 0, −sφ, cθcφ]. Defined for every angle (it is singular, not infinite, at θ = ±90°).
Eigen::Matrix3d euler_rate_matrix_inverse(double roll_rad, double pitch_rad);

/// The ZYX Euler angles of a rotation matrix, the inverse of (2.4): θ = atan2(−R₃₁, √(R₁₁² +
/// R₂₁²)), φ = atan2(R₃₂, R₃₃), ψ = atan2(R₂₁, R₁₁); roll and yaw in (−π, π], pitch in
/// [−π/2, π/2]. At gimbal lock (cos θ < kGimbalCosTolerance) only φ ∓ ψ is observable: roll is
/// set to 0 and yaw carries the whole rotation about the vertical, ψ = atan2(−R₁₂, R₂₂).
/// R must be a rotation matrix (orthonormal, det +1); this is not checked.
EulerAngles euler_from_R(const Eigen::Matrix3d& R_nb);

}  // namespace dynpos::core
