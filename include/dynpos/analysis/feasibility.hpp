#pragma once
/// \file
/// `capability --loads`: for each environmental load of a table, the largest factor λ such that
/// λ times it is held by the vessel's thruster layout, intact, with a unit or a group lost, or
/// in the worst such case (capability/feasibility.hpp).
///
/// The second mode of the capability command, an analysis of its own: feasibility.cpp (request,
/// validate, run) and feasibility_report.cpp (JSON, text, write_outputs); no demo section.

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/analysis/outputs.hpp"
#include "dynpos/capability/feasibility.hpp"

namespace dynpos::analysis {

/// The options of `capability --loads`; each field's name is its request key.
struct FeasibilityRequest {
  std::filesystem::path vessel;  ///< vessel file; empty: the data folder's gunnerus.toml
  std::filesystem::path loads;   ///< the load table (capability/load_table.hpp)
  /// "none" (intact), "worst" (every unit and group lost, the smallest per row), a unit's
  /// name or "group:NAME".
  std::string failure = "worst";
  /// Throws option_error naming the first bad option.
  void validate() const;
};

struct FeasibilityReport {
  std::string vessel;         ///< the vessel's name
  std::string vessel_source;  ///< its file as given, empty for the built-in one
  /// Where the units come from: "[[thruster]]" of the vessel file, or "model" (the vessel
  /// model's propellers with rudders and tunnel).
  std::string layout;
  std::vector<std::string> units;  ///< the units' names
  std::string failure;             ///< as asked
  std::vector<capability::FeasibilityPoint> points;
};

/// Throws option_error("loads") when an option of the capability roses was given with the load
/// table (`given(name)`: the option --name was given, e.g. "direction-step"), naming it.
void check_loads_options(const std::function<bool(std::string_view)>& given);

/// Validates, reads the vessel and the table, and computes each row's factor.
FeasibilityReport run_feasibility(const FeasibilityRequest& request);

/// {analysis: "capability-loads", vessel, vessel_file?, layout, units, failure, points:
/// [{direction_deg, load_factor, capped, limiting: [...], failure}]}.
nlohmann::json to_json(const FeasibilityReport& report);

/// One row per load: direction, factor, the case and the limiting units.
std::string to_text(const FeasibilityReport& report);

/// The JSON (outputs.json); the load factors draw no figure.
Written write_outputs(const FeasibilityReport& report, const Outputs& outputs);

}  // namespace dynpos::analysis
