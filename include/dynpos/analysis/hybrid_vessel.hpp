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

#include "dynpos/analysis/outputs.hpp"
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

/// A load case by its place in kHybridVesselLoadCases.
enum class HybridLoad {
  kIce,      ///< "ice": an ice load sets in
  kMooring,  ///< "mooring": a mooring line snaps
};

/// The load case's entry of kHybridVesselLoadCases.
const LoadCase& load_case(HybridLoad load);

/// "ice" or "mooring".
std::string to_string(HybridLoad load);

/// The load case named `name`; option_error("scenario") for another name, the hint saying what
/// each is (from its scenario file).
HybridLoad hybrid_load_from_string(const std::string& name);

/// What happens in a load case, from its scenario's first load: "a 20 kN ice load sets in", or
/// for a load on from the start "a mooring line holding 20 kN snaps"; without a load, just what
/// the load is.
std::string load_case_phrase(const LoadCase& load_case, const scenario::ScenarioSpec& spec);

struct HybridVesselRequest {
  HybridLoad scenario = HybridLoad::kIce;  ///< the load case
  std::uint64_t seed = 1;                  ///< master seed, the same for both designs
  double within_m = 1.0;                   ///< distance for "back within" [m], > 0

  /// Throws option_error for within_m ≤ 0.
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

/// The plots into outputs.figures (a folder, write_figures), then the JSON listing them.
Written write_outputs(const HybridVesselReport& report, const Outputs& outputs);

}  // namespace dynpos::analysis
