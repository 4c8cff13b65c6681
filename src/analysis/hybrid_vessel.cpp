#include "dynpos/analysis/hybrid_vessel.hpp"

#include <fmt/core.h>

#include <cmath>

#include "dynpos/analysis/data_dir.hpp"
#include "dynpos/analysis/options.hpp"

namespace dynpos::analysis {
namespace {

std::filesystem::path scenario_path(const std::filesystem::path& data, const LoadCase& c) {
  return data / "scenarios" / (std::string(c.scenario_file) + ".toml");
}

// "choose ice (a 20 kN ice load sets in) or mooring (...)", from the scenario files.
std::string load_case_hint() {
  const std::filesystem::path data = find_data_dir();
  std::string hint = "choose ";
  for (const LoadCase& c : kHybridVesselLoadCases) {
    if (hint.size() > 7) hint += " or ";
    hint += fmt::format("{} ({})", c.name,
                        load_case_phrase(c, scenario::load_scenario(scenario_path(data, c))));
  }
  return hint;
}

}  // namespace

const LoadCase& load_case(HybridLoad load) {
  return kHybridVesselLoadCases[static_cast<std::size_t>(load)];
}

std::string to_string(HybridLoad load) { return load_case(load).name; }

HybridLoad hybrid_load_from_string(const std::string& name) {
  for (const HybridLoad load : {HybridLoad::kIce, HybridLoad::kMooring}) {
    if (name == to_string(load)) return load;
  }
  throw option_error("scenario", "unknown load scenario '" + name + "'", load_case_hint());
}

std::string load_case_phrase(const LoadCase& load_case, const scenario::ScenarioSpec& spec) {
  if (spec.loads.empty()) return load_case.load;
  const scenario::LoadEvent& e = spec.loads.front();
  const double force_kN = std::hypot(e.north_N, e.east_N) / 1e3;
  // The same event scenario::first_load_change_s() evaluates the designs after.
  if (e.t_on_s > 0.0) return fmt::format("a {:g} kN {} sets in", force_kN, load_case.load);
  return fmt::format("a {} holding {:g} kN snaps", load_case.load, force_kN);
}

void HybridVesselRequest::validate() const {
  if (!(within_m > 0.0) || !std::isfinite(within_m)) {
    throw option_error("within",
                       fmt::format("the 'back within' distance must be > 0 m, got {:g}", within_m));
  }
}

HybridVesselReport run_hybrid_vessel(const HybridVesselRequest& request) {
  request.validate();
  const std::filesystem::path data = find_data_dir();
  const scenario::ScenarioSpec spec =
      scenario::load_scenario(scenario_path(data, load_case(request.scenario)));
  const scenario::VesselConfig vessel = scenario::load_vessel_config(vessel_file_or_default());
  HybridVesselReport r;
  r.name = to_string(request.scenario);
  r.scenario_name = spec.name;
  r.seed = request.seed;
  r.comparison = scenario::compare_integral_action(spec, vessel, request.seed, request.within_m);
  r.jump_params = spec.hybrid_integral.value_or(hybrid::IntegralJumpParams{});
  return r;
}

}  // namespace dynpos::analysis
