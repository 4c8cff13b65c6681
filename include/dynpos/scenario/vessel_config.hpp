#pragma once
/// \file
/// VesselConfig: every parameter of a virtual vessel, as read from a vessel file
/// (data/vessels/gunnerus.toml). Defaults are the virtual Gunnerus; the file states the
/// values and their sources explicitly.

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "dynpos/core/error.hpp"
#include "dynpos/core/param_range.hpp"
#include "dynpos/model/environment.hpp"
#include "dynpos/model/hull.hpp"
#include "dynpos/model/sea_state.hpp"
#include "dynpos/model/thrust_allocation.hpp"
#include "dynpos/model/thruster_unit.hpp"
#include "dynpos/sensors/sensor_suite.hpp"

namespace dynpos::scenario {

/// Joystick scaling: 100 % demand in a DOF is this force or moment.
struct JoystickParams {
  double max_surge_N = 146e3;  ///< Source: 2 × 73 kN ahead (ThrusterParams at n_max).
  double max_sway_N = 45e3;    ///< Source: tunnel 25 kN + rudder lift at low speed (reasoned).
  double max_yaw_Nm = 6.0e5;   ///< Source: differential thrust + tunnel moment (reasoned).
  /// Lever curve exponent e ≥ 1 (joystick_lever.hpp): a lever at p % along an axis demands
  /// |p/100|^e of the maximum; 1 is a linear lever. Source: calibrated to table 3.24. With e = 2
  /// a surge lever at p % runs the main propellers at p % of n_max, and the speed change of
  /// each mid-size step, Δu ≈ T·ΔF/(m − X_u̇), is the same across the 15–25 %, 25–40 % and
  /// 0–80 % steps (Δu ∝ Δp), which is what the thesis' time constants 59, 34 and 16 s imply;
  /// with e = 1 the 25–40 % step's T came out at 16–19 s.
  double lever_exponent = 2.0;
  /// Allocation and joystick update rate [Hz]. Source: reasoned, typical DP cycle.
  double control_rate_hz = 10.0;
  /// Auto-heading (heading hold) natural frequency ω [rad/s] and damping ratio ζ: a PID law
  /// N = −k_p·ψ̃ − k_d·r − k_i∫ψ̃ with k_p = (I_z − N_ṙ)ω², k_d = 2ζω(I_z − N_ṙ) − N_r and
  /// integral time 10/ω.
  /// Source: reasoned — slow enough not to fight waves, fast enough to hold ±2° in sway tests.
  double heading_hold_omega_rad_s = 0.15;
  double heading_hold_zeta = 0.9;
  /// Throws core::InputError naming the first value outside its range (vessel_param_sections).
  void validate() const;
};

/// All parameters of one virtual vessel.
struct VesselConfig {
  std::string name = "Gunnerus";
  std::string source;  ///< file it was read from, empty for built-in defaults
  model::HullParams hull;
  model::ThrusterParams propeller;  ///< both main propellers
  model::RudderParams rudder;       ///< both rudders
  model::TunnelThrusterParams tunnel;
  model::ThrustConfigurationParams layout;
  model::ThrustAllocationOptions allocation;
  model::WaveResponseParams waves;
  model::WindParams wind;        ///< only the vessel part (areas, coefficients, gust model) is used
  model::CurrentParams current;  ///< only the variation part is used
  model::BiasParams bias;
  JoystickParams joystick;
  /// GNSS antennas, MRUs, gyro, speed log, wind sensor and feedback (vessel-file sections
  /// [sensors], [gnss1]–[gnss3], [mru1]–[mru2], [gyro], [speed_log], [wind_sensor], [feedback]).
  sensors::SensorSuiteParams sensors;
  /// The thruster layout of [[thruster]] tables (docs/vessel-file.md), for the allocation of
  /// any layout and `capability --loads`; empty: the model's own units (the two propellers with
  /// rudders and the tunnel above). The simulator runs them when present.
  std::vector<model::ThrusterUnit> thrusters;
  /// Each [[thruster]] unit's capacity (1 as rated, 0 lost), in layout order; empty: all 1. Not a
  /// vessel-file key: the failure cases of a capability analysis set it.
  std::vector<double> thruster_capacity;

  /// Throws core::InputError naming the first value outside its range or the rule between
  /// values that does not hold (e.g. a mass matrix that is not positive definite).
  void validate() const;
  /// Every parameter in file units, section by section (the layout of the vessel file).
  nlohmann::json to_json() const;
};

/// The numeric keys of every vessel-file section in file order, each bound to its field in
/// `config` with its unit and range: the tables validate() checks, load_vessel_config reads
/// and docs/vessel-file.md lists.
std::vector<core::ParamSection> vessel_param_sections(VesselConfig& config);

/// The ranges of every vessel-file key as Markdown, one table per section (the generated part
/// of docs/vessel-file.md).
std::string vessel_param_tables_markdown();

/// Reads a vessel TOML file; absent keys keep the built-in value. Throws core::InputError with
/// file, line and key for syntax errors, unknown sections or keys and out-of-range values.
VesselConfig load_vessel_config(const std::filesystem::path& path);

}  // namespace dynpos::scenario
