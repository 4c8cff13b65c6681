#pragma once
/// \file
/// The hull of the virtual vessel: a 3-DOF low-frequency maneuvering model in surge, sway and
/// yaw (thesis (2.7), (2.8), (2.20)) with Coriolis and centripetal terms at speed, plus roll and
/// pitch oscillators driven by the turn (heel) and by surge acceleration (trim).
///
/// Kinetics (Fossen 2011, as in thesis (2.7) without waves, which are added as wave-frequency
/// motion on top):
///
///     M ν̇ + C_RB(ν) ν + C_A(ν_r) ν_r + D(ν_r) ν_r = τ_act + τ_env,   ν_r = ν − R(ψ)ᵀ v_c
///
/// with M = M_RB + M_A from (2.10), linear + quadratic surge damping (2.8), and sway–yaw damping
/// whose linear part grows with the surge speed, so that the rudder-to-yaw-rate response is a
/// Nomoto model (2.9)–(2.16) whose time constant shortens with speed.
///
/// State x ∈ ℝ¹⁰: η = (N, E, ψ) [m, m, rad], ν = (u, v, r) [m/s, m/s, rad/s], roll φ [rad],
/// roll rate φ̇ [rad/s], pitch θ [rad], pitch rate θ̇ [rad/s] (low-frequency parts).

#include <Eigen/Core>
#include <vector>

#include "dynpos/core/param_range.hpp"

namespace dynpos::model {

/// Hull parameters. Defaults: the virtual R/V Gunnerus (before the 2015 retrofit); every value
/// says where it comes from.
struct HullParams {
  /// Mass m [kg], (1e3, 1e8). Source: reasoned — Lpp ≈ 28.9 m, B = 9.6 m, T = 2.7 m (Gunnerus
  /// main dimensions) with a block coefficient ≈ 0.6 gives ∇ ≈ 450 m³, so m ≈ 460 t.
  double mass_kg = 460e3;
  /// Yaw inertia I_z [kg·m²]. Source: reasoned — radius of gyration 0.27·Lpp ≈ 7.8 m.
  double iz_kgm2 = 2.8e7;
  /// Longitudinal centre of gravity x_g from the control origin [m]. Source: reasoned, 0.
  double xg_m = 0.0;
  /// Added mass −X_u̇ [kg], ≥ 0. Source: reasoned — ≈ 5 % of m for a full, short hull.
  double x_udot_kg = 23e3;
  /// Added mass −Y_v̇ [kg], ≥ 0. Source: reasoned — ≈ 0.8·m, strip theory for B/T ≈ 3.6.
  double y_vdot_kg = 370e3;
  /// Added mass −Y_ṙ = −N_v̇ [kg·m]. Source: reasoned — small for a fore–aft symmetric hull.
  double y_rdot_kgm = 3.0e5;
  /// Added inertia −N_ṙ [kg·m²], ≥ 0. Source: reasoned — ≈ 0.45·I_z.
  double n_rdot_kgm2 = 1.25e7;
  /// Linear surge damping −X_u [N·s/m]. Source: calibrated — with M₁₁ gives surge time
  /// constants ≈ 60–100 s for small thrust steps at low speed (thesis table 3.24).
  double x_u_Ns_m = 5.0e3;
  /// Quadratic surge damping −X_|u|u [N·s²/m²]. Source: calibrated — full thrust 2×73 kN gives
  /// ≈ 12.5 kn (Gunnerus' top speed 12.6 kn), and the 0–80 % joystick step (64 % thrust with the
  /// lever curve) ≈ 10 kn as on the trial (thesis section 3.5.4).
  double x_uu_Ns2_m2 = 2.6e3;
  /// Linear sway damping at rest −Y_v0 [N·s/m]. Source: calibrated to sway total-speed time
  /// constants 9–19 s (tables 3.28, 3.30).
  double y_v_Ns_m = 25e3;
  /// Speed-proportional sway damping −Y_uv [N·s²/m²] (adds −Y_uv·|u| to −Y_v). Source: reasoned
  /// — lift on the hull as a low-aspect wing, ∝ U (Fossen 2011, ch. 6).
  double y_uv_Ns2_m2 = 90e3;
  /// Quadratic sway damping −Y_|v|v [N·s²/m²]. Source: reasoned — cross-flow drag
  /// ½ρ·C_D·L·T with C_D ≈ 0.6.
  double y_vv_Ns2_m2 = 24e3;
  /// Sway force from yaw rate per surge speed −Y_ur [N·s²/rad] (adds −Y_ur·u to −Y_r). Source:
  /// reasoned.
  double y_ur_Ns2 = 2.0e5;
  /// Yaw moment from sway per surge speed −N_uv [N·s²] (adds −N_uv·u to −N_v). Source: reasoned —
  /// skeg and rudders aft give a stabilising moment that partly offsets the Munk moment
  /// (Y_v̇ − X_u̇)·u·v of C_A; the value keeps the sway–yaw system stable at every speed.
  double n_uv_Ns2 = -3.0e5;
  /// Linear yaw damping at rest −N_r0 [N·m·s/rad]. Source: calibrated with n_ur to the
  /// yaw-rate time constants of table 3.31 (≈ 5 s at 3 kn, ≈ 3 s at 6 kn).
  double n_r_Nms = 2.0e6;
  /// Speed-proportional yaw damping −N_ur [N·m·s²/(rad·m)]. Source: calibrated, see n_r_Nms.
  double n_ur_Nms2 = 3.7e6;
  /// Quadratic yaw damping −N_|r|r [N·m·s²/rad²]. Source: reasoned — cross-flow drag moment
  /// ½ρ·C_D·T·∫|x|³dx = ½ρ·C_D·T·(L/2)⁴/2 with the C_D ≈ 0.6 of y_vv, T = 2.7 m and L between
  /// Lpp 28.9 m and Loa 31.25 m: 1.8–2.5e7. Checked against table 3.31: 0→20° yaw-rate fits
  /// from the log, seeds 1–3, give T 3.4–5.6 s at 3 kn (thesis 4.7–5.6 s); 4e8 gave 1.2–1.5 s.
  double n_rr_Nms2 = 2.0e7;
  /// Roll natural period [s]. Source: reasoned — GM ≈ 1.2 m and B = 9.6 m give ≈ 8 s.
  double roll_period_s = 8.0;
  /// Roll damping ratio ζ_φ [-]. Source: reasoned — bilge keels, ≈ 0.1.
  double roll_damping_ratio = 0.1;
  /// Static heel per centripetal acceleration, φ = k·u·r [rad per m/s²]. Source: reasoned —
  /// outward heel of ≈ 2° in a 3 kn, 1.5 °/s turn: k = −2°/(1.54·0.026) ≈ −0.87 rad·s²/m.
  double heel_per_centripetal = -0.87;
  /// Pitch natural period [s]. Source: reasoned — ≈ 5 s for a 31 m hull.
  double pitch_period_s = 5.0;
  /// Pitch damping ratio ζ_θ [-]. Source: reasoned, heavily damped, 0.3.
  double pitch_damping_ratio = 0.3;
  /// Static trim per surge acceleration, θ = k·u̇ [rad per m/s²]. Source: reasoned — bow up
  /// ≈ 0.3° at 0.05 m/s².
  double trim_per_surge_accel = 0.1;

