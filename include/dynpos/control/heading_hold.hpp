#pragma once
/// \file
/// Auto heading for a joystick: a PID law on the low-frequency heading that holds a fixed
/// heading ψ_h by adding a yaw moment to the operator's yaw demand, as a DP joystick does in
/// the sway tests of thesis section 3.4:
///
///     N = −k_p·ψ̃ − k_d·r − k_i·∫ψ̃ dt,   ψ̃ = ψ − ψ_h wrapped to (−π, π]
///
/// with the gains placed from a natural frequency ω and damping ratio ζ of the yaw mode
/// (I_z − N_ṙ)ψ̈ − N_r·ψ̇ = N (2.9 at rest, N_r < 0 there; here N_r > 0 is the damping):
///
///     k_p = (I_z − N_ṙ)·ω²,   k_d = max(0, 2ζω(I_z − N_ṙ) − N_r),   k_i = k_p·ω/10
///
/// (integral time 10/ω). The yaw demand it returns is a fraction of the joystick's largest
/// moment, clamped to [−1, 1]; while the clamp is active the integral stops (anti-windup).
/// The controller is discrete: one update per control period.

namespace dynpos::control {

/// Parameters of HeadingHold.
struct HeadingHoldParams {
  double inertia_kgm2 = 3.0e6;     ///< yaw inertia with added mass I_z − N_ṙ [kg·m²], > 0
  double yaw_damping_Nms = 2.0e6;  ///< linear yaw damping N_r [N·m·s], ≥ 0 (subtracted from k_d)
  double omega_rad_s = 0.15;       ///< natural frequency ω [rad/s], > 0
  double zeta = 0.9;               ///< damping ratio ζ [-], > 0
  double max_yaw_Nm = 6.0e5;       ///< the yaw moment of a full yaw demand [N·m], > 0
  double rate_hz = 10.0;           ///< update rate [Hz], > 0
  double heading_rad = 0.0;        ///< the held heading ψ_h [rad]

  /// Throws std::invalid_argument naming the first bad field.
  void validate() const;
};

/// The auto-heading PID with anti-windup (see the file comment).
class HeadingHold {
 public:
  /// Throws std::invalid_argument if params.validate() does.
  explicit HeadingHold(const HeadingHoldParams& params);

  /// One update at heading ψ [rad] and yaw rate r [rad/s], on top of the operator's yaw demand
  /// `operator_fraction` (of the largest moment): returns the total yaw demand
  /// clamp(operator_fraction + N/N_max, −1, 1), and integrates ψ̃ over one period unless the
  /// clamp is active.
  double update(double operator_fraction, double heading_rad, double yaw_rate_rad_s);

  double kp() const noexcept { return kp_; }  ///< k_p [N·m/rad]
  double kd() const noexcept { return kd_; }  ///< k_d [N·m·s/rad]
  double ki() const noexcept { return ki_; }  ///< k_i [N·m/(rad·s)]
  /// k_i·∫ψ̃ dt, the integral part of the moment [N·m].
  double integral_Nm() const noexcept { return integral_Nm_; }

 private:
  HeadingHoldParams params_;
  double kp_;
  double kd_;
  double ki_;
  double integral_Nm_ = 0.0;
};

}  // namespace dynpos::control
