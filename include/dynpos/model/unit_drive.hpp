#pragma once
/// \file
/// The drive of one unit of a [[thruster]] layout in the simulator: its propeller, the servo
/// that steers it (an azimuth's direction, a rudder's angle) and the force they make.
///
/// Propeller: a speed-controlled fixed-pitch propeller as the tunnel thruster's model
/// (tunnel_thruster.hpp): shaft speed n [rps] of first order towards the delayed command with a
/// rate limit, thrust T = ρK_T D⁴ n|n| (2.25) with K_T ahead or astern, power P = 2πρK_Q D⁵|n|³
/// (2.28), an azimuth's times its loss factor at its direction (azimuth_region.hpp). Steering:
/// an azimuth turns its thrust direction α at its slew rate, the way round
/// that does not cross a forbidden sector; a rudder turns at its servo rate and makes the side
/// force Y = (κ·max(T, 0) + c)·δ/δ_max, capped at its largest force: the allocation's cone
/// (layout_allocator.hpp) spanned by δ ∈ [−δ_max, δ_max].
///
/// Everything but the keys of the unit (thruster_unit.hpp) takes a default scaled from the
/// rated thrust, each with its source in drive_params(), so that a layout sketched in a few
/// lines can be simulated; the vessel file may give time_constant_s and dead_time_s.

#include <optional>

#include <Eigen/Core>

#include "dynpos/model/thruster_unit.hpp"

namespace dynpos::model {

/// The drive's values; drive_params() derives them from a unit.
struct UnitDriveParams {
  double rho = 1025.0;               ///< water density [kg/m³]
  double diameter_m = 0.0;           ///< propeller diameter D [m]
  double max_shaft_speed_rps = 0.0;  ///< |n| at the rated thrust [rps]
  double kt_ahead = 0.0;             ///< K_T for n > 0 (tunnel: to starboard) [-]
  double kt_astern = 0.0;            ///< K_T for n < 0 (tunnel: to port) [-]
  double kq = 0.0;                   ///< K_Q either way [-]
  double time_constant_s = 0.0;      ///< shaft speed time constant T_n [s]
  double rate_limit_rps2 = 0.0;      ///< |ṅ| limit [rps/s]
  double dead_time_s = 0.0;          ///< command dead time of shaft speed and steering [s]
  double max_rudder_rad = 0.0;       ///< propeller with rudder: δ_max [rad]
  double rudder_rate_rad_s = 0.0;    ///< propeller with rudder: servo rate [rad/s]
  /// Azimuth or rudder: the steering servo's gain inside its rate limit [1/s] (the rate is
  /// saturated while the turn left exceeds rate/gain).
  double steering_gain_per_s = 0.0;
};

/// The drive of `unit` (see the file comment and the sources in unit_drive.cpp).
UnitDriveParams drive_params(const ThrusterUnit& unit);

/// The outputs of a unit at shaft speed n and steering angle.
struct UnitOutput {
  double shaft_speed_rps = 0.0;
  double thrust_N = 0.0;  ///< signed: ahead (tunnel: to starboard) positive
  double power_W = 0.0;
  double angle_rad = 0.0;       ///< azimuth direction α or rudder angle δ; 0 for the others
  double rudder_force_N = 0.0;  ///< propeller with rudder: Y (+ to starboard)
  Eigen::Vector3d tau_b = Eigen::Vector3d::Zero();  ///< (X, Y, N) at the control origin (2.2)
};

/// One unit's drive: const, allocation-free.
class UnitDrive {
 public:
  /// Throws core::InputError for a unit that does not validate.
  explicit UnitDrive(const ThrusterUnit& unit);

  const ThrusterUnit& unit() const noexcept { return unit_; }
  const UnitDriveParams& params() const noexcept { return p_; }

  /// Thrust [N] at shaft speed n [rps] (2.25).
  double thrust_N(double n_rps) const noexcept;
  /// The shaft speed [rps] that gives `thrust_N` at rest, within ±max_shaft_speed_rps.
  double shaft_speed_for(double thrust_N) const noexcept;
  /// ṅ [rps/s] towards the delayed command n_c, clamped to ±max_shaft_speed_rps.
  double shaft_acceleration(double n_rps, double n_command_rps) const noexcept;
  /// The steering rate [rad/s] towards the delayed command: an azimuth the way round clear of
  /// its forbidden sectors at most rate_deg_per_s, a rudder at most its servo rate; 0 for the
  /// others.
  double angle_rate(double angle_rad, double angle_command_rad) const noexcept;
  /// An azimuth's signed turn [rad] from `angle_rad` to `command_rad`: the short way, or the
  /// long way round (|turn| > π) when the short way crosses a forbidden sector and the long way
  /// does not; the short way when both cross one (an order in another gap between sectors: the
  /// unit passes the sector with its thrust cut). 0 for the others.
  double turn_rad(double angle_rad, double command_rad) const noexcept;
  /// Whether the short way from `angle_rad` to `command_rad` crosses a forbidden sector (an
  /// azimuth only).
  bool short_way_blocked(double angle_rad, double command_rad) const noexcept;
  /// An azimuth's directions within `reach_rad` (at most π/2) either way of `angle_rad` [rad],
  /// never across a forbidden sector: one arc of at most 180°, a convex wedge. Empty for
  /// another unit, or an azimuth inside a forbidden sector.
  std::optional<AllowedArc> reachable(double angle_rad, double reach_rad) const noexcept;
  /// The rudder angle [rad] that makes side force `force_N` behind thrust `thrust_N`, within
  /// ±δ_max (0 for a unit without a rudder).
  double rudder_angle_for(double force_N, double thrust_N) const noexcept;
  /// The outputs at shaft speed n [rps] and steering angle [rad]; a unit at capacity 0 (lost)
  /// makes no force.
  UnitOutput outputs(double n_rps, double angle_rad, double capacity = 1.0) const noexcept;

 private:
  double rudder_force(double thrust_N, double rudder_rad) const noexcept;
  // Whether the turn [rad] from `angle` crosses a forbidden sector's interior.
  bool turn_crosses(double angle, double turn) const noexcept;

  ThrusterUnit unit_;
  UnitDriveParams p_;
};

}  // namespace dynpos::model