  /// Throws core::InputError naming the first field outside its range (param_fields) or a
  /// mass matrix that is not positive definite.
  void validate() const;
};

/// The parameters as the keys of the vessel file's [hull] section, each with its unit and
/// range (core/param_range.hpp): the one table validate(), the file reader and the docs use.
std::vector<core::ParamField> param_fields(HullParams& params);

/// The hull: a const model.
class Hull {
 public:
  using State = Eigen::Matrix<double, 10, 1>;
  static constexpr int kNorth = 0, kEast = 1, kYaw = 2, kSurge = 3, kSway = 4, kYawRate = 5,
                       kRoll = 6, kRollRate = 7, kPitch = 8, kPitchRate = 9;

  explicit Hull(const HullParams& params = {});
  const HullParams& params() const noexcept { return params_; }

  /// The 3×3 inertia matrix M = M_RB + M_A, (2.10) extended with surge.
  const Eigen::Matrix3d& mass_matrix() const noexcept { return M_; }

  /// ẋ for BODY forces τ_b = (X, Y, N) [N, N, N·m] and current velocity v_c in NED [m/s].
  State derivatives(const State& x, const Eigen::Vector3d& tau_b,
                    const Eigen::Vector2d& current_n) const noexcept;

  /// ν̇ = M⁻¹(τ_b − C_RB ν − C_A ν_r − D ν_r) (2.7) for velocity ν and the velocity through the
  /// water ν_r (both BODY): the surge, sway and yaw rows of derivatives().
  Eigen::Vector3d nu_dot(const Eigen::Vector3d& nu, const Eigen::Vector3d& nu_r,
                         const Eigen::Vector3d& tau_b) const noexcept {
    return M_inv_ * (tau_b + hydrodynamic_forces(nu, nu_r));
  }

  /// The hydrodynamic and Coriolis forces −(C_RB ν + C_A ν_r + D ν_r) for velocity ν and
  /// relative velocity ν_r (both BODY, (u, v, r)).
  Eigen::Vector3d hydrodynamic_forces(const Eigen::Vector3d& nu,
                                      const Eigen::Vector3d& nu_r) const noexcept;

  /// Steady surge speed [m/s] under surge force X [N] in calm water: the root of
  /// X_u·u + X_|u|u·u|u| = X, (2.8) at rest.
  double steady_surge_speed(double surge_force) const noexcept;

  /// Linearised surge time constant M₁₁ / (−X_u − 2X_|u|u·|u₀|) at surge speed u₀ [s].
  double surge_time_constant(double u0) const noexcept;

  /// Nomoto time constants of the linearised sway–yaw subsystem (2.9) at surge speed u₀ > 0:
  /// T₁, T₂ from the eigenvalues, T₃ from the zero of r/δ for a rudder force at x_rudder [m]
  /// (2.11), and T_r = T₁ + T₂ − T₃ (2.13).
  struct Nomoto {
    double t1_s, t2_s, t3_s, tr_s;
  };
  Nomoto nomoto(double u0, double x_rudder_m) const;

 private:
  Eigen::Matrix2d sway_yaw_damping(double u) const noexcept;
  Eigen::Matrix2d sway_yaw_linear(double u0) const noexcept;  // N(u0) of (2.9)

  HullParams params_;
  Eigen::Matrix3d M_;
  Eigen::Matrix3d M_inv_;
};

}  // namespace dynpos::model
