#pragma once
/// \file
/// `dynpos capability --level 3 --transient`: the failure as it happens (capability/transient.hpp)
/// per direction and weather row, with the request's options, as a table, JSON and a footprint
/// plot (the largest excursion after the failure per direction, one curve per row).

#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "dynpos/analysis/capability.hpp"
#include "dynpos/analysis/outputs.hpp"
#include "dynpos/capability/transient.hpp"

namespace dynpos::analysis {

/// The footprint and what it was computed with.
struct TransientReport {
  std::string vessel;         ///< the vessel's name
  std::string vessel_source;  ///< its file
  std::string environment;    ///< the environment table's name
  std::string failure;        ///< the failure tripped
  capability::TransientOptions options;
  std::vector<capability::TransientPoint> points;  ///< per direction, then per row
};

/// The transient options of `request` (level 3, transient, a named failure): rows, after,
/// seeds, observer and the level-3 options it shares (settle, footprints, direction step, seed,
/// jobs). Throws option_error naming the first bad option.
capability::TransientOptions transient_options(const CapabilityRequest& request);

/// Refuses an option given (`given(name)`, the name as the command line spells it without its
/// dashes, e.g. "wind-tolerance") that does not go with `request.transient`: the transient's own
/// options (rows, after, seeds, observer) without it, the wind search's (duration,
/// wind-tolerance) with it. Throws option_error naming the option.
void check_transient_options(const CapabilityRequest& request,
                             const std::function<bool(std::string_view)>& given);

/// Validates, loads the vessel and runs the footprint.
TransientReport run_capability_transient(const CapabilityRequest& request);

/// {analysis: "capability-transient", vessel, vessel_file?, environment, failure, options: {...},
/// points: [{direction_deg, dp_number, wind_mps, failure, peak_excursion_m, time_to_peak_s,
/// peak_heading_deg, holds, runs: [{seed, peak_excursion_m, time_to_peak_s, peak_heading_deg,
/// recovery_s, load_b, estimated_load_b}]}]}.
nlohmann::json to_json(const TransientReport& report);

/// One row per direction: per weather row the largest excursion, its time and the heading.
std::string to_text(const TransientReport& report);

/// The footprint plot: per direction the largest excursion, one curve per row, the position
/// footprint as a ring, into `svg`.
void write_footprint(const TransientReport& report, const std::filesystem::path& svg);

/// footprint.svg into outputs.figures (created when needed), then the JSON.
Written write_outputs(const TransientReport& report, const Outputs& outputs);

}  // namespace dynpos::analysis
