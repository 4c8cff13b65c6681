#pragma once
/// \file
/// Hybrid against conventional integral action on the virtual Gunnerus under a sudden load
/// (`dynpos hybrid vessel`): a built-in load scenario run twice with the same seed, once with
/// the DP controller's continuous integral action (5.35)–(5.38) and once with jumps of the bias
/// estimate by the practical rule (5.64)–(5.67), both evaluated after the load changes.
///
/// Request keys (option_error): the field name without its unit suffix ("within" for
/// within_m).

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/hybrid/integral_jump.hpp"
#include "dynpos/scenario/load_response.hpp"

namespace dynpos::analysis {

/// A built-in sudden-load case: its short name and its scenario file's name.
struct LoadCase {
  const char* name;           ///< "ice" or "mooring"
  const char* scenario_file;  ///< stem in data/scenarios, e.g. "dp-ice-load"
  const char* load;           ///< what the load is, e.g. "ice load"
};

/// The load cases, ice first.
inline constexpr std::array<LoadCase, 2> kHybridVesselLoadCases = {{
    {"ice", "dp-ice-load", "ice load"},
    {"mooring", "dp-mooring-snap", "mooring line"},
}};

/// What happens in a load case, from its scenario's first load: "a 20 kN ice load sets in", or
/// for a load on from the start "a mooring line holding 20 kN snaps"; without a load, just what
/// the load is.
std::string load_case_phrase(const LoadCase& load_case, const scenario::ScenarioSpec& spec);

struct HybridVesselRequest {
  std::string scenario;    ///< a load case: "ice" or "mooring"
  std::uint64_t seed = 1;  ///< master seed, the same for both designs
  double within_m = 1.0;   ///< distance for "back within" [m], > 0

  /// Throws option_error for an unknown load case ("scenario", the hint saying what each is,
  /// from its scenario file) or within_m ≤ 0.
  void validate() const;
};

/// Both designs' runs and responses.
struct HybridVesselReport {
  std::string name;           ///< "ice" or "mooring"
  std::string scenario_name;  ///< the scenario's name, e.g. "dp-ice-load"
  std::uint64_t seed = 1;
  scenario::HybridComparison comparison;
  hybrid::IntegralJumpParams jump_params;  ///< the hybrid design's jump rule
};

/// The scenario file's stem of a load case ("ice" → "dp-ice-load"); option_error("scenario")
/// for an unknown one.
std::string hybrid_vessel_scenario_file(const std::string& short_name);

/// Validates, then runs both designs (data from find_data_dir(): the load scenario and the
/// Gunnerus vessel file).
HybridVesselReport run_hybrid_vessel(const HybridVesselRequest& request);

/// {case, scenario, scenario_file, seed, load_time_s, within_m, evaluated_s,
/// hybrid_parameters, conventional, hybrid}; per design {peak_offset_m, back_within_s, iae_m_s,
/// energy_kJ, jumps}.
nlohmann::json to_json(const HybridVesselReport& report);

/// to_json(report) with "plots": the paths of the written figures (the `--json` document).
nlohmann::json to_json(const HybridVesselReport& report,
                       const std::vector<std::filesystem::path>& plots);

/// "<scenario> (seed N), load change at T s:" and the side-by-side table of the figures after
/// the load, as aligned text.
std::string to_text(const HybridVesselReport& report);

/// The side-by-side table as Markdown.
std::string to_markdown(const HybridVesselReport& report);

/// The side-by-side table as an HTML fragment.
std::string to_html(const HybridVesselReport& report);

/// Writes hybrid_vessel_<name>_{position,integral,power}.svg into `dir` (created if needed);
/// returns the paths.
std::vector<std::filesystem::path> write_figures(const HybridVesselReport& report,
                                                 const std::filesystem::path& dir);

}  // namespace dynpos::analysis
