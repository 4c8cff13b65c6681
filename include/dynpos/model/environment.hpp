#pragma once
/// \file
/// Slowly varying environment of the virtual vessel: current, wind, the Gauss–Markov bias
/// (2.22) and scheduled step loads. Each is stepped once per simulator tick (sample and hold);
/// the forces are then held over the RK4 step. Waves are in sea_state.hpp.
///
/// Directions: current flows TO current_to_rad, wind comes FROM wind_from_rad, both clockwise
/// from north, as sea-trial reports give them.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "dynpos/core/param_range.hpp"
#include "dynpos/sim/noise.hpp"

namespace dynpos::model {

/// Range of the mean current speed a scenario sets (scenario file [environment]).
inline const core::ParamRange kCurrentSpeedRange{"current_speed_mps", "m/s", 0, 3};
/// Range of the mean wind speed at 10 m a scenario sets (scenario file [environment]).
inline const core::ParamRange kWindSpeedRange{"wind_speed_mps", "m/s", 0, 40};

/// Current parameters.
struct CurrentParams {
  double speed_mps = 0.0;          ///< mean speed [m/s], range kCurrentSpeedRange
  double to_rad = 0.0;             ///< direction it flows to [rad]
  double speed_std_mps = 0.02;     ///< std of the slow speed variation [m/s]. Source: reasoned.
  double dir_std_rad = 0.05;       ///< std of the slow direction variation [rad]. Source: reasoned.
  double time_constant_s = 600.0;  ///< correlation time of the variations [s]. Source:
                                   ///< reasoned (tidal/wind-driven changes over tens of minutes).
  /// Throws core::InputError naming the first value outside its range (param_fields).
  void validate() const;
};

/// The current's parameters as the keys of the vessel file's [current] section, each with its
/// unit and range (core/param_range.hpp): the one table validate(), the file reader and the
/// docs use.
std::vector<core::ParamField> param_fields(CurrentParams& params);

/// Current with slow Gauss–Markov variation of speed and direction.
class Current {
 public:
  Current(const CurrentParams& params, std::uint64_t seed, double dt_s);
  /// Advances the variations by one tick.
  void step() noexcept;
  /// Current velocity in NED (north, east) [m/s].
  Eigen::Vector2d velocity_n() const noexcept;

 private:
  CurrentParams params_;
  sim::GaussMarkov speed_;
  sim::GaussMarkov direction_;
};

/// Wind parameters: mean, gusts and the vessel's wind-force coefficients.
struct WindParams {
  double speed_mps = 0.0;             ///< mean wind speed at 10 m [m/s], range kWindSpeedRange
  double from_rad = 0.0;              ///< direction it comes from [rad]
  double gust_std_fraction = 0.12;    ///< gust std / mean speed [-]. Source: reasoned, turbulence
                                      ///< intensity over open sea ≈ 0.1–0.15 (thesis table 3.3:
                                      ///< 0.5 m/s std at 3.3–4.3 m/s mean).
  double gust_time_constant_s = 8.0;  ///< gust correlation time [s]. Source: reasoned.
  double dir_std_rad = 0.12;          ///< std of direction fluctuations [rad]. Source: thesis table
                                      ///< 3.3–3.4 (7–9° std).
  double frontal_area_m2 =
      90.0;  ///< A_F [m²]. Source: reasoned, 9.6 m beam × ≈ 9.5 m superstructure.
  double lateral_area_m2 = 230.0;  ///< A_L [m²]. Source: reasoned, ≈ 31 m × 7.5 m mean height.
  double length_m = 31.25;         ///< L_oa [m]. Source: Gunnerus main dimensions.
  double cx = 0.6;   ///< head-wind drag coefficient [-]. Source: reasoned (Isherwood-type values).
  double cy = 0.8;   ///< beam-wind coefficient [-]. Source: reasoned.
  double cn = 0.08;  ///< yaw-moment coefficient [-]. Source: reasoned.
  double rho_air = 1.226;  ///< air density [kg/m³].
  /// Throws core::InputError naming the first value outside its range (param_fields).
  void validate() const;
};

/// The wind's parameters as the keys of the vessel file's [wind] section, with units and ranges.
std::vector<core::ParamField> param_fields(WindParams& params);

/// The wind force and moment in BODY (X, Y, N) [N, N, N·m] of a relative wind of speed
/// speed_mps [m/s] coming from gamma_rad [rad] off the bow (0 ahead, π/2 from starboard):
/// ½ρ_a V² (−c_x cos γ·A_F, −c_y sin γ·A_L, −c_n sin 2γ·A_L·L).
Eigen::Vector3d wind_force_b(const WindParams& params, double speed_mps, double gamma_rad) noexcept;

/// The wind force and moment in BODY (X, Y, N) [N, N, N·m] on a vessel with heading ψ [rad]
/// moving at velocity_n over ground (NED) [m/s] in a wind of speed_mps [m/s] coming from
/// from_rad [rad]: wind_force_b of the relative wind. The one home of the relative wind, for
/// Wind::force_b and for a fit driven by a logged wind.
Eigen::Vector3d relative_wind_force_b(const WindParams& params, double speed_mps, double from_rad,
                                      double heading_rad,
                                      const Eigen::Vector2d& velocity_n) noexcept;

/// Wind with Gauss–Markov gusts; forces by smooth coefficient curves of the relative angle.
class Wind {
 public:
  Wind(const WindParams& params, std::uint64_t seed, double dt_s);
  void step() noexcept;
  /// The true wind now: speed [m/s] and direction it comes from [rad].
  double speed_mps() const noexcept;
  double from_rad() const noexcept;
  /// Wind force and moment in BODY (X, Y, N) for heading ψ [rad] and velocity over ground in
  /// NED (north, east) [m/s]: ½ρ_a V_rw² (−c_x cos γ·A_F, c_y sin γ·A_L, c_n sin 2γ·A_L·L),
  /// γ = the angle the relative wind comes from, relative to the bow.
  Eigen::Vector3d force_b(double heading_rad, const Eigen::Vector2d& velocity_n) const noexcept;

