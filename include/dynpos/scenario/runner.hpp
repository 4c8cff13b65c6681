#pragma once
/// \file
/// Runs a scenario on the virtual vessel: the plant, the operator's commands, the log and the
/// truth that goes with it.

#include <cstdint>

#include <nlohmann/json.hpp>

#include "dynpos/core/log.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::scenario {

/// The outcome of one run.
struct ScenarioRun {
  /// The trial logger: every sensor at its rate with noise and latency (missing between its
  /// samples), commands and setpoints, in logger units (deg, rpm, kW, kN; docs/log-format.md).
  core::Log log;
  /// The true motion and actuator states at the log rate, SI units (docs/log-format.md).
  core::Log truth_log;
  nlohmann::json truth;  ///< parameters, seed, lever arms, command times, true time constants
};

/// Simulates `spec` on `vessel` with master seed `seed`. Deterministic: the same inputs give
/// bit-identical results. Throws std::runtime_error if the simulation fails (e.g. diverges).
ScenarioRun run_scenario(const ScenarioSpec& spec, const VesselConfig& vessel, std::uint64_t seed);

}  // namespace dynpos::scenario
