#pragma once
/// \file
/// A rudder behind a main propeller: servo (angle) dynamics and the hydrodynamic rudder force.
///
/// Angle convention: a positive rudder angle α turns the trailing edge to starboard; the lift
/// then pushes the stern to port (F_y < 0 at the rudder, which sits aft of the control origin)
/// and the bow turns to starboard (N > 0, positive yaw rate). Hence "rudder to starboard" ⇔
/// α > 0 ⇔ starboard turn.
///
/// Servo: α̇ = sat_r((sat_αmax(α_c) − α)/T_s), a fast first-order servo inside a rate limit r;
/// the rate limit dominates, which makes the FOPDT time constant of a step grow with the step
/// size as in tables 3.33–3.36 (0→20°: 1.7–2.0 s, 47°→0: 4.1–4.4 s). The command dead time is a
/// DelayLine owned by the caller (delay_line.hpp). Continuous state: α [rad].
///
/// Force: the rudder sees the vessel's water-relative velocity at the rudder plus, with ahead
/// thrust, the propeller slipstream. By momentum (actuator-disk) theory the far slipstream
/// speed is V_s = √(V_a² + 8T/(ρπD²)); a fraction η of the rudder area is in the slipstream, so
/// the dynamic pressure is q = ½ρ(η·V_s² + (1 − η)·V_a²) = ½ρV_a² + η·4T⁺/(πD²), where V_a is
/// the axial inflow (ahead positive) and T⁺ = max(T, 0). Lift L = q·A·C_L(α_e) normal to the
/// inflow and drag D = q·A·C_D(α_e) along it, with the effective angle of attack α_e from the
/// rudder angle and the local flow direction. With no speed and no thrust, q = 0: no force.

#include <Eigen/Core>
#include <vector>

#include "dynpos/core/param_range.hpp"
#include "dynpos/model/fopdt_truth.hpp"

namespace dynpos::model {

/// Parameters of one rudder (servo and hydrodynamics). Defaults: one R/V Gunnerus rudder.
struct RudderParams {
  /// Maximum rudder angle |α| [rad]. Source: thesis section 3.5 yaw step tests,
  /// "maximum angle (about 47 degrees)".
  double max_angle = 47.0 * 3.14159265358979323846 / 180.0;
  /// Servo rate limit |α̇| [rad/s]. Source: calibrated to tables 3.33–3.36 — for
  /// a rate-limited ramp of Δα the Smith time constant is ≈ 0.525·Δα/r, so T = 4.2 s for 47°
  /// and 1.8 s for 20° both give r ≈ 6°/s; 5.9°/s gives Smith T = 1.77 s (0→20°), 2.39 s
  /// (20→47°), 4.17 s (47→0°). The SOLAS minimum of 2.3°/s would give T ≈ 4.6 s for the 0→20°
  /// step, outside the tables.
  double rate_limit = 5.9 * 3.14159265358979323846 / 180.0;
  /// Servo time constant T_s inside the rate limit [s]. Source: reasoned —
  /// hydraulic servo loop, rounds the ends of the ramp.
  double servo_time_constant = 0.3;
  /// Command dead time [s]. Source: calibrated to tables 3.33–3.36 (δ 0.7–1.5 s);
  /// the Smith dead time adds ≈ 0.1× the ramp duration to this: 1.02 s (0→20°), 1.15 s
  /// (20→47°), 1.52 s (47→0°).
  double dead_time = 0.65;
  /// Movable rudder area A [m²]. Source: reasoned — span 1.8 m × chord 1.1 m,
  /// about 1.2 % of L·T per rudder for a 31 m, 2.7 m draught twin-screw vessel.
  double area = 2.0;
  /// Geometric aspect ratio Λ [-]. Source: reasoned — 1.8/1.1.
  double aspect_ratio = 1.64;
  /// Lift slope C_Lα [1/rad]. Source: reasoned — low-aspect-ratio wing
  /// 2πΛ/(Λ + 2) ≈ 2.8 for Λ = 1.64.
  double lift_slope = 2.8;
  /// Stall angle of attack α_stall [rad]. Source: reasoned — 30°; rudders in a
  /// slipstream stall late.
  double stall_angle = 30.0 * 3.14159265358979323846 / 180.0;
  /// Lift retained after stall relative to the stall peak [-]. Source: reasoned —
  /// post-stall lift falls linearly from C_Lα·α_stall at α_stall to this fraction at
  /// α_stall + post_stall_width and stays there up to 90°.
  double post_stall_lift_fraction = 0.6;
  /// Angle over which the lift falls from its stall peak to the post-stall fraction [rad]. Source:
  /// calibrated to the thesis yaw tests (section 3.5, figures 3.15–3.18): the rudder step 20°→47°
  /// gives "an initial pulse in yaw rate, but does not significantly change the steady state". 10°,
  /// an abrupt stall as for a thick low-aspect-ratio section, raises the steady rate by 9–18 %
  /// there, 14 % on average (60° spread the fall up to 90° and raised it by 70–95 %); the pulse is
  /// the lift peak at α_stall passed on the way.
  double post_stall_width = 10.0 * 3.14159265358979323846 / 180.0;
  /// Zero-lift drag coefficient C_D0 [-]. Source: reasoned — NACA-type section.
  double drag_zero = 0.013;
  /// Angle-dependent drag C_D = C_D0 + k_D·sin²α_e, k_D [-]. Source: reasoned —
  /// flat-plate normal force ≈ 1.1 at 90°.
  double drag_angle = 1.1;
  /// Fraction η of the rudder area inside the propeller slipstream [-]. Source:
  /// reasoned — a 2 m propeller slipstream covers most of a 1.8 m span rudder.
  double slipstream_fraction = 0.7;
  /// Diameter D of the propeller ahead of the rudder [m]. Source: as
  /// ThrusterParams::diameter.
  double propeller_diameter = 2.0;
  /// Flow straightening γ of the local drift angle at the rudder [-]. Source:
  /// reasoned — hull and propeller straighten the transverse flow; 0.5 is a usual value.
  double flow_straightening = 0.5;
  /// Lift efficiency in astern flow relative to ahead [-]. Source: reasoned —
  /// the trailing edge leads, 0.5.
  double astern_lift_factor = 0.5;
  /// Water density ρ [kg/m³]. Source: standard sea water.
  double rho = 1025.0;