 private:
  WindParams params_;
  sim::GaussMarkov gust_;
  sim::GaussMarkov direction_;
};

/// The bias b in NED (2.22): ḃ = −T⁻¹ b + w_b per axis (N, E, yaw moment), exactly discretised.
///
/// The bias stands for the slowly varying forces the simulator does not model one by one. Most
/// of them in a seaway is the slowly varying (second-order) wave drift, which grows with H_s²
/// like the mean drift; the rest (current shear, hull–current interaction, model error) stays in
/// calm water. The stationary std is therefore given at a reference sea state and scaled by
///   k(H_s) = √(c² + (1 − c²)·(H_s/H_ref)⁴),
/// with c the calm-water fraction: k(H_ref) = 1, k(0) = c (see sea_state_factor).
struct BiasParams {
  Eigen::Vector3d std{2.0e3, 2.0e3, 2.0e4};  ///< stationary std at H_ref [N, N, N·m]. Source:
                                             ///< reasoned, checked against pure DP in Hs 2 m
                                             ///< (thesis tables 3.14–3.22).
  Eigen::Vector3d time_constant_s{300.0, 300.0, 300.0};  ///< T per axis [s]. Source: reasoned.
  /// Reference significant wave height H_ref [m] at which `std` holds. Source: the
  /// pure-DP trial's sea state, Hs ≈ 2 m (thesis tables 3.14–3.22).
  double reference_hs_m = 2.0;
  /// Calm-water fraction c of the std [-]; 1 disables the sea-state scaling.
  /// Source: calibrated — the smallest surge step (0.37 kN, thesis table 3.24) is only seen
  /// with no bias in calm water (c = 0: 5 N at Hs 0.1 m); 0.05 (100 N) already doubles the
  /// scatter of its fits. Calm water keeps the current's and the wind's own variation.
  double calm_fraction = 0.0;
  /// Throws core::InputError naming the first value outside its range (param_fields).
  void validate() const;
  /// k(H_s) above, for significant wave height H_s [m] ≥ 0.
  double sea_state_factor(double hs_m) const noexcept;
};

/// The bias' parameters as the keys of the vessel file's [bias] section, with units and ranges.
std::vector<core::ParamField> param_fields(BiasParams& params);

/// `params` with the stds scaled by params.sea_state_factor(H_s) for H_s [m].
BiasParams bias_for_sea_state(const BiasParams& params, double hs_m);

class Bias {
 public:
  Bias(const BiasParams& params, std::uint64_t seed, double dt_s);
  void step() noexcept;
  /// b = (force north [N], force east [N], yaw moment [N·m]).
  Eigen::Vector3d value_n() const noexcept;

 private:
  std::vector<sim::GaussMarkov> axes_;
};

/// A scheduled load: a constant force in NED and a yaw moment switched on at t_on and off at
/// t_off (e.g. an ice load, or a mooring line that snaps: on from 0, off at the snap).
struct StepLoad {
  double t_on_s = 0.0;
  double t_off_s = 1e300;            ///< [s]; default: never switched off
  Eigen::Vector3d force_n{0, 0, 0};  ///< (north [N], east [N], yaw moment [N·m])
};

/// Sum of the step loads active at t [s] (active on t_on ≤ t < t_off).
Eigen::Vector3d step_loads_n(const std::vector<StepLoad>& loads, double t_s) noexcept;

}  // namespace dynpos::model
