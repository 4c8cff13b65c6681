#include "vessel_motion.hpp"

#include <cmath>

#include "dynpos/model/hull.hpp"

namespace dynpos::scenario::detail {

using model::Hull;

sensors::RigidBodyMotion compose_motion(const Eigen::Ref<const Eigen::VectorXd>& x,
                                        const Eigen::Ref<const Eigen::VectorXd>& dx,
                                        const model::WaveMotion6& wf) {
  // Low frequency: planar position p_l, heading ψ_l with rate r_l = ψ̇_l and ṙ_l.
  const double psi = x[Hull::kYaw], r = dx[Hull::kYaw], r_dot = dx[Hull::kYawRate];
  const double c = std::cos(psi), s = std::sin(psi);
  const Eigen::Matrix2d R2{{c, -s}, {s, c}};
  const Eigen::Vector2d p_l(x[Hull::kNorth], x[Hull::kEast]);
  const Eigen::Vector2d v_l(dx[Hull::kNorth], dx[Hull::kEast]);
  // p̈_l = d/dt(R(ψ)ν) = R(ψ)(ν̇ + r·S·ν) with S(a, b) = (−b, a).
  const Eigen::Vector2d nu(x[Hull::kSurge], x[Hull::kSway]);
  const Eigen::Vector2d nu_dot(dx[Hull::kSurge], dx[Hull::kSway]);
  const auto S = [](const Eigen::Vector2d& a) { return Eigen::Vector2d(-a.y(), a.x()); };
  const Eigen::Vector2d a_l = R2 * (nu_dot + r * S(nu));

  // Wave frequency: ξ along the LF axes, p = p_l + R(ψ_l)ξ; differentiate twice.
  const Eigen::Vector2d xi = wf.position.head<2>(), xi_d = wf.velocity.head<2>(),
                        xi_dd = wf.acceleration.head<2>();
  sensors::RigidBodyMotion m;
  m.p_n << p_l + R2 * xi, wf.position[2];
  m.v_n << v_l + R2 * (xi_d + r * S(xi)), wf.velocity[2];
  m.a_n << a_l + R2 * (xi_dd + 2.0 * r * S(xi_d) + r_dot * S(xi) - r * r * xi), wf.acceleration[2];

  // Euler angles and their first two derivatives.
  const Eigen::Vector3d th(x[Hull::kRoll] + wf.position[3], x[Hull::kPitch] + wf.position[4],
                           psi + wf.position[5]);
  const Eigen::Vector3d th_d(dx[Hull::kRoll] + wf.velocity[3], dx[Hull::kPitch] + wf.velocity[4],
                             r + wf.velocity[5]);
  const Eigen::Vector3d th_dd(dx[Hull::kRollRate] + wf.acceleration[3],
                              dx[Hull::kPitchRate] + wf.acceleration[4],
                              r_dot + wf.acceleration[5]);
  m.theta = th;
  // ω = T(Θ)⁻¹Θ̇ with T⁻¹ = [1 0 −sθ; 0 cφ cθsφ; 0 −sφ cθcφ]; ω̇ = T⁻¹Θ̈ + (dT⁻¹/dt)Θ̇.
  const double sphi = std::sin(th.x()), cphi = std::cos(th.x());
  const double sth = std::sin(th.y()), cth = std::cos(th.y());
  const double phid = th_d.x(), thd = th_d.y();
  const Eigen::Matrix3d T_inv{{1.0, 0.0, -sth}, {0.0, cphi, cth * sphi}, {0.0, -sphi, cth * cphi}};
  const Eigen::Matrix3d T_inv_dot{{0.0, 0.0, -cth * thd},
                                  {0.0, -sphi * phid, -sth * thd * sphi + cth * cphi * phid},
                                  {0.0, -cphi * phid, -sth * thd * cphi - cth * sphi * phid}};
  m.omega_nb_b = T_inv * th_d;
  m.omega_dot_nb_b = T_inv * th_dd + T_inv_dot * th_d;
  return m;
}

}  // namespace dynpos::scenario::detail
