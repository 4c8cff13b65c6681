#pragma once
/// \file
/// ScenarioSpec: what one virtual sea-trial run does — its length, environment and the
/// schedule of operator commands — as read from a scenario file in data/scenarios/.
///
/// Angles here are in the units of the scenario file's keys (degrees); the runner converts.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "dynpos/control/observer.hpp"
#include "dynpos/hybrid/integral_jump.hpp"
#include "dynpos/scenario/device_files.hpp"

namespace dynpos::scenario {

/// Joystick (manual) thrust demand, held from t_s until the next entry: the fraction of the
/// maximum force or moment in each DOF that goes to the thrust allocation.
struct JoystickCommand {
  double t_s = 0.0;        ///< [s] ≥ 0, when the demand is applied
  double surge_pct = 0.0;  ///< [%] −100…100 of maximum surge force, + forward
  double sway_pct = 0.0;   ///< [%] −100…100 of maximum sway force, + starboard
  double yaw_pct = 0.0;    ///< [%] −100…100 of maximum yaw moment, + bow to starboard
};

/// Manual rudder command (both rudders, as in the thesis' yaw step tests), held from t_s until
/// the next entry; it overrides the allocation's rudder angles until an entry with release.
struct RudderCommand {
  double t_s = 0.0;        ///< [s] ≥ 0
  double angle_deg = 0.0;  ///< [deg] −90…90, + trailing edge to starboard (turns to starboard);
                           ///< the servo limits it to the rudder's maximum angle
  bool release = false;    ///< true: hand the rudders back to the thrust allocation
};

/// A DP setpoint (NED, relative to the start position). With a time it is applied then; without
/// one (t_s < 0) it is applied when the vessel reaches the previous setpoint's operating circle,
/// as in the DP 4-corner maneuver (thesis 3.5.2).
struct SetpointCommand {
  double t_s = -1.0;         ///< [s], or < 0 for "when the previous one is reached"
  double north_m = 0.0;      ///< [m]
  double east_m = 0.0;       ///< [m]
  double heading_deg = 0.0;  ///< [deg]
  std::string name;          ///< leg name for reports (e.g. "ahead"), may be empty
};

/// A scheduled load in NED, e.g. an ice load (switched on) or a mooring line that snaps (on
/// from the start, off at the snap).
struct LoadEvent {
  double t_on_s = 0.0;     ///< [s] ≥ 0
  double t_off_s = 1e300;  ///< [s] > t_on_s; default: never switched off
  double north_N = 0.0;    ///< force towards north [N]
  double east_N = 0.0;     ///< force towards east [N]
  double yaw_Nm = 0.0;     ///< yaw moment, + bow to starboard [N·m]
};

/// A failure as it happens: at t_s the unit, group ("group:NAME") or model actuator `name`
/// trips. Its drive is cut (its thrust falls with the unit's own dynamics); the DP system flags
/// it from its feedback kDetection_s later and the allocation has it at capacity 0 from then on
/// (unit_failure.hpp).
struct FailureEvent {
  double t_s = 0.0;  ///< [s] in [0, duration]
  std::string name;  ///< a [[thruster]] unit, "group:NAME", or port, stb, tunnel, rudder.port,
                     ///< rudder.stb of the model; several joined by "+" fail together
};

/// A loss of the DP system's position reference (every GNSS receiver) over
/// [t_s, t_s + duration_s): no fixes are logged and the DP observer coasts on its model.
struct DropoutEvent {
  double t_s = 0.0;         ///< [s] ≥ 0
  double duration_s = 0.0;  ///< [s] > 0
  /// True at scenario time t [s].
  bool covers(double t) const noexcept { return t >= t_s && t < t_s + duration_s; }
};

/// True while one of `dropouts` covers scenario time t [s].
bool any_covers(const std::vector<DropoutEvent>& dropouts, double t) noexcept;

/// The weather and water of a run. Directions follow the sea-trial habit: wind and waves are
/// given as the direction they come FROM, current as the direction it flows TO, all in degrees
/// clockwise from north.
struct EnvironmentSpec {
  double current_speed_mps = 0.0;  ///< [m/s] 0…3
  double current_to_deg = 0.0;     ///< [deg] direction the current flows to
  double wind_speed_mps = 0.0;     ///< [m/s] 0…40, 10-minute mean at 10 m
  double wind_from_deg = 0.0;      ///< [deg]
  double hs_m = 0.0;               ///< [m] significant wave height 0…8 (0 = no waves)
  double tp_s = 6.0;               ///< [s] spectral peak period 2…20
  double wave_from_deg = 0.0;      ///< [deg]
  int wave_components = 60;        ///< number of spectral components, 10…1000
};

/// A whole scenario.
struct ScenarioSpec {
  std::string name;           ///< identifier, e.g. "surge-steps-forward"
  std::string description;    ///< one paragraph for humans
  std::string source;         ///< file it was read from (for messages), empty if built in code
  double duration_s = 60.0;   ///< [s] > 0, run length
  double dt_s = 0.01;         ///< [s] integration step, > 0, divides every rate's period
  double log_rate_hz = 10.0;  ///< [Hz] rate of the truth log; its period is a multiple of dt
  double initial_heading_deg = 0.0;  ///< [deg] ψ(0)
  /// UTC of t = 0, "YYYY-MM-DDTHH:MM:SS[.sss]Z": the time base of the NMEA files
  /// (gnssK.nmea). Default: a day of the Gunnerus sea trials of August 2014.
  std::string start_utc = "2014-08-27T10:00:00Z";
  double initial_surge_mps = 0.0;  ///< [m/s] u(0), with actuators trimmed to hold it
  /// Joystick with auto heading: a heading controller adds its yaw demand to the joystick's,
  /// holding ψ(0), as a DP joystick does in sway tests. Not with DP setpoints.
  bool heading_hold = false;
  /// [s] whole seconds in [0, 3600]: the vessel runs this long before t = 0 in the
  /// scenario's weather with its t = 0 state of commands (no lever, or the trim of
  /// initial_surge_mps; auto heading if on), and the logs begin after it. A trial log starts
  /// with the vessel drifting with current and wind, not at rest over ground. Joystick scenarios
  /// only (DP holds its first setpoint from rest).
  double settle_s = 0.0;
  EnvironmentSpec environment;
  std::vector<JoystickCommand> joystick;  ///< sorted by t_s; empty = zero demand throughout
  std::vector<RudderCommand> rudder;      ///< sorted by t_s; manual rudder steps
  /// DP mode: when non-empty, the DP controller (with reference model) drives the allocation
  /// from the first setpoint's time on, and joystick commands are not allowed.
  std::vector<SetpointCommand> setpoints;
  std::vector<LoadEvent> loads;  ///< scheduled step loads
  /// DP mode: what the DP controller runs on (file key `observer`): the true low-frequency
  /// motion ("ideal", the default), the passive observer, the EKF, or the raw measurements.
  control::ObserverKind observer = control::ObserverKind::kIdeal;
  /// Whether the observer's model has the wind force from the DP system's wind sensor, as DP
  /// systems feed the wind forward (file key `observer_wind_feedforward`; dp_estimator.hpp).
  /// Default true; false leaves the wind in the observer's bias estimate (docs/theory.md).
  bool observer_wind_feedforward = true;
  /// Whether the DP system bridges a GNSS loss by dead reckoning on its MRU's acceleration
  /// (file key `inertial_position_aid`; control/inertial_position.hpp, dp_estimator.hpp).
  /// Default true; false leaves the observer to coast on its model through the loss.
  bool inertial_position_aid = true;
  /// A unit that fails during the run (file keys `failure_at_s`, `failure`).
  std::optional<FailureEvent> failure;
  /// GNSS dropouts ([[gnss_dropout]] with t_s, duration_s), in increasing time.
  std::vector<DropoutEvent> gnss_dropouts;
  /// DP mode with hybrid integral action (thesis ch. 5): the bias estimate jumps by the
  /// practical rule (5.64)–(5.67) (file section [hybrid], enabled = true). Absent: the
  /// conventional continuous integral action only.
  std::optional<hybrid::IntegralJumpParams> hybrid_integral;
  /// Also write the logs as real loggers do, one file per device (section [device_files],
  /// enabled = true; device_files.hpp). Absent: log.csv, truth and NMEA files only.
  std::optional<DeviceFilesSpec> device_files;
  /// Shortens (or lengthens) the run to duration [s], dropping commands after the new end.
  void set_duration(double duration);
  /// Throws core::InputError (naming source and the bad field) if a value is out of range, the
  /// joystick times are not increasing or lie outside [0, duration].
  void validate() const;
};

/// Reads a scenario TOML file (schema in docs/cli.md, "Scenario files").
/// Throws core::InputError with file, line and key for every problem.
ScenarioSpec load_scenario(const std::filesystem::path& path);

/// The names of the scenario files (stem of data/scenarios/*.toml) in `scenario_dir`, sorted.
std::vector<std::string> list_scenarios(const std::filesystem::path& scenario_dir);

/// Resolves a scenario argument: an existing .toml path, or a name in `scenario_dir`.
/// Throws core::InputError "unknown scenario 'X'" listing the available ones.
std::filesystem::path resolve_scenario(const std::string& name_or_path,
                                       const std::filesystem::path& scenario_dir);

}  // namespace dynpos::scenario
