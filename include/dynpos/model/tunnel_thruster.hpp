#pragma once
/// \file
/// The bow tunnel thruster: first-order shaft-speed dynamics with rate limit, sign-dependent
/// thrust map and a loss of effectiveness with forward speed.
///
/// ṅ = sat_r((sat(n_c) − n)/T_n); T = c(sign n)·n|n|·η(u), (2.25) with the speed factor
/// η(u) = η_min + (1 − η_min)·exp(−(u/u₀)²). Continuous state: n [rps]. The command dead time is
/// a DelayLine owned by the caller (delay_line.hpp). Positive thrust pushes the bow to
/// starboard (BODY +y).
///
/// The speed factor models the thesis remark (section 2.2) that "the tunnel thruster is only
/// effective for low-speed, and will become inefficient at higher speed due to cross-coupling
/// drag". The curve is reasoned from published tunnel-thruster model tests (e.g. Chislett and
/// Bjørheden 1966, summarised by Sørensen 2012), which show the side force falling to ≈ 0.3–0.5
/// of bollard at 3–4 kn; the partial recovery above ≈ 6 kn is ignored, so η is monotone.

#include <vector>

#include "dynpos/core/param_range.hpp"
#include "dynpos/model/fopdt_truth.hpp"

namespace dynpos::model {

/// Parameters of the bow tunnel thruster. Defaults: the R/V Gunnerus tunnel thruster.
struct TunnelThrusterParams {
  /// Water density ρ [kg/m³]. Source: standard sea water.
  double rho = 1025.0;
  /// Propeller diameter D [m]. Source: reasoned — ≈ 200 kW tunnel thruster.
  double diameter = 1.2;
  /// K_T for n > 0 (thrust to starboard) [-]. Source: reasoned — typical
  /// tunnel-thruster value; with D = 1.2 m and n_max it gives ≈ 25 kN.
  double kt_starboard = 0.40;
  /// K_T for n < 0 (thrust to port) [-]. Source: reasoned — asymmetric blades,
  /// ≈ 90 % of the starboard value.
  double kt_port = 0.36;
  /// K_Q for either direction [-]. Source: reasoned — 200 kW at n_max.
  double kq = 0.0785;
  /// Maximum shaft speed |n| [rps]. Source: reasoned — 5.42 rps (325 rpm) gives
  /// ρK_T D⁴n² ≈ 25 kN starboard, inside the 20–30 kN stated for Gunnerus.
  double max_shaft_speed = 5.42;
  /// Shaft speed time constant T_n [s]. Source: reasoned — no tunnel step
  /// test in the thesis; a 200 kW electric drive, similar to the small-step main propeller T_n.
  double time_constant = 1.0;
  /// Shaft speed rate limit |ṅ| [rps/s]. Source: reasoned — full reversal
  /// −n_max → +n_max in ≈ 8 s.
  double rate_limit = 1.4;
  /// Command dead time [s]. Source: reasoned — like the main propellers' command
  /// path (tables 3.23–3.29, δ ≈ 1–3 s); the tunnel thruster is logged at 1 Hz only.
  double dead_time = 1.0;
  /// Speed factor floor η_min [-]. Source: reasoned (see file comment).
  double speed_factor_min = 0.3;
  /// Speed factor scale u₀ [m/s]. Source: reasoned — η = 0.5 at 3 kn and ≈ 0.37
  /// at 4 kn.
  double speed_factor_scale = 1.38;
  /// Position of the thruster in BODY, x [m]. Source: reasoned — near the bow
  /// of a 31 m vessel, 12.5 m forward of the control origin amidships.
  double x = 12.5;

  /// Throws core::InputError naming the first field outside its range (param_fields).
  void validate() const;
};

/// The parameters as the keys of the vessel file's [tunnel] section, each with its unit and range
/// (core/param_range.hpp): the one table validate(), the file reader and the docs use.
std::vector<core::ParamField> param_fields(TunnelThrusterParams& params);

/// Instantaneous outputs of the tunnel thruster.
struct TunnelThrusterOutput {
  double shaft_speed = 0.0;   ///< n [rps]
  double thrust = 0.0;        ///< side force, BODY +y [N], after the speed factor
  double power = 0.0;         ///< P = 2πnQ [W], (2.28)
  double speed_factor = 1.0;  ///< η(u) [-]
};

/// The bow tunnel thruster: const model.
class TunnelThruster {
 public:
  /// A tunnel thruster with the given parameters (validated; throws core::InputError).
  explicit TunnelThruster(const TunnelThrusterParams& params = {});

  const TunnelThrusterParams& params() const noexcept { return params_; }

  /// ṅ = sat_r((sat(n_c) − n)/T_n); n_c is the delayed shaft speed command [rps].
  double shaft_acceleration(double n, double n_command) const noexcept;

  /// Outputs at shaft speed n [rps] and vessel surge speed through water u [m/s].
  TunnelThrusterOutput outputs(double n, double surge_speed) const noexcept;

  /// Speed factor η(u) = η_min + (1 − η_min)·exp(−(u/u₀)²), even in u, decreasing in |u|.
  double speed_factor(double surge_speed) const noexcept;

  /// Bollard thrust-map coefficient c = ρK_T D⁴ [N/rps²] for the sign of n, > 0.
  double thrust_coefficient(double n) const noexcept;

  /// Side force at shaft speed n and surge speed u: T = c·n|n|·η(u) [N].
  double thrust(double n, double surge_speed = 0.0) const noexcept;

  /// Shaft speed [rps] that gives side force T at surge speed u (inverse of thrust()), clamped
  /// to ±max_shaft_speed.
  double shaft_speed_for_thrust(double thrust, double surge_speed = 0.0) const noexcept;

  /// Largest side force to starboard at surge speed u [N] (> 0).
  double max_thrust_starboard(double surge_speed = 0.0) const noexcept;
  /// Largest side force magnitude to port at surge speed u [N] (> 0).
  double max_thrust_port(double surge_speed = 0.0) const noexcept;

 private:
  TunnelThrusterParams params_;
  double diameter_pow4_;  // D⁴ [m⁴], as std::pow gives it, taken once
};

/// The shaft speed n(t) [rps] of a shaft-speed command step n_from → n_to [rps] from rest at
/// n_from (dead time included, RK4 at dt [s]), long enough to settle.
StepResponse tunnel_step_response(const TunnelThruster& thruster, double n_from, double n_to,
                                  double dt = 0.01);

/// The Smith two-point truth of tunnel_step_response().
FopdtTruth tunnel_step_truth(const TunnelThruster& thruster, double n_from, double n_to,
                             double dt = 0.01);

}  // namespace dynpos::model
