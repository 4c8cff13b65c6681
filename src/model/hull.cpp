#include "dynpos/model/hull.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dynpos/core/error.hpp"

namespace dynpos::model {
namespace {

// The [hull] table: every parameter with its range (core/param_range.hpp).
template <typename P>
std::vector<core::BasicParamField<core::ParamValue<P>>> fields(P& p) {
  return {
      {{"mass_kg", "kg", 1e3, 1e8}, &p.mass_kg},
      {{"iz_kgm2", "kg·m²", 1, 1e12}, &p.iz_kgm2},
      {{"xg_m", "m", -100, 100}, &p.xg_m},
      {{"x_udot_kg", "kg", 0, 1e8}, &p.x_udot_kg},
      {{"y_vdot_kg", "kg", 0, 1e8}, &p.y_vdot_kg},
      {{"y_rdot_kgm", "kg·m", -1e10, 1e10}, &p.y_rdot_kgm},
      {{"n_rdot_kgm2", "kg·m²", 0, 1e12}, &p.n_rdot_kgm2},
      {{"x_u_Ns_m", "N·s/m", 1e-3, 1e8}, &p.x_u_Ns_m},
      {{"x_uu_Ns2_m2", "N·s²/m²", 0, 1e8}, &p.x_uu_Ns2_m2},
      {{"y_v_Ns_m", "N·s/m", 1e-3, 1e9}, &p.y_v_Ns_m},
      {{"y_uv_Ns2_m2", "N·s²/m²", 0, 1e9}, &p.y_uv_Ns2_m2},
      {{"y_vv_Ns2_m2", "N·s²/m²", 0, 1e9}, &p.y_vv_Ns2_m2},
      {{"y_ur_Ns2", "N·s²", -1e10, 1e10}, &p.y_ur_Ns2},
      {{"n_uv_Ns2", "N·s²", -1e10, 1e10}, &p.n_uv_Ns2},
      {{"n_r_Nms", "N·m·s", 1e-3, 1e12}, &p.n_r_Nms},
      {{"n_ur_Nms2", "N·m·s²", 0, 1e12}, &p.n_ur_Nms2},
      {{"n_rr_Nms2", "N·m·s²", 0, 1e13}, &p.n_rr_Nms2},
      {{"roll_period_s", "s", 0.5, 60}, &p.roll_period_s},
      {{"roll_damping_ratio", "1", 1e-3, 2}, &p.roll_damping_ratio},
      {{"heel_per_centripetal", "rad·s²/m", -10, 10}, &p.heel_per_centripetal},
      {{"pitch_period_s", "s", 0.5, 60}, &p.pitch_period_s},
      {{"pitch_damping_ratio", "1", 1e-3, 2}, &p.pitch_damping_ratio},
      {{"trim_per_surge_accel", "rad·s²/m", -10, 10}, &p.trim_per_surge_accel},
  };
}

}  // namespace

std::vector<core::ParamField> param_fields(HullParams& params) { return fields(params); }

void HullParams::validate() const {
  core::check_ranges("hull", fields(*this));
  const double m22 = mass_kg + y_vdot_kg;
  const double m33 = iz_kgm2 + n_rdot_kgm2;
  const double m23 = mass_kg * xg_m + y_rdot_kgm;
  if (!(m22 * m33 - m23 * m23 > 0)) {
    throw core::InputError({},
                           "HullParams.y_rdot_kgm must be small enough that M is positive "
                           "definite");
  }
}

Hull::Hull(const HullParams& params) : params_(params) {
  params_.validate();
  const HullParams& p = params_;
  M_ << p.mass_kg + p.x_udot_kg, 0.0, 0.0,                              //
      0.0, p.mass_kg + p.y_vdot_kg, p.mass_kg * p.xg_m + p.y_rdot_kgm,  //
      0.0, p.mass_kg * p.xg_m + p.y_rdot_kgm, p.iz_kgm2 + p.n_rdot_kgm2;
  M_inv_ = M_.inverse();
}

Eigen::Vector3d Hull::hydrodynamic_forces(const Eigen::Vector3d& nu,
                                          const Eigen::Vector3d& nu_r) const noexcept {
  const HullParams& p = params_;
  const double m = p.mass_kg;
  const double u = nu.x(), v = nu.y(), r = nu.z();
  const double ur = nu_r.x(), vr = nu_r.y();
  // C_RB(ν)ν (Fossen 2011, 3-DOF, x_g on the centre line).
  const Eigen::Vector3d c_rb(-m * (p.xg_m * r * r + v * r), m * u * r, m * p.xg_m * u * r);
  // C_A(ν_r)ν_r with X_u̇ = −x_udot, Y_v̇ = −y_vdot, Y_ṙ = N_v̇ = −y_rdot (Munk moment included).
  const double a2 = -p.y_vdot_kg * vr - p.y_rdot_kgm * r;
  const Eigen::Vector3d c_a(a2 * r, p.x_udot_kg * ur * r, -a2 * ur - p.x_udot_kg * ur * vr);
  // D(ν_r)ν_r: linear + quadratic (2.8) in surge; speed-dependent sway–yaw damping.
  const double abs_u = std::abs(ur);
  const Eigen::Vector3d d(
      (p.x_u_Ns_m + p.x_uu_Ns2_m2 * abs_u) * ur,
      (p.y_v_Ns_m + p.y_uv_Ns2_m2 * abs_u + p.y_vv_Ns2_m2 * std::abs(vr)) * vr +
          p.y_ur_Ns2 * ur * r,
      p.n_uv_Ns2 * ur * vr + (p.n_r_Nms + p.n_ur_Nms2 * abs_u + p.n_rr_Nms2 * std::abs(r)) * r);
  return -(c_rb + c_a + d);
}

Hull::State Hull::derivatives(const State& x, const Eigen::Vector3d& tau_b,
                              const Eigen::Vector2d& current_n) const noexcept {
  const HullParams& p = params_;
  const double psi = x[kYaw];
  const double c = std::cos(psi), s = std::sin(psi);
  const Eigen::Vector3d nu(x[kSurge], x[kSway], x[kYawRate]);
  // Current in BODY: v_c,b = R(ψ)ᵀ v_c,n (2.19); constant current, so ν̇_c = 0 in NED.
  const Eigen::Vector3d nu_c(c * current_n.x() + s * current_n.y(),
                             -s * current_n.x() + c * current_n.y(), 0.0);
  const Eigen::Vector3d nu_dot = this->nu_dot(nu, nu - nu_c, tau_b);

  State dx;
  // η̇ = R(ψ)ν (2.20).
  dx[kNorth] = c * nu.x() - s * nu.y();
  dx[kEast] = s * nu.x() + c * nu.y();
  dx[kYaw] = nu.z();
  dx.segment<3>(kSurge) = nu_dot;
  // Roll: φ̈ + 2ζωφ̇ + ω²φ = ω²·k_heel·u·r (quasi-static outward heel in a turn).
  const double w_roll = 2.0 * M_PI / p.roll_period_s;
  dx[kRoll] = x[kRollRate];
  dx[kRollRate] = -2.0 * p.roll_damping_ratio * w_roll * x[kRollRate] -
                  w_roll * w_roll * (x[kRoll] - p.heel_per_centripetal * nu.x() * nu.z());
  // Pitch: θ̈ + 2ζωθ̇ + ω²θ = ω²·k_trim·u̇ (trim while accelerating).
  const double w_pitch = 2.0 * M_PI / p.pitch_period_s;
  dx[kPitch] = x[kPitchRate];
  dx[kPitchRate] = -2.0 * p.pitch_damping_ratio * w_pitch * x[kPitchRate] -
                   w_pitch * w_pitch * (x[kPitch] - p.trim_per_surge_accel * nu_dot.x());
  return dx;
}

double Hull::steady_surge_speed(double surge_force) const noexcept {
  const double a = params_.x_uu_Ns2_m2, b = params_.x_u_Ns_m, f = std::abs(surge_force);
  const double u = a > 0 ? (-b + std::sqrt(b * b + 4.0 * a * f)) / (2.0 * a) : f / b;
  return std::copysign(u, surge_force);
}

double Hull::surge_time_constant(double u0) const noexcept {
  return M_(0, 0) / (params_.x_u_Ns_m + 2.0 * params_.x_uu_Ns2_m2 * std::abs(u0));
}

Eigen::Matrix2d Hull::sway_yaw_linear(double u0) const noexcept {
  const HullParams& p = params_;
  // N(u₀) of (2.9): linearisation of C_RB + C_A + D about (u₀, 0, 0) in (v, r).
  Eigen::Matrix2d n;
  n << p.y_v_Ns_m + p.y_uv_Ns2_m2 * std::abs(u0), (p.mass_kg + p.x_udot_kg) * u0 + p.y_ur_Ns2 * u0,
      (p.y_vdot_kg - p.x_udot_kg) * u0 + p.n_uv_Ns2 * u0,
      (p.mass_kg * p.xg_m + p.y_rdot_kgm) * u0 + p.n_r_Nms + p.n_ur_Nms2 * std::abs(u0);
  return n;
}

Hull::Nomoto Hull::nomoto(double u0, double x_rudder_m) const {
  if (!(u0 > 0.0)) throw std::invalid_argument("Hull::nomoto needs a forward speed u0 > 0");
  const Eigen::Matrix2d m2 = M_.bottomRightCorner<2, 2>();
  const Eigen::Matrix2d a = -m2.inverse() * sway_yaw_linear(u0);
  const Eigen::Vector2d b = m2.inverse() * Eigen::Vector2d(1.0, x_rudder_m);
  const Eigen::Vector2cd ev = a.eigenvalues();
  // r/F(s) = (b₂ s + a₂₁b₁ − a₁₁b₂) / det(sI − A)  ⇒  T₃ = b₂ / (a₂₁b₁ − a₁₁b₂).
  Nomoto out{};
  const double t_a = -1.0 / ev[0].real(), t_b = -1.0 / ev[1].real();
  out.t1_s = std::max(t_a, t_b);
  out.t2_s = std::min(t_a, t_b);
  out.t3_s = b.y() / (a(1, 0) * b.x() - a(0, 0) * b.y());
  out.tr_s = out.t1_s + out.t2_s - out.t3_s;  // (2.13)
  return out;
}

}  // namespace dynpos::model
