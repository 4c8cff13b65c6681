#pragma once
/// \file
/// Time-domain DP capability (DNV-ST-0111 Level 3 style): the virtual vessel under its DP
/// controller in the simulator, with gusting wind, irregular waves and current from each
/// direction, each direction searched along the environment table (rows stepped up, then
/// bisected) until the vessel leaves its footprint.
///
/// A run holds position at heading 0 with the weather from the direction searched; the first
/// settle_s let the integral action take up the mean load (the vessel starts at rest in the
/// full weather) and are not judged. The vessel holds when, over the rest of the run, its
/// position stays within footprint_m of the setpoint and its heading within footprint_deg.
/// Directions run in parallel; each run is seeded from the master seed alone, so the result
/// does not depend on the number of jobs.

#include <cstdint>
#include <string>
#include <vector>

#include "dynpos/capability/environment_table.hpp"
#include "dynpos/capability/quasi_static.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::capability {

/// Options of a time-domain rose.
struct TimeDomainOptions {
  EnvironmentTable environment = dnv_level1_table();  ///< wind → waves and current
  double direction_step_deg = 10.0;                   ///< 0, step, …, < 360 [deg]
  double duration_s = 1200.0;                         ///< judged part of each run [s], > 0
  double settle_s = 300.0;                            ///< unjudged start of each run [s], ≥ 0
  double footprint_m = 5.0;                           ///< largest position excursion held [m], > 0
  double footprint_deg = 3.0;                         ///< largest heading excursion held [deg], > 0
  double wind_tolerance_mps = 0.25;  ///< bisection ends within this [m/s], 1e-6 … 10
  std::uint64_t seed = 1;            ///< master seed of every run
  unsigned jobs = 0;                 ///< parallel runs; 0 = every core
  /// Throws core::InputError naming the first bad option (request keys: duration, settle,
  /// footprint, footprint_deg, wind_tolerance, direction_step).
  void validate() const;
};

/// How one run went.
struct RunVerdict {
  bool holds = false;
  double max_excursion_m = 0.0;  ///< largest distance from the setpoint after settling [m]
  double max_heading_deg = 0.0;  ///< largest |heading error| after settling [deg]
  std::string axis;              ///< "position", "heading" or "" when it holds
};

/// One run at `environment` from from_rel_deg off the bow, with `failed` actuators lost.
RunVerdict time_domain_run(const scenario::VesselConfig& vessel,
                           const std::vector<std::string>& failed, const Environment& environment,
                           double from_rel_deg, const TimeDomainOptions& options);

/// The rose: per direction the DP number, the strongest wind held (bisected) and the axis that
/// is lost first ("position" or "heading"; "none" beyond the table or the simulator's range of
/// waves). The search for the number starts at the row the quasi-static balance of the same
/// load (level 2, no reserve) holds and steps up or down from there, taking a row that holds to
/// hold every row below it (the standard steps up from the calm; a run costs about a second).
std::vector<CapabilityPoint> time_domain_rose(const scenario::VesselConfig& vessel,
                                              const std::vector<std::string>& failed,
                                              const TimeDomainOptions& options);

}  // namespace dynpos::capability
