#pragma once
/// \file
/// A fixed-pitch main propeller with shaft-speed control (thesis section 2.2, after Sørensen
/// 2012 and Smogeli 2006), and the first-order thrust alternative (2.29).
///
/// Signal chain from the commanded shaft speed n_c [rps] to the thrust T_a [N]:
///
///     n_c ─▶ dead time δ ─▶ reference generator ─▶ PI + feedforward ─▶ torque saturation
///         (DelayLine, caller)   ṅ_ref rate-limited     Q_c                 |Q_c| ≤ min(Q_max,
///         P_max/|ω|)
///     ─▶ motor Q̇_m = (Q_c − Q_m)/T_m ─▶ shaft I_s·ω̇ = Q_m − Q_a − K_ω·ω ─▶ n = ω/2π ─▶ T_a, Q_a, P
///
/// Continuous state x ∈ ℝ⁴ (indices below): n_ref [rps], z = ∫(ω_ref − ω)dt [rad],
/// Q_m [N·m], ω [rad/s]. The dead time is a DelayLine owned by the caller and advanced once per
/// tick (see delay_line.hpp); derivatives() takes the already delayed command, held over the
/// RK4 step. Nothing here allocates; every member function is const.
///
/// Sign conventions: n > 0 gives forward (ahead) thrust T_a > 0 along BODY x.

#include <Eigen/Core>
#include <vector>

#include "dynpos/core/param_range.hpp"
#include "dynpos/model/fopdt_truth.hpp"

namespace dynpos::model {

/// Parameters of one fixed-pitch, speed-controlled main propeller. Defaults: one R/V Gunnerus
/// main propeller (before the 2015 retrofit).
struct ThrusterParams {
  /// Water density ρ [kg/m³]. Source: standard sea water.
  double rho = 1025.0;
  /// Propeller diameter D [m]. Source: reasoned — a ≈ 500 kW open propeller on a
  /// 31 m vessel with 2.7 m draught; 2.0 m fits under the hull with tip clearance.
  double diameter = 2.0;
  /// Thrust coefficient K_T at J = 0 for n > 0 [-]. Source: Table 3.2,
  /// c = ρK_T D⁴ = 8.13 kN/rps² ⇒ K_T = 8130/(1025·2⁴) = 0.49573.
  double kt_forward = 8130.0 / (1025.0 * 16.0);
  /// Thrust coefficient K_T at J = 0 for n < 0 [-]. Source: Table 3.2,
  /// c = 5.8 kN/rps² ⇒ K_T = 5800/(1025·2⁴) = 0.35366.
  double kt_reverse = 5800.0 / (1025.0 * 16.0);
  /// Torque coefficient K_Q for n > 0 [-]. Source: reasoned — gives the rated
  /// 500 kW shaft power at n_max = 3 rps (P = 2πρK_Q D⁵n³, (2.28)); K_T/K_Q ≈ 5.5 is typical of
  /// open fixed-pitch propellers.
  double kq_forward = 0.09;
  /// Torque coefficient K_Q for n < 0 [-]. Source: reasoned — reverse running
  /// absorbs slightly less torque than ahead at equal |n| (≈ 0.94 of ahead).
  double kq_reverse = 0.085;
  /// Slope k_T of the optional linear K_T(J) = K_T0 − k_T·J, J = V_a/(|n|D) (2.27) [-]. Source:
  /// reasoned — 0 by default so the thrust map is exactly (3.17) with the Table 3.2 coefficients,
  /// as the thrust-map back-calculation expects.
  double kt_slope = 0.0;
  /// Slope k_Q of the optional linear K_Q(J) = K_Q0 − k_Q·J [-]. Source: as
  /// kt_slope.
  double kq_slope = 0.0;
  /// Maximum shaft speed magnitude |n| [rps]. Source: reasoned — 3 rps (180 rpm)
  /// gives 100 % thrust c·n² = 73 kN ahead, inside the 60–80 kN stated for Gunnerus.
  double max_shaft_speed = 3.0;
  /// Maximum motor power P_max [W]. Source: Gunnerus main propulsion motors
  /// ≈ 500 kW each; 10 % margin above the 500 kW needed at n_max so the limit is not active in
  /// calm water.
  double max_power = 550.0e3;
  /// Maximum motor torque |Q_c| [N·m]. Source: reasoned — 1.25 × the 26.6 kN·m
  /// absorbed at n_max; leaves margin for acceleration.
  double max_torque = 33.0e3;
  /// Shaft inertia I_s incl. motor, gear (referred to the shaft), propeller and entrained water
  /// [kg·m²]. Source: reasoned — order of a 500 kW electric drive with a 2 m
  /// propeller; only the closed-loop bandwidth matters, set by the PI gains below.
  double shaft_inertia = 2000.0;
  /// Linear shaft friction K_ω [N·m·s/rad]. Source: reasoned — ≈ 2 % of rated
  /// torque at rated speed.
  double friction = 30.0;
  /// Motor torque time constant T_m in Q̇_m = (Q_c − Q_m)/T_m [s]. Source:
  /// reasoned — electric drive torque loop, 0.1–0.3 s; must be > 0.004 s for RK4 at h = 0.01 s.
  double motor_time_constant = 0.15;
  /// Rate limit of the reference generator |ṅ_ref| [rps/s]. Source: calibrated
  /// so Smith fits of 0→80 % and 0→100 % thrust steps give T_n ≈ 4.7 and 5.2 s (tables 3.23,
  /// 3.27, 3.29: 5.5, 4.7, 4.5 s; larger steps are slower because the reference ramps).
  double ref_rate_limit = 0.3;
  /// Time constant of the reference filter inside the rate limit, ṅ_ref = sat((n_c − n_ref)/T_r)
  /// [s]. Source: calibrated — sets the Smith T_n of small steps (5–10 %,
  /// 15–25 %) to ≈ 0.6 s, inside the thesis 0.5–1.4 s (tables 3.23, 3.25).
  double ref_time_constant = 0.8;
  /// Proportional speed gain K_p [N·m·s/rad]. Source: reasoned — I_s/0.35 s, a
  /// closed-loop speed bandwidth of ≈ 3 rad/s, well below the motor bandwidth 1/T_m.
  double kp = 6000.0;
  /// Integral speed gain K_i [N·m/rad]. Source: reasoned — K_p/T_i, T_i = 1 s.
  double ki = 6000.0;
  /// Command dead time δ [s]. Source: calibrated to tables 3.23–3.29 (δ_n
  /// 1.2–3.3 s): the Smith dead time is δ plus ≈ 0.2 s for small steps and ≈ 0.1× the ramp
  /// duration for large ones, giving δ_n 1.5–2.4 s.
  double dead_time = 1.3;

