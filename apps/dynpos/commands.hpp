#pragma once
// The dynpos subcommands: each file registers one on the top-level app.
// A registered callback throws on failure; main() maps exceptions to exit codes.

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/scenario/campaign.hpp"
#include "dynpos/scenario/load_response.hpp"

namespace dynpos::cli {

/// Exit codes of the dynpos executable.
enum ExitCode : int {
  kExitOk = 0,
  kExitFailure = 1,      ///< an unexpected error while running
  kExitInputError = 2,   ///< bad input or options: the message says where and how to fix it
  kExitUnavailable = 3,  ///< the subcommand is part of the contract but not in this version
};

/// Thrown by a subcommand that is part of the CLI contract but not shipped in this version.
struct Unavailable {
  std::string command;
  std::string planned;  ///< what the subcommand will do
};

/// The scenario name that runs every built-in scenario.
inline constexpr const char* kCampaign = "campaign";

/// Every scenario file of `scenario_dir`, loaded, in name order.
std::vector<scenario::ScenarioSpec> load_campaign(const std::filesystem::path& scenario_dir);

/// Prints one line per run and where the report is.
void print_campaign(const std::vector<scenario::RunSummary>& runs,
                    const std::filesystem::path& out_dir);

/// `dynpos hybrid vessel`: both designs on a sudden-load scenario of the virtual Gunnerus.
struct HybridVesselResult {
  std::string name;           ///< "ice" or "mooring"
  std::string scenario_name;  ///< the scenario file's name, e.g. "dp-ice-load"
  std::uint64_t seed = 1;
  scenario::HybridComparison comparison;
  nlohmann::json parameters;  ///< the jump rule's parameters
};
/// The scenario file of a load case ("ice" → "dp-ice-load"); InputError for an unknown one.
std::string hybrid_vessel_scenario_file(const std::string& short_name);
HybridVesselResult run_hybrid_vessel(const std::string& short_name, std::uint64_t seed,
                                     double within_m = 1.0);
nlohmann::json hybrid_vessel_json(const HybridVesselResult& r);
enum class TableFormat { kText, kMarkdown, kHtml };
/// The side-by-side table.
std::string hybrid_vessel_table(const HybridVesselResult& r, TableFormat format);
std::vector<std::filesystem::path> write_hybrid_vessel_plots(const HybridVesselResult& r,
                                                             const std::filesystem::path& dir);
/// Adds `vessel` to the `hybrid` subcommand.
void add_hybrid_vessel(CLI::App& hybrid);

/// Adds a subcommand of the contract that a later version fills in: it says what it will do
/// and exits with kExitUnavailable.
void add_planned(CLI::App& parent, const std::string& name, const std::string& description,
                 const std::string& planned);

// Subcommands under `identify` and `leverarm`, one file each.
void add_identify_agility(CLI::App& identify);          // cmd_identify_agility.cpp
void add_identify_thrust_map(CLI::App& identify);       // cmd_identify_thrust_map.cpp
void add_identify_four_corner(CLI::App& identify);      // cmd_identify_four_corner.cpp
void add_identify_station_keeping(CLI::App& identify);  // cmd_identify_station_keeping.cpp
void add_leverarm_gnss(CLI::App& leverarm);             // cmd_leverarm_gnss.cpp
void add_leverarm_mru(CLI::App& leverarm);              // cmd_leverarm_mru.cpp

void register_simulate(CLI::App& app);
void register_identify(CLI::App& app);
void register_leverarm(CLI::App& app);
void register_hybrid(CLI::App& app);
void register_compare(CLI::App& app);
void register_demo(CLI::App& app);

}  // namespace dynpos::cli
