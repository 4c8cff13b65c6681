#pragma once
/// \file
/// The main job on the built-in virtual Gunnerus (`dynpos demo`): every built-in scenario
/// simulated into its own folder (scenario::run_campaign), each analysis run on those logs as a
/// section of the report (demo_sections.hpp), and the report written: index.html, summary.md
/// and summary.json (campaign_report.hpp). Each section builds its analysis' public request,
/// calls its runner and writes the analysis' own JSON document (the one `--json` writes).
///
/// The report folder is the output, written by the run itself as the campaign and the sections
/// go (a stopped demo keeps what is done): there is no separate write_outputs.
///
/// Request keys (option_error): "out" for out_dir.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "dynpos/scenario/campaign.hpp"

namespace dynpos::analysis {

struct DemoRequest {
  std::filesystem::path out_dir = "dynpos-demo";  ///< the report folder (created if needed)
  std::uint64_t seed = 1;  ///< master seed; the same seed gives byte-identical files
  /// The folder of the scenarios and vessels the campaign runs; absent: find_data_dir(). (The
  /// analysis sections read their vessel and load scenarios from find_data_dir().)
  std::optional<std::filesystem::path> data_dir;

  /// Throws option_error("out") if out_dir is empty.
  void validate() const;
};

struct DemoReport {
  std::filesystem::path out_dir;
  std::uint64_t seed = 1;
  std::vector<scenario::RunSummary> runs;   ///< the campaign's runs, in name order
  std::vector<std::string> section_titles;  ///< the report's analysis sections, in order
};

/// Validates; runs the campaign into out_dir, then the analysis sections in the order of
/// demo_sections.hpp (step, agility, four-corner, station keeping, failure test, GNSS and MRU
/// lever arms, hybrid vessel, capability), and writes the report.
DemoReport run_demo(const DemoRequest& request);

/// One line per scenario run, the totals and where index.html is.
std::string to_text(const DemoReport& report);

}  // namespace dynpos::analysis