  /// Throws core::InputError naming the first field outside its range (param_fields).
  void validate() const;
};

/// The parameters as the keys of the vessel file's [rudder] section, each with its unit and
/// range (core/param_range.hpp): the one table validate(), the file reader and the docs use.
std::vector<core::ParamField> param_fields(RudderParams& params);

/// Local flow conditions at one rudder.
struct RudderInflow {
  /// Vessel velocity through the water at the rudder, BODY x [m/s] (u + current-relative, with
  /// wake already applied by the caller if wanted); ahead > 0.
  double u = 0.0;
  /// Vessel velocity through the water at the rudder, BODY y [m/s], v + x_R·r.
  double v = 0.0;
  /// Thrust T of the propeller ahead of the rudder [N]; only T > 0 feeds the slipstream.
  double propeller_thrust = 0.0;
};

/// The rudder force at the rudder, in BODY.
struct RudderForce {
  double lift = 0.0;                              ///< signed lift L [N] (positive for α_e > 0)
  double drag = 0.0;                              ///< drag D [N], ≥ 0
  Eigen::Vector2d f_b = Eigen::Vector2d::Zero();  ///< (F_x, F_y) in BODY [N]
  double angle_of_attack = 0.0;                   ///< α_e [rad]
  double dynamic_pressure = 0.0;                  ///< q [Pa]
};

/// One rudder: const servo and force model.
class Rudder {
 public:
  /// A rudder with the given parameters (validated; throws core::InputError).
  explicit Rudder(const RudderParams& params = {});

  const RudderParams& params() const noexcept { return params_; }

  /// Servo: α̇ = sat_r((sat_αmax(α_c) − α)/T_s); α_c is the delayed command [rad].
  double angle_rate(double angle, double angle_command) const noexcept;

  /// Force at the rudder for rudder angle α [rad] and local inflow.
  RudderForce force(double angle, const RudderInflow& inflow) const noexcept;

  /// Lift coefficient C_L(α_e): linear to stall, then falling linearly to the post-stall
  /// fraction over the post-stall width and flat beyond; odd in α_e; |α_e| ≤ π/2 expected.
  double lift_coefficient(double angle_of_attack) const noexcept;
  /// Drag coefficient C_D(α_e) = C_D0 + k_D·sin²α_e.
  double drag_coefficient(double angle_of_attack) const noexcept;

  /// Dynamic pressure q = ½ρV_a² + η·4T⁺/(πD²) [Pa] for axial inflow V_a [m/s] and thrust T.
  double dynamic_pressure(double axial_speed, double propeller_thrust) const noexcept;

  /// The rudder angle [rad] that gives transverse force F_y [N] at the rudder in straight ahead
  /// flow (v = 0), by inverting the linear lift L = q·A·C_Lα·α (F_y = −L); clamped to
  /// ±min(stall, max) angle. Returns 0 when q = 0.
  double angle_for_side_force(double side_force, double axial_speed,
                              double propeller_thrust) const noexcept;

  /// The largest |F_y| [N] available in straight ahead flow within the linear region
  /// (|α| ≤ min(stall, max)): q·A·C_Lα·α_lin. Linear in T⁺ (see file comment).
  double max_side_force(double axial_speed, double propeller_thrust) const noexcept;

 private:
  RudderParams params_;
};

/// Simulates a step of the rudder command α_from → α_to [rad] (dead time included, RK4 at dt
/// [s]) and returns the Smith two-point truth of α(t).
FopdtTruth rudder_step_truth(const Rudder& rudder, double angle_from, double angle_to,
                             double dt = 0.01);

}  // namespace dynpos::model
