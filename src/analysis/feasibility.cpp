#include "dynpos/analysis/feasibility.hpp"

#include <fmt/core.h>

#include <optional>

#include "dynpos/analysis/data_dir.hpp"
#include "dynpos/analysis/options.hpp"
#include "dynpos/capability/load_table.hpp"
#include "dynpos/capability/vessel_units.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::analysis {

void check_loads_options(const std::function<bool(std::string_view)>& given) {
  for (const char* option :
       {"level", "site", "hs", "tp", "current", "direction-step", "wind-tolerance", "duration",
        "settle", "footprint", "footprint-deg", "seed", "jobs", "out", "transient", "rows", "after",
        "seeds", "observer"}) {
    if (given(option)) {
      throw option_error("loads",
                         fmt::format("--{} is not an option of the load table's factors", option),
                         "with --loads give --vessel, --failure and --json only");
    }
  }
}

void FeasibilityRequest::validate() const {
  if (loads.empty()) throw option_error("loads", "no load table", "give --loads FILE.csv");
  if (failure.empty()) {
    throw option_error("failure", "an empty failure case",
                       "none, worst, a unit's name or group:NAME");
  }
  if (!vessel.empty() && !std::filesystem::is_regular_file(vessel)) {
    throw option_error("vessel", "'" + vessel.string() + "' is not a file",
                       "give a vessel TOML file (docs/vessel-file.md)");
  }
}

FeasibilityReport run_feasibility(const FeasibilityRequest& q) {
  q.validate();
  const scenario::VesselConfig vessel =
      scenario::load_vessel_config(vessel_file_or_default(q.vessel));
  FeasibilityReport r;
  r.vessel = vessel.name;
  r.vessel_source = q.vessel.empty() ? "" : q.vessel.string();
  r.failure = q.failure;
  std::vector<model::ThrusterUnit> units = vessel.thrusters;
  r.layout = "[[thruster]]";
  if (units.empty()) {
    r.layout = "model";
    units = capability::gunnerus_units(
        model::ThrustAllocator(model::Thruster(vessel.propeller), model::Rudder(vessel.rudder),
                               model::TunnelThruster(vessel.tunnel),
                               model::ThrustConfiguration(vessel.layout), vessel.allocation));
  }
  for (const model::ThrusterUnit& u : units) r.units.push_back(u.name);
  const model::LayoutAllocator allocator(units);
  // The case is checked before the table is read: a misspelt unit costs no reading.
  const std::optional<capability::FailureCase> c =
      q.failure == "worst" ? std::nullopt
                           : std::optional(capability::failure_case(units, q.failure));
  const std::vector<capability::LoadCase> loads = capability::read_load_table(q.loads.string());
  if (!c) {
    r.points = capability::worst_feasibility(allocator, loads);
  } else {
    for (const capability::LoadCase& load : loads) {
      r.points.push_back(capability::feasibility(allocator, load, *c));
    }
  }
  return r;
}

}  // namespace dynpos::analysis