  /// Throws core::InputError naming the first field outside its range (param_fields).
  void validate() const;
};

/// The parameters as the keys of the vessel file's [propeller] section, each with its unit and
/// range (core/param_range.hpp): the one table validate(), the file reader and the docs use.
std::vector<core::ParamField> param_fields(ThrusterParams& params);

/// The held input of the thruster over one integration step.
struct ThrusterInput {
  /// Delayed commanded shaft speed n_c [rps] (output of the caller's DelayLine); clamped to
  /// ±max_shaft_speed inside.
  double n_command = 0.0;
  /// Advance (inflow) speed V_a [m/s] at the propeller, used by K_T(J), K_Q(J) only.
  double advance_speed = 0.0;
};

/// Instantaneous outputs of the thruster.
struct ThrusterOutput {
  double shaft_speed = 0.0;   ///< n [rps]
  double thrust = 0.0;        ///< T_a [N], (2.25)
  double load_torque = 0.0;   ///< Q_a [N·m], (2.26)
  double power = 0.0;         ///< P = 2πnQ_a [W], (2.28)
  double motor_torque = 0.0;  ///< Q_m [N·m]
};

/// Smith-fit truth of one simulated shaft-speed step (see fopdt_truth.hpp).
struct ThrusterStepTruth {
  FopdtTruth shaft_speed;  ///< T_n, δ_n of n(t)
  FopdtTruth thrust;       ///< T_thrust, δ_thrust of T_a(t)
};

/// One speed-controlled fixed-pitch propeller: a const model of (2.23)–(2.28).
class Thruster {
 public:
  using State = Eigen::Vector4d;
  static constexpr int kNRef = 0;         ///< n_ref [rps]
  static constexpr int kIntegral = 1;     ///< z = ∫(ω_ref − ω)dt [rad]
  static constexpr int kMotorTorque = 2;  ///< Q_m [N·m]
  static constexpr int kOmega = 3;        ///< ω = 2πn [rad/s]

