#pragma once
/// \file
/// A campaign: several scenarios run on one vessel, each into its own folder, with a summary of
/// each run. `dynpos simulate campaign` and `dynpos demo` are built on it.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "dynpos/scenario/run_files.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::scenario {

/// Key figures of one simulated scenario, for the campaign summary.
struct RunSummary {
  std::string name;
  std::string description;
  double duration_s = 0.0;
  std::size_t rows = 0;
  std::uint64_t seed = 0;         ///< the scenario's own seed (from the master seed and name)
  double max_speed_mps = 0.0;     ///< largest √(u² + v²)
  double max_yaw_rate_dps = 0.0;  ///< largest |r| [deg/s]
  double distance_m = 0.0;        ///< track length over ground
  double energy_kJ = 0.0;         ///< ∫(P_port + P_stb + P_tunnel) dt
  double wall_time_s = 0.0;       ///< simulation time on this machine
};

/// The seed a scenario runs with in a campaign: independent of which other scenarios run.
std::uint64_t campaign_seed(std::uint64_t master_seed, const std::string& scenario_name);

/// Every scenario file of `scenario_dir` (list_scenarios), loaded, in name order. Throws
/// core::InputError naming the folder if it holds none.
std::vector<ScenarioSpec> load_campaign(const std::filesystem::path& scenario_dir);

/// Runs each scenario with its campaign_seed() and writes DIR/<name>/ as it goes
/// (run_scenario_into), on `jobs` threads (0 = every core; each run holds one block of rows,
/// kRunBlockRows). The files
/// do not depend on `jobs`. Returns the summaries in scenario order; the report on them is the
/// application's (analysis/campaign_report.hpp).
std::vector<RunSummary> run_campaign(const std::vector<ScenarioSpec>& scenarios,
                                     const VesselConfig& vessel, std::uint64_t master_seed,
                                     const std::filesystem::path& out_dir, unsigned jobs = 0);

}  // namespace dynpos::scenario
