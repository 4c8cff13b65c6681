#pragma once
// The dynpos subcommands: each file registers one on the top-level app.
// A registered callback throws on failure; main() maps exceptions to exit codes.

#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "dynpos/scenario/campaign.hpp"

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

void register_simulate(CLI::App& app);
void register_identify(CLI::App& app);
void register_leverarm(CLI::App& app);
void register_hybrid(CLI::App& app);
void register_compare(CLI::App& app);
void register_demo(CLI::App& app);

}  // namespace dynpos::cli
