#pragma once
// The units of `identify vessel` (private to the module): each unit's thrust map and the dynamics
// of its order → shaft speed from the existing analyses (ident::fit_thrust_map, the step
// detector and ident::fit_fopdt) on every log, combined over the logs into the vessel file's
// values (docs/theory.md, "Vessel identification", "The units").

#include <optional>
#include <string>
#include <vector>

#include "dynpos/analysis/vessel_id.hpp"
#include "dynpos/core/log.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::analysis::vessel_units {

/// One unit's logged columns on its log's time axis, SI (NaN = missing); a column the log does
/// not hold is empty.
struct UnitColumns {
  std::string unit;                       ///< "port", "stb", "tunnel" or a layout unit's name
  std::vector<double> shaft_speed_rps;    ///< rpm.NAME: the shaft speed feedback
  std::vector<double> order_rps;          ///< command.rpm.NAME: the shaft speed order
  std::vector<double> thrust_N;           ///< thrust.NAME: the DP system's thrust feedback
  std::vector<double> azimuth_rad;        ///< azimuth.NAME: an azimuth's direction feedback
  std::vector<double> azimuth_order_rad;  ///< command.azimuth.NAME: its direction order
};

/// The unit columns of one log.
struct LogUnits {
  std::string name;  ///< the log as given
  std::vector<double> time_s;
  std::vector<UnitColumns> units;
};

/// The columns of `units` (rpm.NAME, command.rpm.NAME, thrust.NAME, azimuth.NAME,
/// command.azimuth.NAME) that `log` holds.
LogUnits log_units(const std::string& name, const core::Log& log,
                   const std::vector<std::string>& units);

/// One estimate of a value with its 1σ (> 0) and where it came from (the log).
struct Estimate {
  double value = 0.0;
  double sigma = 0.0;
  std::string source;
};

/// Estimates combined: the inverse-variance weighted mean, σ = (Σ 1/σᵢ²)^(−1/2) widened by the
/// Birge ratio √(χ²/(n − 1)) when the estimates scatter more than their σ allow (χ² of their
/// deviations from the mean), so that σ is never smaller than the scatter shows.
struct Combined {
  double value = 0.0;
  double sigma = 0.0;
  std::size_t count = 0;
  std::vector<std::string> sources;  ///< the distinct sources, in order of first appearance
};

/// nullopt without an estimate of finite, positive σ (those are left out).
std::optional<Combined> combine(const std::vector<Estimate>& estimates);

struct UnitResult {
  /// Each value of the model's units (the [propeller] and [tunnel] keys) or of a layout's
  /// (thruster.NAME.KEY), determined or not.
  std::vector<VesselParameter> parameters;
  std::vector<UnitIdentification> units;
};

/// The values of the vessel's units — the model's own (port, stb, tunnel) or its [[thruster]]
/// layout's — that `logs` determine (σ/|value| ≤ max_rel_sigma), the others kept from `start`
/// with the excitation that would determine them. A layout's units run on `jobs` threads (0:
/// every core); the result does not depend on it.
UnitResult identify_units(const scenario::VesselConfig& start, const std::vector<LogUnits>& logs,
                          double max_rel_sigma, unsigned jobs = 1);

/// Sets each determined value of `parameters` in `config` (keys "table.key", and
/// "thruster.NAME.key" for a layout's unit).
void apply(scenario::VesselConfig& config, const std::vector<VesselParameter>& parameters);

}  // namespace dynpos::analysis::vessel_units