  /// A thruster with the given parameters (validated; throws core::InputError).
  explicit Thruster(const ThrusterParams& params = {});

  const ThrusterParams& params() const noexcept { return params_; }

  /// Time derivative ẋ of the state: reference generator, PI + feedforward with saturation and
  /// conditional anti-windup, motor (2.23) in its stable form Q̇_m = (Q_c − Q_m)/T_m (the thesis
  /// prints (Q_m − Q_c)/T_m, which is unstable for T_m > 0), shaft (2.24).
  State derivatives(const State& x, const ThrusterInput& u) const noexcept;

  /// Outputs n, T_a, Q_a, P at state x and advance speed V_a [m/s].
  ThrusterOutput outputs(const State& x, double advance_speed = 0.0) const noexcept;

  /// Thrust (2.25) with the optional K_T(J): T_a = sign(n)ρD⁴n²·(K_T0 − k_T·J), J = V_a/(|n|D).
  double thrust(double n, double advance_speed = 0.0) const noexcept;
  /// Load torque (2.26): Q_a = sign(n)ρD⁵n²·(K_Q0 − k_Q·J).
  double torque(double n, double advance_speed = 0.0) const noexcept;
  /// Shaft power (2.28): P = 2πn·Q_a.
  double power(double n, double advance_speed = 0.0) const noexcept;
  /// The thrust-map coefficient c = ρK_T D⁴ [N/rps²] for the sign of n (3.17), > 0.
  double thrust_coefficient(double n) const noexcept;
  /// Inverse bollard map n = sign(T)·√(|T|/c) [rps], clamped to ±max_shaft_speed.
  double shaft_speed_for_thrust(double thrust) const noexcept;
  /// Largest ahead thrust c₊·n_max² [N] (> 0).
  double max_thrust_forward() const noexcept;
  /// Largest astern thrust magnitude c₋·n_max² [N] (> 0).
  double max_thrust_reverse() const noexcept;
  /// The equilibrium state that holds shaft speed n [rps] at advance speed V_a [m/s].
  State steady_state(double n, double advance_speed = 0.0) const noexcept;

 private:
  ThrusterParams params_;
  double diameter_pow4_;  // D⁴ [m⁴], as std::pow gives it, taken once
};

/// The shaft speed n(t) [rps] and thrust T_a(t) [N] of a step of the commanded shaft speed
/// n_from → n_to [rps] at advance speed 0 from steady state (dead time included, RK4 at step dt
/// [s]), long enough to settle.
struct ThrusterStepResponse {
  StepResponse shaft_speed;
  StepResponse thrust;
};
ThrusterStepResponse thruster_step_response(const Thruster& thruster, double n_from, double n_to,
                                            double dt = 0.01);

/// The Smith two-point truth for n and T_a of thruster_step_response().
ThrusterStepTruth thruster_step_truth(const Thruster& thruster, double n_from, double n_to,
                                      double dt = 0.01);

/// Parameters of the first-order thrust model (2.29) for one thruster.
struct FirstOrderThrusterParams {
  /// Time constant T_thr [s]. Source: reasoned — between the small- and
  /// large-step T_thrust of tables 3.23–3.29 (0.3–4.7 s); 2 s.
  double time_constant = 2.0;
  /// Command dead time [s]. Source: Table 3.27 δ_thrust 2.7–4.9 s; 3 s.
  double dead_time = 3.0;
  /// Largest ahead thrust [N]. Source: as ThrusterParams, 8.13 kN/rps²·(3 rps)².
  double max_thrust_forward = 8130.0 * 9.0;
  /// Largest astern thrust magnitude [N]. Source: 5.8 kN/rps²·(3 rps)².
  double max_thrust_reverse = 5800.0 * 9.0;

  /// Throws core::InputError naming the first field outside its range.
  void validate() const;
};

/// The first-order thruster (2.29): Ṫ = (T_c − T)/T_thr with T_c saturated; state T [N].
class FirstOrderThruster {
 public:
  explicit FirstOrderThruster(const FirstOrderThrusterParams& params = {});
  const FirstOrderThrusterParams& params() const noexcept { return params_; }
  /// Ṫ = (sat(T_c) − T)/T_thr, (2.29); T_c is the delayed thrust command [N].
  double derivative(double thrust, double thrust_command) const noexcept;

 private:
  FirstOrderThrusterParams params_;
};

}  // namespace dynpos::model
