#pragma once
/// \file
/// The environments of a capability analysis: DNV-ST-0111's Level 1 table (DP capability
/// numbers 0–11 on the Beaufort scale) and a site's own table, each a relation wind speed →
/// significant wave height, peak period and current that the analysis follows continuously
/// (linear between rows) when it searches for the strongest wind the vessel holds.

#include <string>
#include <vector>

namespace dynpos::capability {

/// One environment: wind, waves and current, co-linear (from the same direction).
struct Environment {
  double wind_mps = 0.0;     ///< mean wind speed 10 m above the sea [m/s]
  double hs_m = 0.0;         ///< significant wave height [m]
  double tp_s = 0.0;         ///< spectral peak period [s]; 0 without waves
  double current_mps = 0.0;  ///< current speed [m/s]
};

/// Rows of increasing wind speed; the first is the calm (all zero) unless a site says otherwise.
struct EnvironmentTable {
  std::string name;               ///< "DNV-ST-0111 Level 1" or the site file
  std::vector<Environment> rows;  ///< wind strictly increasing
  /// The environment at wind speed w [m/s]: linear between the rows around w, the last row's
  /// waves and current beyond it (and the first's below it).
  Environment at(double wind_mps) const;
  /// Throws core::InputError (naming `name`) unless there are ≥ 2 rows, each finite and ≥ 0,
  /// with the wind strictly increasing.
  void validate() const;
};

/// DNV-ST-0111 (Assessment of station keeping capability of DP vessels, Dec 2021), Table 2-1:
/// DP capability number n = 0…11 (row n) with its wind speed, H_s, T_p and current
/// (0.25 m/s at 1, 0.5 at 2, 0.75 m/s from 3 on).
const EnvironmentTable& dnv_level1_table();

/// The DP capability number of wind speed w [m/s] in the DNV table: the largest n whose wind is
/// ≤ w (0 below the table's first step, 11 at or above its last).
int dp_number_for_wind(double wind_mps);

/// DNV-ST-0111's reserve for dynamics at Levels 1 and 2: the environmental forces are
/// multiplied by this factor before they are balanced against the thrust.
inline constexpr double kDynamicAllowance = 1.25;

/// A site table from a TOML file: [[environment]] rows with wind_mps, hs_m, tp_s and
/// current_mps. Throws core::InputError naming the file, line and key for bad input.
EnvironmentTable read_site_table(const std::string& path);

}  // namespace dynpos::capability
