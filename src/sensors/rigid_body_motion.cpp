#include "dynpos/sensors/rigid_body_motion.hpp"

#include <Eigen/Geometry>

#include "dynpos/core/rotation.hpp"

namespace dynpos::sensors {

Eigen::Matrix3d RigidBodyMotion::R_nb() const {
  return core::R_nb_zyx(theta.x(), theta.y(), theta.z());
}

Eigen::Vector3d RigidBodyMotion::v_b() const { return R_nb().transpose() * v_n; }

Eigen::Vector3d point_position_n(const RigidBodyMotion& m, const Eigen::Vector3d& l_b) {
  return m.p_n + m.R_nb() * l_b;
}

Eigen::Vector3d point_velocity_b(const RigidBodyMotion& m, const Eigen::Vector3d& l_b) {
  return m.v_b() + m.omega_nb_b.cross(l_b);
}

Eigen::Vector3d point_acceleration_b(const RigidBodyMotion& m, const Eigen::Vector3d& l_b) {
  // S(ω)²l = ω × (ω × l), S(ω̇)l = ω̇ × l.
  const Eigen::Vector3d& w = m.omega_nb_b;
  return m.R_nb().transpose() * m.a_n + w.cross(w.cross(l_b)) + m.omega_dot_nb_b.cross(l_b);
}

Eigen::Vector3d point_specific_force_b(const RigidBodyMotion& m, const Eigen::Vector3d& l_b) {
  const Eigen::Vector3d g_b = m.R_nb().transpose() * Eigen::Vector3d(0.0, 0.0, kGravity_mps2);
  return point_acceleration_b(m, l_b) - g_b;
}

}  // namespace dynpos::sensors
