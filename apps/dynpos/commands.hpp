#pragma once
// The dynpos subcommands: each file registers one on the top-level app.
// A registered callback throws on failure; main() maps exceptions to exit codes.

#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "dynpos/analysis/outputs.hpp"

namespace dynpos::cli {

/// Exit codes of the dynpos executable.
enum ExitCode : int {
  kExitOk = 0,
  kExitFailure = 1,     ///< an unexpected error while running
  kExitInputError = 2,  ///< bad input or options: the message says where and how to fix it
};

/// Adds --seed bound to `seed`: a decimal number from 0 to 2⁶⁴−1, anything else (a sign, "-1",
/// an overflow) refused with exit 2 (output_options.cpp).
CLI::Option* add_seed_option(CLI::App& sub, std::uint64_t& seed, const std::string& help);

/// Adds --json bound to `json`: a file name or "-" (standard output); an empty name is refused
/// with exit 2 instead of silently writing nothing (output_options.cpp).
CLI::Option* add_json_option(CLI::App& sub, std::string& json, const std::string& help);

/// Marks `option` as naming an output file (or "-", standard output) / an output folder, for
/// check_outputs(); returns it (output_options.cpp). --json is marked by add_json_option.
CLI::Option* output_file(CLI::Option* option);
CLI::Option* output_folder(CLI::Option* option);

/// Checks every output of the subcommand given, before any subcommand runs (main.cpp calls it
/// once the command line is parsed), so that a refused output costs no run and nothing is
/// written: an output file's folder exists and the file can be written (analysis::
/// check_output_file), an output folder is not a file (check_output_dir), and no output file
/// is an input of the command (the same device and inode: LOG, A and B, --map, --segments,
/// --vessel, a FILE of --col ROLE=COLUMN@FILE or --clock-offset FILE=SECONDS, …): exit 2
/// naming both.
void check_outputs(const CLI::App& app);

/// Prints the normal output of a subcommand to `out`: the one place reports leave the program.
/// What they echo of the user's input (scenario names, labels, keys, paths) reaches the
/// terminal as text (core::printable_text), never as a control sequence.
void print_text(std::FILE* out, const std::string& text);
template <typename... Args>
void print_text(std::FILE* out, fmt::format_string<Args...> format, Args&&... args) {
  print_text(out, fmt::format(format, std::forward<Args>(args)...));
}

/// The options of an analysis subcommand: its typed request and its outputs (--json, figures).
template <class Request>
struct AnalysisOptions {
  Request request;
  analysis::Outputs outputs;
};

/// Adds --arm, the lever arm X,Y[,Z] [m] of the antenna whose position is logged, bound to
/// `arm_m` (analysis::arm_from_numbers makes it the request's; output_options.cpp).
CLI::Option* add_arm_option(CLI::App& sub, std::vector<double>& arm_m);

/// Prints to_text(report) and a "wrote FILE" line per file `written` to `out`.
template <class Report>
void print_report(std::FILE* out, const Report& report, const analysis::Written& written) {
  print_text(out, to_text(report));
  for (const std::filesystem::path& file : written) print_text(out, "wrote {}\n", file.string());
}

/// Where a subcommand prints its text: standard output, or standard error when the JSON goes
/// to standard output.
inline std::FILE* text_out(const analysis::Outputs& outputs) {
  return outputs.json == "-" ? stderr : stdout;
}

/// The end of every analysis subcommand: write_outputs(report, outputs) (the analysis' files and
/// JSON), then print_report on text_out(outputs).
template <class Report>
void write_and_print(const Report& report, const analysis::Outputs& outputs) {
  print_report(text_out(outputs), report, write_outputs(report, outputs));
}

/// How an analysis subcommand reads its log: LOG, a file read at once, its results written once
/// (`dynpos identify step LOG`); or a live stream, the analysis re-run as it arrives
/// (`dynpos live identify step --udp HOST:PORT`, cmd_live.cpp).
enum class LogMode { kFile, kLive };

/// Adds `vessel` to the `hybrid` subcommand.
void add_hybrid_vessel(CLI::App& hybrid);

// Subcommands under `identify` and `leverarm` (and, in live mode, under `live identify` and
// `live leverarm`), one file each.
void add_identify_step(CLI::App& identify, LogMode mode);  // cmd_identify.cpp
void add_identify_agility(CLI::App& identify);             // cmd_identify_agility.cpp
void add_identify_thrust_map(CLI::App& identify);          // cmd_identify_thrust_map.cpp
void add_identify_four_corner(CLI::App& identify);         // cmd_identify_four_corner.cpp
void add_identify_station_keeping(
    CLI::App& identify,
    LogMode mode = LogMode::kFile);                    // cmd_identify_station_keeping.cpp
void add_identify_failure_test(CLI::App& identify);    // cmd_identify_failure_test.cpp
void add_identify_vessel_command(CLI::App& identify);  // cmd_identify_vessel.cpp
void add_leverarm_gnss(CLI::App& leverarm, LogMode mode = LogMode::kFile);  // cmd_leverarm_gnss.cpp
void add_leverarm_mru(CLI::App& leverarm);                                  // cmd_leverarm_mru.cpp

void register_simulate(CLI::App& app);
void register_compare_trial(CLI::App& app);  // cmd_identify_vessel.cpp
void register_identify(CLI::App& app);
void register_leverarm(CLI::App& app);
void register_hybrid(CLI::App& app);
void register_compare(CLI::App& app);
void register_demo(CLI::App& app);
void register_capability(CLI::App& app);   // cmd_capability.cpp
void register_montecarlo(CLI::App& app);   // cmd_montecarlo.cpp
void register_estimate(CLI::App& app);     // cmd_estimate.cpp
void register_consequence(CLI::App& app);  // cmd_consequence.cpp
void register_live(CLI::App& app);         // cmd_live.cpp
/// Called by the signal thread (main.cpp) for Ctrl-C, SIGTERM or SIGHUP: true when a live
/// session is running and takes the signal as a request to end with its final result (the
/// first signal only; another then ends the process as usual).
bool live_session_takes_signal() noexcept;  // cmd_live.cpp

}  // namespace dynpos::cli
