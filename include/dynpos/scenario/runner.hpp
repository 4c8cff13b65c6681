#pragma once
/// \file
/// Runs a scenario on the virtual vessel: the plant, the operator's commands, the log and the
/// truth that goes with it.
///
/// run_scenario() composes the parts of a run on one sim::Simulator: the VesselPlant, the
/// control task (operator commands, auto heading or DP, thrust allocation; control_task.hpp),
/// the actuators' dead times (actuator_commands.hpp), the environment (trial_environment.hpp)
/// and the two loggers (truth_recorder.hpp, trial_logger.hpp), on the time base of
/// trial_clock.hpp.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "dynpos/core/log.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/trial_truth.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::scenario {

/// The outcome of one run.
struct ScenarioRun {
  /// The trial logger: every sensor at its rate with noise and latency (missing between its
  /// samples), commands and setpoints, in logger units (deg, rpm, kW, kN; docs/log-format.md).
  core::Log log;
  /// The true motion and actuator states at the log rate, SI units (docs/log-format.md).
  core::Log truth_log;
  /// Parameters, seed, lever arms, command times, true time constants (truth.json).
  TrialTruth truth;
  /// UTC of t = 0, "YYYY-MM-DDTHH:MM:SS[.sss]Z" (ScenarioSpec::start_utc).
  std::string start_utc;
  /// [m] geoid (mean sea level) above the WGS84 ellipsoid at the GNSS origin: the origin's
  /// ellipsoidal height, the vessel's sea level. NMEA GGA splits the height with it.
  double geoid_separation_m = 0.0;
  /// Write the device files too (ScenarioSpec::device_files).
  std::optional<DeviceFilesSpec> device_files;
};

/// Simulates `spec` on `vessel` with master seed `seed`. Deterministic: the same inputs give
/// bit-identical results. Throws std::runtime_error if the simulation fails (e.g. diverges).
ScenarioRun run_scenario(const ScenarioSpec& spec, const VesselConfig& vessel, std::uint64_t seed);

/// Receives a run's rows a block at a time, in time order: the trial logger's rows and the
/// truth's rows of the same times. Both logs are emptied after the call (their channels stay).
using RunBlockSink = std::function<void(const core::Log& log, const core::Log& truth_log)>;

/// Rows a streamed run holds before it hands them on: 16 384 rows (164 s at 100 Hz) of the
/// ~150 channels of the two logs take about 14 MB.
inline constexpr std::size_t kRunBlockRows = 16384;

/// As run_scenario(), but the rows go to `sink` every `block_rows` rows and at the end instead
/// of being kept, so that memory does not grow with the run (finding M1 of the reliability
/// review). The returned run's logs have their channels and no rows. The blocks joined are
/// run_scenario()'s logs, bit for bit. Throws std::invalid_argument if `sink` is empty, and
/// whatever `sink` throws.
ScenarioRun stream_scenario(const ScenarioSpec& spec, const VesselConfig& vessel,
                            std::uint64_t seed, const RunBlockSink& sink,
                            std::size_t block_rows = kRunBlockRows);

}  // namespace dynpos::scenario
