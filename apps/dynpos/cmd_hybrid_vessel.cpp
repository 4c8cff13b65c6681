// dynpos hybrid vessel --scenario ice|mooring: the DP controller of the virtual Gunnerus with
// conventional and with hybrid integral action under a sudden load, side by side
// (analysis/hybrid_vessel.hpp).

#include <fmt/core.h>

#include <memory>
#include <string>

#include "commands.hpp"
#include "dynpos/analysis/hybrid_vessel.hpp"

namespace dynpos::cli {
namespace {

struct VesselOptions {
  analysis::HybridVesselRequest request;
  std::string scenario;       ///< --scenario, a load case's name (analysis::HybridLoad)
  analysis::Outputs outputs;  ///< --json, --out (the folder of the plots)
};

}  // namespace

void add_hybrid_vessel(CLI::App& hybrid) {
  auto opt = std::make_shared<VesselOptions>();
  CLI::App* sub = hybrid.add_subcommand(
      "vessel",
      "Hybrid vs conventional integral action on the virtual Gunnerus under a sudden load");
  sub->add_option("--scenario", opt->scenario,
                  "ice: a 20 kN ice load sets in; mooring: a mooring line holding 20 kN snaps")
      ->required();
  add_seed_option(*sub, opt->request.seed, "Master seed (the same for both designs)");
  output_folder(sub->add_option("--out", opt->outputs.figures,
                                "Folder for the SVG plots (created if needed)"));
  add_json_option(*sub, opt->outputs.json, "Write the results as JSON to FILE, or '-' for stdout");
  // The library checks the value (HybridVesselRequest::validate); the type name says the range.
  sub->add_option("--within", opt->request.within_m, "Distance for 'back within' [m]")
      ->type_name("FLOAT:POSITIVE")
      ->capture_default_str();
  const auto& cases = analysis::kHybridVesselLoadCases;
  sub->footer(fmt::format(
      "Runs data/scenarios/{}.toml or {}.toml twice on the virtual "
      "Gunnerus (thrusters with dynamics and saturation, waves, wind, current): the DP "
      "controller (5.35)-(5.38) with continuous integral action, and with hybrid integral action "
      "(jumps by the practical rule (5.64)-(5.67)). Figures after the load: peak offset, time "
      "back within 1 m, IAE, energy, jumps. Plots: hybrid_vessel_<scenario>_{{position,integral,"
      "power}}.svg.",
      cases[0].scenario_file, cases[1].scenario_file));
  sub->callback([opt] {
    opt->request.scenario = analysis::hybrid_load_from_string(opt->scenario);
    write_and_print(analysis::run_hybrid_vessel(opt->request), opt->outputs);
  });
}

}  // namespace dynpos::cli
