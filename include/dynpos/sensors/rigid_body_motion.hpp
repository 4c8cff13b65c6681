#pragma once
/// \file
/// RigidBodyMotion: the full 6-DOF kinematics of the vessel's control origin at one instant, and
/// the motion of any point fixed in the hull (a sensor at its lever arm).
///
/// Frames: NED (x north, y east, z down) and BODY (x forward, y starboard, z down); R_nb = R(Θ)
/// (2.4) rotates BODY vectors into NED. Thesis chapter 4 writes the antenna position (4.2) and
/// the MRU acceleration (4.65) of a point at lever arm l from these quantities.

#include <Eigen/Core>

namespace dynpos::sensors {

/// Standard gravity [m/s²], the magnitude of g_n = (0, 0, g) in NED.
inline constexpr double kGravity_mps2 = 9.80665;

struct RigidBodyMotion {
  Eigen::Vector3d p_n = Eigen::Vector3d::Zero();    ///< control-origin position in NED [m]
  Eigen::Vector3d v_n = Eigen::Vector3d::Zero();    ///< its velocity in NED [m/s]
  Eigen::Vector3d a_n = Eigen::Vector3d::Zero();    ///< its acceleration in NED [m/s²]
  Eigen::Vector3d theta = Eigen::Vector3d::Zero();  ///< Θ = (φ, θ, ψ) roll, pitch, yaw [rad]
  Eigen::Vector3d omega_nb_b = Eigen::Vector3d::Zero();      ///< ω = (p, q, r) in BODY [rad/s]
  Eigen::Vector3d omega_dot_nb_b = Eigen::Vector3d::Zero();  ///< ω̇ in BODY [rad/s²]

  /// R(Θ), (2.4).
  Eigen::Matrix3d R_nb() const;
  /// Velocity of the control origin in BODY, ν = R(Θ)ᵀ v_n [m/s].
  Eigen::Vector3d v_b() const;
};

/// NED position of the hull point at lever arm l_b, (4.2): P = P₀ + R(Θ)·l.
Eigen::Vector3d point_position_n(const RigidBodyMotion& m, const Eigen::Vector3d& l_b);

/// BODY velocity of the hull point at lever arm l_b: R(Θ)ᵀv_n + ω × l.
Eigen::Vector3d point_velocity_b(const RigidBodyMotion& m, const Eigen::Vector3d& l_b);

/// Kinematic acceleration of the hull point at lever arm l_b, in BODY: R(Θ)ᵀ A with
/// A = A₀ + R(Θ)(S(ω)² + S(ω̇))·l, (4.65).
Eigen::Vector3d point_acceleration_b(const RigidBodyMotion& m, const Eigen::Vector3d& l_b);

/// Specific force at lever arm l_b in BODY, what an accelerometer senses: f = R(Θ)ᵀ(A − g_n),
/// so a hull at rest and level reads f = (0, 0, −g).
Eigen::Vector3d point_specific_force_b(const RigidBodyMotion& m, const Eigen::Vector3d& l_b);

}  // namespace dynpos::sensors
