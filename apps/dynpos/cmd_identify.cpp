// dynpos identify step|thrust-map|agility|four-corner|station-keeping|failure-test: thesis
// chapter 3 (and the DP failure tests) on any CSV log through a column map. `step` is here; the
// others have a file each.

#include <memory>

#include "commands.hpp"
#include "dynpos/analysis/step.hpp"
#include "enum_option.hpp"
#include "live_command.hpp"
#include "log_input.hpp"

namespace dynpos::cli {

void add_identify_step(CLI::App& identify, LogMode mode) {
  auto opt = std::make_shared<AnalysisOptions<analysis::StepRequest>>();
  analysis::StepRequest& r = opt->request;
  CLI::App* step = identify.add_subcommand(
      "step", "Step-test identification: FOPDT gain, time constant and dead time per step");
  const std::string roles =
      "time, input (the command), output (the response), trigger (e.g. power feedback, to time "
      "steps without a command)";
  add_log_options(*step, r.source, roles, mode);
  add_enum_option(*step, "--method", r.method, analysis::step_method_from_name,
                  "lsq: least squares with the dead time; smith: Smith's two-point "
                  "method (3.8)-(3.9); smith2: Smith's second-order 20/60 %; rk: "
                  "Rangaiah-Krishnaswamy 14/55/91 %");
  step->add_option("--from", r.from_s, "Window start [s] (one step in the window)");
  step->add_option("--to", r.to_s, "Window end [s]");
  step->add_option("--step-at", r.step_at_s, "Step time [s] (with or without a window)");
  step->add_option_function<std::string>(
          "--derive",
          [&r](const std::string& name) { r.derive = analysis::step_derive_from_name(name); },
          "total-speed: fit sqrt(u^2 + v^2) (3.19) from the roles u and v (sway tests)")
      ->type_name("total-speed");
  step->add_option("--min-step", r.min_step,
                   "Smallest input change counted as a step, in the input's SI unit (default: "
                   "adapted to the log from its noise and largest changes, and printed)");
  step->add_option("--segments", r.segments_file,
                   "CSV of named stretches 'name, start, end' [s, log clock], e.g. the tests of "
                   "the bridge log: only steps inside them are analysed, and named")
      ->check(CLI::ExistingFile);
  step->add_option("--min-plateau", r.min_plateau_s,
                   "Shortest time [s] the input holds a level to count as a step")
      ->capture_default_str();
  add_json_option(*step, opt->outputs.json, "Write the results as JSON to FILE, or '-' for stdout");
  step->footer(
      "Finds every step of the input (or trigger) automatically, or takes the window given, and "
      "fits y = y0 + K*du*(1 - exp(-(t - t0 - delay)/T)) (3.7) to the output after each. Values "
      "are SI: y in the output's SI unit, K in output unit per input unit, T and delay in s. "
      "A step that cannot be fitted is listed with status failed and the reason. "
      "Warnings: steady_state_not_reached, poor_fit, short_window, few_samples, ... "
      "Example on a virtual trial log: dynpos identify step DIR/log.csv "
      "--col input=command.rpm.stb --col output=rpm.stb");
  set_run_callback<analysis::StepRequest>(
      *step, mode, [opt] { return opt->request; }, analysis::run_step, opt->outputs,
      "dynpos live identify step --follow DIR/log.csv --col input=command.rpm.stb --col "
      "output=rpm.stb --idle-exit 5");
}

void register_identify(CLI::App& app) {
  CLI::App* identify = app.add_subcommand(
      "identify", "Identify thruster and vessel dynamics from sea-trial logs (thesis ch. 3)");
  identify->require_subcommand(1, 1);
  add_identify_step(*identify, LogMode::kFile);
  add_identify_thrust_map(*identify);
  add_identify_agility(*identify);
  add_identify_four_corner(*identify);
  add_identify_station_keeping(*identify);
  add_identify_failure_test(*identify);
  add_identify_vessel_command(*identify);
}

}  // namespace dynpos::cli
