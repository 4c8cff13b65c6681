#pragma once
/// \file
/// The analysis sections of the `dynpos demo` report, one per analysis. Each runs its analysis
/// on the logs of the campaign written into `campaign_dir` (DIR/<scenario>/log.csv and
/// truth.json), writes its figures and JSON under campaign_dir/analysis/ (hybrid: DIR/hybrid/),
/// and returns the section, links relative to campaign_dir. An empty title means the analysis
/// has nothing to add (its scenario is not in the campaign).

#include <cstdint>
#include <filesystem>

#include "dynpos/analysis/report_section.hpp"

namespace dynpos::analysis {

ReportSection step_demo_section(const std::filesystem::path& campaign_dir);
ReportSection agility_demo_section(const std::filesystem::path& campaign_dir);
ReportSection four_corner_demo_section(const std::filesystem::path& campaign_dir);
ReportSection station_keeping_demo_section(const std::filesystem::path& campaign_dir);
/// The failure tests of the DP trials (dp-thruster-trip, dp-bus-failure): the events found in
/// the logger's files beside truth.json's `failure` (analysis/failure-test/<scenario>.json).
ReportSection failure_test_demo_section(const std::filesystem::path& campaign_dir);
ReportSection leverarm_gnss_demo_section(const std::filesystem::path& campaign_dir);
ReportSection leverarm_mru_demo_section(const std::filesystem::path& campaign_dir);
/// Hybrid against conventional integral action on the virtual vessel under both sudden loads,
/// with the campaign's master seed.
ReportSection hybrid_vessel_demo_section(const std::filesystem::path& campaign_dir,
                                         std::uint64_t seed);

/// DP capability of the virtual vessel: level 1 with every single failure, level 3 (time
/// domain, seeded by the campaign's master seed) intact and for the failures worst at level 1.
ReportSection capability_demo_section(const std::filesystem::path& campaign_dir,
                                      std::uint64_t seed);

}  // namespace dynpos::analysis
