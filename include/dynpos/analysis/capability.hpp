#pragma once
/// \file
/// `capability`: DP capability after DNV-ST-0111 on the vessel model — for each direction of the
/// weather the strongest environment held, intact and after single failures (the worst case
/// per direction), at Level 1 (the standard's table, rated thrust), Level 2 (the model's thrust
/// losses, a site's environment) or Level 3 (time-domain runs of the DP-controlled vessel).

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/analysis/outputs.hpp"
#include "dynpos/capability/environment_table.hpp"
#include "dynpos/capability/quasi_static.hpp"
#include "dynpos/capability/time_domain.hpp"
#include "dynpos/core/parallel_for.hpp"

namespace dynpos::analysis {

/// The options of `capability`; each field's name is its request key.
struct CapabilityRequest {
  int level = 1;                 ///< 1, 2 or 3 (level)
  std::filesystem::path vessel;  ///< vessel file; empty: the data folder's gunnerus.toml
  /// "none" (intact only), "worst" (intact and every single failure, the worst per direction)
  /// or one failure: an actuator of the model (capability::actuator_names()), or a unit or
  /// "group:NAME" of a [[thruster]] layout (capability::single_failures(vessel)).
  std::string failure = "worst";
  /// With failure "worst": the single failures it is the worst of (computed in this order);
  /// empty: every one (capability::single_failures(vessel)). The demo takes level 3's worst case
  /// over the failures worst somewhere at level 1.
  std::vector<std::string> worst_of;
  std::filesystem::path site;            ///< level 2: a site table (TOML [[environment]] rows)
  std::optional<double> hs;              ///< level 2: fixed H_s [m] instead of the table's
  std::optional<double> tp;              ///< level 2: fixed T_p [s]
  std::optional<double> current;         ///< level 2: fixed current [m/s]
  double direction_step = 10.0;          ///< [deg], dividing 360
  double duration = 1200.0;              ///< level 3: judged run length [s]
  double settle = 300.0;                 ///< level 3: unjudged start of a run [s]
  double footprint = 5.0;                ///< level 3: position footprint [m]
  double footprint_deg = 3.0;            ///< level 3: heading footprint [deg]
  std::optional<double> wind_tolerance;  ///< [m/s]; default 0.01 (levels 1, 2), 0.25 (level 3)
  std::uint64_t seed = 1;                ///< level 3: master seed of the runs
  unsigned jobs = core::kEveryCore;      ///< level 3: parallel runs, 0 = every core
  /// Level 3: the failure as it happens instead of a rose (analysis/capability_transient.hpp).
  bool transient = false;
  std::vector<int> rows{3, 4, 5};  ///< transient: the weather rows (DP numbers) run
  double after = 300.0;            ///< transient: run after the failure [s]
  unsigned seeds = 1;              ///< transient: runs per direction and row
  std::string observer = "ideal";  ///< transient: what the DP loop runs on
  /// Throws option_error naming the first bad option.
  void validate() const;
};

/// A rose of one case.
struct CapabilityCase {
  std::string failure;  ///< "none" (intact), an actuator, or "worst"
  std::vector<capability::CapabilityPoint> points;
};

/// The result and what it was computed with.
struct CapabilityReport {
  int level = 1;
  std::string vessel;         ///< the vessel's name
  std::string vessel_source;  ///< its file
  /// "model" (the model's propellers, rudders and tunnel) or "[[thruster]]" (the file's layout;
  /// levels 1 and 2 only).
  std::string layout = "model";
  std::string environment;         ///< the environment table's name
  std::string failure;             ///< as asked
  double dynamic_allowance = 1.0;  ///< factor on the load (levels 1 and 2), 1 at level 3
  CapabilityCase intact;
  std::vector<CapabilityCase> failures;  ///< each case computed (one, or every single one)
  std::optional<CapabilityCase> worst;   ///< per direction the smallest over `failures`
  std::optional<capability::TimeDomainOptions> time_domain;  ///< level 3's runs and footprint
  /// The points the JSON's "points" holds: the failure case asked (worst, or the one named),
  /// else the intact rose.
  const CapabilityCase& headline() const;
};

/// Validates, loads the vessel and environment, and computes the roses.
CapabilityReport run_capability(const CapabilityRequest& request);

/// DNV's notation numbers (A, B, C, D): the lowest number within ±30° of the bow and over all
/// directions, intact (A, B) and for the failure case (C, D: the worst case, or the one failure
/// asked; absent without failures).
std::array<std::optional<int>, 4> capability_notation(const CapabilityReport& report);

/// {analysis: "capability", level, vessel, vessel_file?, layout, thrust_losses, environment,
/// failure, dynamic_allowance, notation: [A, B, C, D], points: [{direction_deg, dp_number,
/// max_wind_mps, limiting, failure, beyond_table}], intact: [...], cases: {name: [...]},
/// time_domain?: {...}}.
nlohmann::json to_json(const CapabilityReport& report);

/// Whether the thrusters' losses are modelled: levels 2 and 3 of the model's units (the
/// propellers', tunnel's and rudders' thrust at the current's inflow, or the simulator's
/// thrusters). Level 1 is rated thrust at rest; a [[thruster]] layout keeps its ratings.
bool thrust_losses(const CapabilityReport& report);

/// "DP capability-L1(A,B,C,D)", NA for a number not computed.
std::string notation_text(const CapabilityReport& report);

/// One row per direction: intact and the failure case, DP number and wind.
std::string to_text(const CapabilityReport& report);

/// The capability rose (two polar panels, DP number and limiting wind, intact and failure
/// overlaid) as SVG into `svg`.
void write_rose(const CapabilityReport& report, const std::filesystem::path& svg);

/// The rose as outputs.figures/rose.svg (a folder, created when needed), then the JSON.
Written write_outputs(const CapabilityReport& report, const Outputs& outputs);

}  // namespace dynpos::analysis
