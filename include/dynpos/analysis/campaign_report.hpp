#pragma once
/// \file
/// The report of a campaign (`dynpos simulate campaign`, `dynpos demo`): a table of the
/// scenarios run, then the analysis sections, as summary.md and index.html, and the same figures
/// as summary.json.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/analysis/report_section.hpp"
#include "dynpos/scenario/campaign.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::analysis {

/// {vessel, master_seed, scenarios: [{name, description, duration_s, rows, seed, max_speed_mps,
/// max_yaw_rate_dps, distance_m, energy_kJ, log, truth_log, truth}]}, paths relative to the
/// campaign folder. The wall-clock times are not in it, so it is the same for the same seed.
nlohmann::json campaign_json(const std::vector<scenario::RunSummary>& runs,
                             const scenario::VesselConfig& vessel, std::uint64_t master_seed);

/// (Re)writes DIR/summary.json, DIR/summary.md and DIR/index.html: the campaign table, then
/// the sections with a title (in order), each file atomically.
void write_campaign_report(const std::vector<scenario::RunSummary>& runs,
                           const scenario::VesselConfig& vessel, std::uint64_t master_seed,
                           const std::filesystem::path& out_dir,
                           const std::vector<ReportSection>& sections);

/// One line per run (simulated and wall-clock time, top speed, energy), the totals and where
/// the report is (DIR/index.html).
std::string campaign_text(const std::vector<scenario::RunSummary>& runs,
                          const std::filesystem::path& out_dir);

}  // namespace dynpos::analysis
