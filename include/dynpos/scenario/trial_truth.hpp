#pragma once
/// \file
/// TrialTruth: what a virtual sea trial knows to be true about its run — the seed, the scenario
/// and vessel as run, the exact command and step times, the true lever arms and the model's
/// true time constants — written by the simulator (run_scenario) and read by the analyses and
/// tests that compare their estimates with it.
///
/// truth.json is its file format (docs/log-format.md). to_json()/write_trial_truth() are its one
/// writer and from_json()/read_trial_truth() its one reader. Units are SI unless a field's name
/// gives its unit (the keys of truth.json are the field names). A missing number (NaN) is JSON
/// null, and null reads back as NaN.
///
/// The vessel block stays JSON: it is the vessel file's schema (every parameter in file units,
/// section by section) that VesselConfig::to_json() defines from the vessel file's field tables;
/// a typed copy would be a second reader of that schema beside the TOML loader, and none of the
/// analyses reads it (they read the typed lever arms).

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/hybrid/integral_jump.hpp"
#include "dynpos/model/fopdt_truth.hpp"
#include "dynpos/model/hull.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/sensors/mru.hpp"

namespace dynpos::scenario {

/// The scenario as run (truth.json "scenario"): its settings, manual rudder steps, loads and
/// weather. The joystick and setpoint schedules are in TrialTruth::commands and ::setpoints,
/// with the times the run applied them.
struct TrialScenario {
  std::string name;
  std::string description;
  double duration_s = 0.0;
  double dt_s = 0.0;
  double log_rate_hz = 0.0;
  double initial_heading_deg = 0.0;
  double initial_surge_mps = 0.0;
  double settle_s = 0.0;
  std::string start_utc;
  std::vector<RudderCommand> rudder;  ///< angle_deg is null in the file for a release
  std::vector<LoadEvent> loads;       ///< t_off_s is null in the file for "never"
  EnvironmentSpec environment;
};

/// The scenario part of `spec` that truth.json repeats.
TrialScenario trial_scenario(const ScenarioSpec& spec);

/// One joystick command at the control step that applied it (truth.json "commands").
struct CommandTruth {
  double t_s = 0.0;
  double surge_pct = 0.0;  ///< the lever [%] as the operator set it
  double sway_pct = 0.0;
  double yaw_pct = 0.0;
  double demand_surge_N = 0.0;  ///< the demand the lever makes through the lever curve
  double demand_sway_N = 0.0;
  double demand_yaw_Nm = 0.0;
  double n_port_rps = 0.0;  ///< the allocation's commands at that step
  double n_stb_rps = 0.0;
  double rudder_port_deg = 0.0;
  double rudder_stb_deg = 0.0;
  double n_tunnel_rps = 0.0;
  Eigen::Vector3d tau_unmet = Eigen::Vector3d::Zero();  ///< X [N], Y [N], N [N·m] not met
};

/// A change of a main propeller's commanded shaft speed with its Smith two-point truth
/// (truth.json "propeller_steps"; fopdt_truth.hpp).
struct PropellerStepTruth {
  double t_s = 0.0;
  std::string thruster;  ///< "port" or "stb"
  double n_from_rps = 0.0;
  double n_to_rps = 0.0;
  model::FopdtTruth shaft_speed;
  model::FopdtTruth thrust;
};

/// Nomoto's time constants of the linearised hull at one speed (2.13) [s].
struct NomotoTruth {
  double T1_s = 0.0;
  double T2_s = 0.0;
  double T3_s = 0.0;
  double Tr_s = 0.0;  ///< T₁ + T₂ − T₃, the first-order yaw-rate time constant
};

/// The Nomoto truth of a model::Hull::Nomoto.
NomotoTruth nomoto_truth(const model::Hull::Nomoto& n);

/// A manual rudder step (truth.json "rudder_steps").
struct RudderStepTruth {
  double t_s = 0.0;
  double from_deg = 0.0;
  double to_deg = 0.0;  ///< within the servo's limit
  double surge_mps = 0.0;
  model::FopdtTruth servo;            ///< the servo's Smith truth
  std::optional<NomotoTruth> nomoto;  ///< at the step's surge speed, when above 0.1 m/s
};

/// A DP setpoint as the run applied it (truth.json "setpoints").
struct SetpointTruth {
  std::string name;
  double t_start_s = 0.0;
  double north_m = 0.0;
  double east_m = 0.0;
  double heading_deg = 0.0;
  std::optional<double> t_end_s;      ///< when the next setpoint took over
  std::optional<double> t_reached_s;  ///< first time inside the operating circle (3.5.2)
};

/// The hybrid integral action of a run (truth.json "hybrid").
struct HybridTruth {
  hybrid::IntegralJumpParams params;
  std::vector<double> jump_times_s;
};

/// The model's own time constants (truth.json "time_constants").
struct TimeConstantsTruth {
  NomotoTruth nomoto_3kn;
  NomotoTruth nomoto_6kn;
  model::FopdtTruth rudder_0_to_20deg;
};

/// A failure as it happened in the run (ScenarioSpec::failure) and the vessel's response, from
/// the true motion of the control origin as the log samples it (wave-frequency motion included,
/// as a position reference sees it), with the meanings of `identify failure-test`
/// (ident/failure_test.hpp: pre-failure window 60 s, hold 10 s, response span 300 s).
struct FailureTruth {
  double time_s = 0.0;             ///< the failure instant [s]
  std::string unit;                ///< as the scenario names it (a unit, group:NAME, actuator)
  std::vector<std::string> units;  ///< the units lost
  /// The figures below are missing (NaN, null in the file) with fewer than 3 samples before the
  /// failure.
  double footprint_m = 0.0;       ///< largest pre-failure distance from the pre-failure mean
  double peak_excursion_m = 0.0;  ///< largest distance from the pre-failure mean after it [m]
  double time_to_peak_s = 0.0;    ///< from the failure to that peak [s]
  /// From the failure until back within the pre-failure footprint [s]; missing if never.
  std::optional<double> recovery_s;
  double peak_heading_deg = 0.0;  ///< largest |heading − pre-failure mean| after it [deg]
};

/// Everything truth.json holds (see the file comment).
struct TrialTruth {
  std::uint64_t seed = 0;
  TrialScenario scenario;
  nlohmann::json vessel;  ///< VesselConfig::to_json() of the vessel as run
  std::vector<CommandTruth> commands;
  std::vector<PropellerStepTruth> propeller_steps;
  std::vector<RudderStepTruth> rudder_steps;
  std::vector<SetpointTruth> setpoints;  ///< DP mode only
  std::optional<HybridTruth> hybrid;     ///< with hybrid integral action only
  std::optional<FailureTruth> failure;   ///< with a failure as it happens only
  std::string observer = "ideal";        ///< what the DP controller ran on (ScenarioSpec)
  /// The true lever arm of every GNSS antenna and MRU, BODY [m], by sensor name.
  std::map<std::string, Eigen::Vector3d> lever_arms;
  sensors::AccelerationConvention mru_acceleration = sensors::AccelerationConvention::kKinematic;
  TimeConstantsTruth time_constants;
  /// The largest unmet X [N], Y [N], N [N·m] of the allocation over the run.
  Eigen::Vector3d allocation_unmet_max = Eigen::Vector3d::Zero();
  std::string start_utc;  ///< UTC of t = 0, "YYYY-MM-DDTHH:MM:SS[.sss]Z"
};

/// truth.json's document (keys sorted, as nlohmann::json orders objects).
nlohmann::json to_json(const TrialTruth& truth);

/// Reads a truth.json document. Throws core::InputError naming `file` and the key (e.g.
/// "commands[2].t_s") of the first missing or mistyped value.
TrialTruth from_json(const nlohmann::json& doc, const std::string& file = {});

/// Writes `truth` as truth.json to `path` (pretty-printed, atomically).
void write_trial_truth(const TrialTruth& truth, const std::filesystem::path& path);

/// Reads truth.json from `path`. Throws core::InputError naming the file (and the key) if it
/// cannot be read, is not JSON or lacks a value.
TrialTruth read_trial_truth(const std::filesystem::path& path);

}  // namespace dynpos::scenario
