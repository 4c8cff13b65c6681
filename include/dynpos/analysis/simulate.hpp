#pragma once
/// \file
/// A virtual sea trial (`dynpos simulate`): one scenario, or the whole campaign, run on the
/// virtual R/V Gunnerus and written into a run folder — log.csv, truth.csv, truth.json and the
/// NMEA files (scenario/campaign.hpp); the campaign adds one folder per scenario and its report.
///
/// The run folder is the analysis' output, written by the run itself as it goes (a campaign's
/// logs do not fit in memory): there is no separate write_outputs, no JSON and no figure.
///
/// Request keys (option_error): the field name without its unit suffix or _dir/_file ("out" for
/// out_dir, "vessel" for vessel_file, "duration" for duration_s, "log_rate" for log_rate_hz).

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "dynpos/core/parallel_for.hpp"
#include "dynpos/scenario/campaign.hpp"

namespace dynpos::analysis {

/// The scenario name that runs every built-in scenario.
inline constexpr const char* kCampaign = "campaign";

struct SimulateRequest {
  /// A name in the data folder's scenarios/ (e.g. "surge-steps-forward"), a .toml file, or
  /// kCampaign for all of them.
  std::string scenario;
  std::filesystem::path out_dir;      ///< the run folder (created if needed); writing it is the
                                      ///< analysis
  std::uint64_t seed = 1;             ///< master seed; the same seed gives byte-identical files
  std::filesystem::path vessel_file;  ///< empty: the data folder's vessels/gunnerus.toml
  std::optional<double> duration_s;   ///< run length override [s], > 0
  std::optional<double> log_rate_hz;  ///< log rate override [Hz], > 0
  /// The DP observer override: "ideal", "passive", "ekf" or "raw" (DP scenarios).
  std::optional<std::string> observer;
  bool list = false;                 ///< only list the built-in scenarios
  unsigned jobs = core::kEveryCore;  ///< campaign: scenarios run at once, 0 = every core

  /// Throws option_error for a duration or log rate that is not > 0 ("duration", "log_rate"),
  /// an unknown observer ("observer"),
  /// and InputError when no scenario or (unless list) no output folder is given.
  void validate() const;
};

/// A built-in scenario: its file's name and its description.
struct ScenarioListing {
  std::string name;
  std::string description;
};

/// What one scenario run wrote.
struct SimulatedRun {
  std::string scenario;  ///< the scenario's name
  double duration_s = 0.0;
  std::uint64_t seed = 1;
  std::size_t rows = 0;      ///< rows of log.csv
  std::size_t channels = 0;  ///< channels of log.csv
};

struct SimulateReport {
  std::filesystem::path out_dir;
  /// The built-in scenarios (list), one run, or the summaries of the campaign's runs in order.
  std::variant<std::vector<ScenarioListing>, SimulatedRun, std::vector<scenario::RunSummary>>
      result;
};

/// Validates; lists the scenarios, or runs the scenario (or each scenario of the campaign, with
/// the overrides) and writes OUT/log.csv, truth.csv, truth.json and gnssK.nmea (the campaign:
/// OUT/<scenario>/ each, then OUT/summary.json, summary.md and index.html).
SimulateReport run_simulate(const SimulateRequest& request);

/// Refuses, before anything is allocated, simulated runs whose memory (the `concurrent` largest
/// held at once: a run holds two blocks of scenario::kRunBlockRows rows while it writes its
/// files) or files (all of them) exceed what the machine has: option_error "duration/log_rate"
/// naming the memory needed and available, "out" the disk space needed and free on out_dir's
/// file system. Estimates: 1 kB a held row, 1.5 kB a row and 4 kB a second of files.
void check_simulation_resources(const std::vector<scenario::ScenarioSpec>& specs,
                                std::size_t concurrent, const std::filesystem::path& out_dir);

/// What `dynpos simulate` prints: the list, the run and the files written, or one line per
/// campaign run with where the report is.
std::string to_text(const SimulateReport& report);

}  // namespace dynpos::analysis
