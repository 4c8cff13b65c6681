#pragma once
/// \file
/// The DP 4-corner maneuver (thesis section 3.5.2, tables 3.6–3.10): the log cut into its legs,
/// with the duration, the accumulated thrust ∫|T|dt and the energy ∫P dt of each thruster per
/// leg and in total.
///
/// Segmentation (docs/theory.md, "DP 4-corner"):
/// - from the DP setpoints when they are logged: every change of the setpoint starts a leg; the
///   leg ends when the vessel is first inside the operating circle of its setpoint (position
///   within `radius_m`, heading within `heading_tol_rad`), or at the next change if it never
///   gets there (then `reached` is false unless the change finds it within the reach margins).
///   Position and heading are first averaged over a centered window of `wave_filter_s` (unit
///   vectors for the heading): the DP system decides on its wave-filtered estimate, and a 1–2 m sea
///   moves a high GNSS antenna by decimetres, which would otherwise let the crossing of the circle
///   jump by many seconds. A leg is named by its move in the frame of the previous setpoint
///   heading: "ahead 50 m", "crab to port 50 m", "astern 50 m, heading −90°".
/// - otherwise from the track and heading: the vessel is moving when its speed over ground
///   exceeds `moving_speed_mps` or its turn rate `moving_rate_rad_s` (both from differences over
///   ±`smoothing_s`); stretches of motion, with pauses shorter than `min_pause_s` bridged, are
///   cut at their corners: the track of a stretch is simplified to a polyline (Douglas–Peucker,
///   vertices where it strays more than `corner_tolerance_m` from the chord), each polyline
///   segment is a leg. Legs shorter than `min_leg_s`, or that neither move `min_move_m` nor turn
///   `min_turn_rad` (the vessel swaying in waves), are dropped. A leg is named by its
///   displacement in the frame of its start heading.
/// The position may be that of a GNSS antenna: with its lever arm given, it is moved to the
/// control origin, where a DP system tests its operating circle; without, the circle is tested
/// at the antenna (a 0.6 m arm moves a slow final approach's crossing by several seconds).

#include <optional>
#include <string>
#include <vector>

#include "dynpos/ident/channel_integrals.hpp"
#include "dynpos/ident/station_keeping.hpp"

namespace dynpos::ident {

/// Logged channels, SI, NaN = missing sample; an empty vector = not logged.
struct FourCornerInput {
  std::vector<double> t_s;  ///< strictly increasing
  std::vector<double> north_m, east_m, heading_rad;
  std::vector<double> setpoint_north_m, setpoint_east_m, setpoint_heading_rad;
  std::vector<ThrusterChannels> thrusters;
  /// Horizontal lever arm (x forward, y starboard) [m] of the point whose position is logged
  /// (e.g. a GNSS antenna); the position is moved to the control origin, p_CO = p − R(ψ)·l,
  /// before the analysis. Zero when the logged position is already the control origin's.
  double arm_x_m = 0.0, arm_y_m = 0.0;
};

/// How the legs are found.
enum class LegSegmentation {
  kAuto,       ///< from the setpoints when they are logged and change, else from the track
  kSetpoints,  ///< from the setpoints only (error if they are not logged or never change)
  kTrack,      ///< from the track and heading only
};

struct FourCornerOptions {
  LegSegmentation segmentation = LegSegmentation::kAuto;
  double radius_m = 2.0;           ///< operating circle [m], > 0
  double heading_tol_rad = 0.035;  ///< ≈ 2°, > 0
  /// Width of the centered moving average of position and heading before the circle test [s];
  /// 0 = none. 10 s spans one to two wave periods (Tp 6–8 s).
  double wave_filter_s = 10.0;
  /// A setpoint change that finds the vessel within radius + reach_margin_m and heading_tol +
  /// reach_margin_rad counts as reaching the old setpoint: a DP sequence issues its next
  /// setpoint on reaching, and the filtered position differs from the DP's by decimetres.
  double reach_margin_m = 0.5;
  double reach_margin_rad = 0.009;   ///< ≈ 0.5°
  double moving_speed_mps = 0.1;     ///< track segmentation: moving above this speed [m/s]
  double moving_rate_rad_s = 0.005;  ///< … or above this turn rate [rad/s] (≈ 0.3°/s)
  double smoothing_s = 5.0;          ///< half-width of the difference for speed and rate [s]
  double min_leg_s = 20.0;           ///< shorter stretches of motion are not legs [s]
  double min_pause_s = 15.0;         ///< shorter pauses do not end a leg [s]
  double corner_tolerance_m = 5.0;   ///< track deviation from a straight leg that is a corner [m]
  double min_move_m = 5.0;           ///< a track leg moves at least this far … [m]
  double min_turn_rad = 0.175;       ///< … or turns at least this much (≈ 10°) [rad]
  ChannelIntegralOptions integrals;
  /// Throws core::InputError naming the bad option.
  void validate() const;
};

struct Leg {
  std::string name;
  double t_start_s = 0.0;
  double t_end_s = 0.0;
  /// t_end − t_start for a leg; for the total, the sum of the legs' durations (pauses between
  /// legs of a track segmentation are not counted) [s].
  double duration_s = 0.0;
  /// Displacement over the leg in the frame of its start heading [m] and heading change [rad];
  /// from the setpoints (setpoint segmentation) or the track.
  double forward_m = 0.0, starboard_m = 0.0, heading_change_rad = 0.0;
  bool reached = true;  ///< setpoint segmentation: the operating circle was reached
  std::optional<double> setpoint_north_m, setpoint_east_m, setpoint_heading_rad;
  std::vector<ThrusterSummary> thrusters;  ///< accumulated thrust and energy over the leg
  std::optional<double> total_accumulated_thrust_Ns;
  std::optional<double> total_energy_J;
};

struct FourCornerResult {
  std::string segmentation;  ///< "setpoints" or "track"
  std::vector<Leg> legs;
  /// "total": first start to last end; duration, accumulated thrust and energy summed over the
  /// legs (missing when any leg's figure is).
  Leg total;
};

/// A leg's name from its move: "ahead 50 m", "crab to port 50 m", "astern 50 m, heading
/// change −90°". A component is named when it exceeds `min_move_m` and a quarter of the larger
/// one; the heading change when it exceeds `min_turn_rad`.
std::string leg_name(double forward_m, double starboard_m, double heading_change_rad,
                     double min_move_m = 2.0, double min_turn_rad = 0.035);

/// Cuts the maneuver into legs and sums per leg. Throws core::InputError when the position or
/// heading is not logged, or no leg is found (no setpoint change and no motion).
FourCornerResult analyse_four_corner(const FourCornerInput& input,
                                     const FourCornerOptions& options = {});

}  // namespace dynpos::ident
