// dynpos capability: DP capability after DNV-ST-0111 (levels 1-3) on the vessel model, intact
// and after single failures, as a table, JSON and a capability rose (analysis/capability.hpp).

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "commands.hpp"
#include "dynpos/analysis/capability.hpp"
#include "dynpos/analysis/capability_transient.hpp"
#include "dynpos/analysis/feasibility.hpp"

namespace dynpos::cli {
namespace {

struct CapabilityCliOptions {
  analysis::CapabilityRequest request;
  std::filesystem::path loads;  ///< a load table: the feasibility mode
  analysis::Outputs outputs;    ///< --json, --out (the folder of rose.svg)
};

}  // namespace

void register_capability(CLI::App& app) {
  auto o = std::make_shared<CapabilityCliOptions>();
  analysis::CapabilityRequest& r = o->request;
  CLI::App* sub = app.add_subcommand(
      "capability",
      "DP capability (DNV-ST-0111 levels 1-3): the strongest weather held per direction, "
      "intact and after single failures, with a capability rose");
  sub->add_option("--level", r.level,
                  "1: the standard's table, rated thrust; 2: the model's thrust losses at the "
                  "current's inflow, a site environment; 3: time-domain runs of the "
                  "DP-controlled vessel")
      ->capture_default_str();
  sub->add_option("--vessel", r.vessel, "Vessel file (default: data/vessels/gunnerus.toml)");
  sub->add_option("--failure", r.failure,
                  "none, worst (every single failure, the worst per direction) or one case: "
                  "an actuator of the model (port, stb, rudder.port, rudder.stb, tunnel), or a "
                  "unit or group:NAME of a [[thruster]] layout")
      ->capture_default_str();
  sub->add_option("--loads", o->loads,
                  "Load table (CSV: direction_deg,X_N,Y_N,N_Nm, the environment's load in "
                  "BODY): for each row the largest factor held by the vessel's [[thruster]] "
                  "layout (or its model's units), and the limiting units");
  sub->add_option("--site", r.site,
                  "Level 2: site table, TOML [[environment]] rows with wind_mps, hs_m, tp_s, "
                  "current_mps (default: the DNV table)");
  sub->add_option("--hs", r.hs, "Level 2: fixed significant wave height [m]");
  sub->add_option("--tp", r.tp, "Level 2: fixed peak period [s]");
  sub->add_option("--current", r.current, "Level 2: fixed current speed [m/s]");
  sub->add_option("--direction-step", r.direction_step, "Direction step [deg], dividing 360")
      ->capture_default_str();
  sub->add_option("--wind-tolerance", r.wind_tolerance,
                  "Bisection tolerance on the wind [m/s] (default 0.01; level 3: 0.25)");
  sub->add_option("--duration", r.duration, "Level 3: judged run length [s]")
      ->capture_default_str();
  sub->add_option("--settle", r.settle, "Level 3: unjudged start of each run [s]")
      ->capture_default_str();
  sub->add_option("--footprint", r.footprint, "Level 3: position footprint [m]")
      ->capture_default_str();
  sub->add_option("--footprint-deg", r.footprint_deg, "Level 3: heading footprint [deg]")
      ->capture_default_str();
  add_seed_option(*sub, r.seed, "Level 3: master seed of the runs");
  sub->add_option("--jobs", r.jobs, "Level 3: parallel runs (default: every core)");
  sub->add_flag("--transient", r.transient,
                "Level 3: trip the --failure named as it happens after --settle s of "
                "stationkeeping; per direction and weather row the largest excursion and the "
                "time to it (a footprint plot, footprint.svg) instead of a rose");
  sub->add_option("--rows", r.rows, "Transient: the weather rows (DP numbers) run")
      ->delimiter(',')
      ->capture_default_str();
  sub->add_option("--after", r.after, "Transient: run after the failure [s]")
      ->capture_default_str();
  sub->add_option("--seeds", r.seeds, "Transient: runs per direction and row (seeds --seed, +1, …)")
      ->capture_default_str();
  sub->add_option("--observer", r.observer,
                  "Transient: what the DP loop runs on: ideal, passive, ekf or raw")
      ->capture_default_str();
  output_folder(
      sub->add_option("--out", o->outputs.figures, "Folder for the capability rose (rose.svg)"));
  add_json_option(*sub, o->outputs.json, "Write the results as JSON to FILE, or '-' for stdout");
  sub->footer(
      "Wind, waves and current come from the same direction, relative to the bow (0 = head-on, "
      "90 = from starboard). Levels 1 and 2 balance the mean load × 1.25 (DNV's reserve for "
      "dynamics) against the thrusters' limits exactly; level 3 bisects the environment until "
      "the vessel leaves its footprint. Example: dynpos capability --failure worst --out cap");
  sub->callback([o, sub] {
    // Whether --NAME was given. The outputs were checked with every other before the run.
    const auto given = [sub](std::string_view name) {
      return sub->count("--" + std::string(name)) > 0;
    };
    if (!o->loads.empty()) {
      analysis::check_loads_options(given);
      const analysis::FeasibilityRequest loads{o->request.vessel, o->loads, o->request.failure};
      return write_and_print(analysis::run_feasibility(loads), o->outputs);
    }
    analysis::check_transient_options(o->request, given);
    if (o->request.transient) {
      return write_and_print(analysis::run_capability_transient(o->request), o->outputs);
    }
    write_and_print(analysis::run_capability(o->request), o->outputs);
  });
}

}  // namespace dynpos::cli
