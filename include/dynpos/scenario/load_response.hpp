#pragma once
/// \file
/// How a DP vessel answers a sudden load (an ice load setting in, a mooring line snapping), and
/// the comparison of the conventional and the hybrid integral action on the same run (thesis
/// chapter 5 on the full virtual vessel).

#include <cstddef>
#include <cstdint>
#include <optional>

#include "dynpos/core/log.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::scenario {

/// Figures of the response to a load at t_load, from a truth log with north, east,
/// setpoint.north, setpoint.east and power.* channels.
struct LoadResponse {
  double t_load_s = 0.0;
  double peak_offset_m = 0.0;  ///< largest horizontal distance from the setpoint after t_load
  /// Time after t_load from which the distance stays within the threshold to the end of the
  /// run: 0 if it never left; nullopt if it is still outside at the end.
  std::optional<double> back_within_s;
  double within_m = 1.0;    ///< the threshold [m]
  double iae_m_s = 0.0;     ///< ∫ distance dt from t_load to the end [m·s]
  double energy_kJ = 0.0;   ///< ∫ (P_port + P_stb + P_tunnel) dt from t_load to the end [kJ]
  double duration_s = 0.0;  ///< the evaluated interval, t_load to the end of the log [s]
};

/// Evaluates the truth log after t_load_s (inside the log). Throws std::invalid_argument if a
/// channel is missing, t_load_s is outside the log or within_m ≤ 0.
LoadResponse evaluate_load_response(const core::Log& truth_log, double t_load_s,
                                    double within_m = 1.0);

/// The time of the first load event of spec: when it sets in, or for a load on from the start
/// (a mooring line), when it is released. Throws core::InputError if spec has no load.
double first_load_change_s(const ScenarioSpec& spec);

/// One design's run and its response.
struct DesignRun {
  ScenarioRun run;
  LoadResponse response;
  std::size_t jumps = 0;  ///< jumps of the integral state over the whole run
};

/// The conventional and the hybrid design on the same scenario, seed and vessel.
struct HybridComparison {
  DesignRun conventional;
  DesignRun hybrid;
  double t_load_s = 0.0;
};

/// Runs spec twice — without and with hybrid integral action (spec.hybrid_integral, or the
/// defaults of hybrid::IntegralJumpParams when absent) — and evaluates both after the load.
HybridComparison compare_integral_action(const ScenarioSpec& spec, const VesselConfig& vessel,
                                         std::uint64_t seed, double within_m = 1.0);

}  // namespace dynpos::scenario
