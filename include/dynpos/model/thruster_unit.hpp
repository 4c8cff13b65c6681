#pragma once
/// \file
/// One thruster unit of a general layout: where it sits, which way it can push, how hard, and
/// the thrust directions it may not use. The allocator for any layout (layout_allocator.hpp)
/// works on a list of them.
///
/// Frames and angles: positions in BODY from the control origin (x forward, y starboard); a
/// thrust direction α is measured from ahead towards starboard (0° thrust ahead, 90° thrust to
/// starboard, clockwise seen from above), so the force is F_b = T·(cos α, sin α). A force F at
/// (x, y) gives τ = (F_x, F_y, x·F_y − y·F_x) (2.2).

#include <optional>
#include <string>
#include <vector>

namespace dynpos::model {

/// What a unit can do.
enum class UnitType {
  kAzimuth,          ///< any direction in the horizontal plane outside its forbidden sectors
  kTunnel,           ///< side force only: positive to starboard, negative to port
  kPropeller,        ///< surge force only: ahead and astern
  kPropellerRudder,  ///< a propeller with a rudder in its slipstream: surge thrust T and the
                     ///< rudder's side force Y, |Y| ≤ κ·max(T, 0) + c (thesis 2.2.2)
};

/// "azimuth", "tunnel", "propeller", "propeller_rudder".
std::string_view unit_type_name(UnitType type) noexcept;

/// A sector of thrust directions from `from_deg` clockwise to `to_deg` [deg], each in
/// [0, 360); from 300 to 60 is the 120° across ahead.
struct AngleSector {
  double from_deg = 0.0;
  double to_deg = 0.0;
};

/// A point of a unit's thrust factor by direction (interaction losses): the factor in [0, 1] of
/// the rating at direction angle_deg in [0, 360) (azimuth_region.hpp).
struct LossPoint {
  double angle_deg = 0.0;
  double factor = 1.0;
};

/// One unit. Thrusts are rated magnitudes [N] ≥ 0: for a tunnel, max_thrust_N to starboard and
/// max_reverse_thrust_N to port; for an azimuth the disc's radius is max_thrust_N.
struct ThrusterUnit {
  std::string name;
  UnitType type = UnitType::kAzimuth;
  double x_m = 0.0;  ///< position forward of the control origin [m]
  double y_m = 0.0;  ///< position to starboard of the control origin [m]
  double max_thrust_N = 0.0;
  double max_reverse_thrust_N = 0.0;
  /// Azimuth only: thrust directions it may not point in (e.g. into a neighbour's wake).
  std::vector<AngleSector> forbidden_deg;
  /// Propeller with rudder only: the rudder's side force per newton of ahead thrust κ [-] and
  /// at zero thrust c [N] (from the ship's speed; 0 at rest), both ≥ 0.
  double rudder_lift_per_thrust = 0.0;
  double rudder_lift_at_zero_N = 0.0;
  /// Propeller with rudder only: the largest side force of the rudder [N] (its stall), > 0, or
  /// 0 for the cone alone; and where the side force acts, forward of the control origin [m]
  /// (the rudder's centre of pressure; unset: x_m).
  double rudder_max_force_N = 0.0;
  std::optional<double> rudder_x_m;
  /// Azimuth only: the slew rate limit [deg/s], > 0, for a simulator's azimuth model. Source:
  /// reasoned — 10°/s, a half turn in 18 s, typical of DP azimuth thrusters.
  double rate_deg_per_s = 10.0;
  /// The simulator's drive (unit_drive.hpp): the shaft speed's time constant [s], > 0 (unset:
  /// scaled from the rated thrust), and the command dead time [s], ≥ 0. Source of 1 s: the
  /// Gunnerus tunnel thruster's (tunnel_thruster.hpp), inside the 1–3 s of tables 3.23–3.36.
  std::optional<double> time_constant_s;
  double dead_time_s = 1.0;
  /// The allocation's rate limit of each of the unit's forces [N/s], > 0 (unset: the rated
  /// thrust over 4 shaft time constants, the drive's ramp from rest to full speed,
  /// unit_drive.hpp), used when an allocation is given the previous one (AllocationRates).
  std::optional<double> thrust_rate_N_per_s;
  /// Cost of a fraction of the unit's capacity, relative to the others [-], > 0.
  double weight = 1.0;
  /// Azimuth only: the thrust factor by direction, points in increasing angle, linear between
  /// them round the circle; empty: 1 in every direction.
  std::vector<LossPoint> loss;
  /// Redundancy group (switchboard, engine room); empty: none.
  std::string group;

  /// Throws core::InputError naming the unit and the first bad field.
  void validate() const;
};

/// A unit of `type` at (x_m, y_m) with its ratings and forbidden sectors, every other field at its
/// default (a short way to write a layout in code).
ThrusterUnit thruster_unit(std::string name, UnitType type, double x_m, double y_m,
                           double max_thrust_N, double max_reverse_thrust_N = 0.0,
                           std::vector<AngleSector> forbidden_deg = {});

/// An arc of allowed thrust directions, from `from_rad` increasing by `span_rad` ≤ π (a convex
/// wedge), angles in radians as α above.
struct AllowedArc {
  double from_rad = 0.0;
  double span_rad = 0.0;
};

/// The directions an azimuth may use, as arcs of at most 180° each (a longer allowed arc is cut
/// into equal pieces; the full circle is one arc of 2π when nothing is forbidden). Empty when
/// the forbidden sectors cover every direction.
std::vector<AllowedArc> allowed_arcs(const std::vector<AngleSector>& forbidden_deg);

/// True when direction α [rad] lies inside a forbidden sector (its edges allowed), within
/// `tolerance_rad`.
bool in_forbidden_sector(double alpha_rad, const std::vector<AngleSector>& forbidden_deg,
                         double tolerance_rad = 1e-9);

}  // namespace dynpos::model
