#pragma once
// The units of a [[thruster]] layout in identify vessel (private to the module): each unit's
// command dead time and shaft time constant from the steps of its shaft speed order, an
// azimuth's slew rate from the rate-limited stretches of its turns (docs/theory.md, "The
// units"). Their keys are "thruster.NAME.KEY", NAME the unit's name.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dynpos/analysis/vessel_id.hpp"
#include "dynpos/scenario/vessel_config.hpp"
#include "vessel_units.hpp"

namespace dynpos::analysis::vessel_units {

/// "thruster.NAME.KEY".
std::string layout_key(const std::string& unit, const std::string& key);

/// (NAME, KEY) of "thruster.NAME.KEY" (NAME may hold dots, KEY does not); nullopt for another
/// key.
std::optional<std::pair<std::string, std::string>> layout_key_parts(const std::string& key);

/// Appends each layout unit's values (dead_time_s, time_constant_s; an azimuth's
/// rate_deg_per_s) and what the logs show of its dynamics to `out`, in layout order; the units
/// on `jobs` threads (0: every core).
void layout_units(const scenario::VesselConfig& start, const std::vector<LogUnits>& logs,
                  double max_rel_sigma, unsigned jobs, UnitResult& out);

/// Sets `p` in `config` when it is a layout unit's value; false for another key.
bool apply_layout(scenario::VesselConfig& config, const VesselParameter& p);

}  // namespace dynpos::analysis::vessel_units
