#include "dynpos/sensors/rigid_body_motion.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

#include "dynpos/core/rotation.hpp"

namespace dynpos::sensors {
namespace {

// A smooth analytic 6-DOF trajectory: position, Euler angles and all their derivatives in
// closed form, so the point kinematics can be checked against finite differences of (4.2).
struct Trajectory {
  static Eigen::Vector3d pos(double t) {
    return {3.0 * t + 2.0 * std::sin(0.3 * t), -1.0 + std::cos(0.2 * t), 0.4 * std::sin(0.9 * t)};
  }
  static Eigen::Vector3d euler(double t) {
    return {0.05 * std::sin(1.1 * t), 0.03 * std::cos(0.7 * t), 0.2 * t + 0.1 * std::sin(0.5 * t)};
  }
  static Eigen::Vector3d d(Eigen::Vector3d (*f)(double), double t, double h = 1e-4) {
    return (f(t + h) - f(t - h)) / (2.0 * h);
  }
  static Eigen::Vector3d dd(Eigen::Vector3d (*f)(double), double t, double h = 1e-3) {
    return (f(t + h) - 2.0 * f(t) + f(t - h)) / (h * h);
  }
  // ω = T(Θ)⁻¹Θ̇ and its derivative by differences of ω(t).
  static Eigen::Vector3d omega(double t) {
    const Eigen::Vector3d th = euler(t);
    return core::euler_rate_matrix_inverse(th.x(), th.y()) * d(euler, t);
  }
  static RigidBodyMotion at(double t) {
    RigidBodyMotion m;
    m.p_n = pos(t);
    m.v_n = d(pos, t);
    m.a_n = dd(pos, t);
    m.theta = euler(t);
    m.omega_nb_b = omega(t);
    m.omega_dot_nb_b = d(omega, t, 1e-3);
    return m;
  }
};

const Eigen::Vector3d kArm(14.978, 0.039, 0.568);  // MRU 2, table 4.6

Eigen::Vector3d point_n(double t) { return point_position_n(Trajectory::at(t), kArm); }

TEST(RigidBodyMotion, OriginPointIsThePosition) {
  const RigidBodyMotion m = Trajectory::at(2.0);
  EXPECT_EQ(point_position_n(m, Eigen::Vector3d::Zero()), m.p_n);
}

TEST(RigidBodyMotion, PointVelocityIsTheDerivativeOfItsPosition) {
  for (double t : {0.0, 1.3, 7.7}) {
    const RigidBodyMotion m = Trajectory::at(t);
    const Eigen::Vector3d v_fd = m.R_nb().transpose() * Trajectory::d(point_n, t, 1e-4);
    // Central differences, h = 1e-4 s: truncation ~h²·|p'''| ≈ 1e-8 m/s, round-off ~1e-16·|p|/h.
    EXPECT_LT((point_velocity_b(m, kArm) - v_fd).norm(), 1e-6) << "t = " << t;
  }
}

TEST(RigidBodyMotion, PointAccelerationIsTheSecondDerivativeOfItsPosition) {
  for (double t : {0.0, 1.3, 7.7}) {
    const RigidBodyMotion m = Trajectory::at(t);
    const Eigen::Vector3d a_fd = m.R_nb().transpose() * Trajectory::dd(point_n, t, 1e-3);
    // Second differences at h = 1e-3 s: truncation ~h²/12·|p''''| ~1e-7, round-off
    // ~1e-16·|p|/h² ~1e-9; the ω̇ fed in is itself a difference (error ~1e-7 rad/s² × 15 m).
    EXPECT_LT((point_acceleration_b(m, kArm) - a_fd).norm(), 1e-5) << "t = " << t;
  }
}

TEST(RigidBodyMotion, SpecificForceOfALevelHullAtRestIsMinusGravity) {
  RigidBodyMotion m;
  m.theta = {0.0, 0.0, 1.2};  // heading does not matter
  const Eigen::Vector3d f = point_specific_force_b(m, kArm);
  EXPECT_NEAR(f.x(), 0.0, 1e-12);
  EXPECT_NEAR(f.y(), 0.0, 1e-12);
  EXPECT_NEAR(f.z(), -kGravity_mps2, 1e-12);
}

TEST(RigidBodyMotion, SpecificForceAndKinematicAccelerationDifferByGravityInBody) {
  const RigidBodyMotion m = Trajectory::at(3.0);
  const Eigen::Vector3d g_b = m.R_nb().transpose() * Eigen::Vector3d(0, 0, kGravity_mps2);
  EXPECT_LT((point_acceleration_b(m, kArm) - point_specific_force_b(m, kArm) - g_b).norm(), 1e-12);
}

}  // namespace
}  // namespace dynpos::sensors
