// dynpos identify agility: thrust agility (thesis section 3.5.1, figures 3.1-3.3): the time to
// 63.2 % of the response of every thruster (and of the vessel's speed) after a joystick thrust
// step in each direction, as a table, JSON and polar plots.

#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "dynpos/analysis/agility.hpp"
#include "dynpos/analysis/agility_text.hpp"
#include "log_input.hpp"

namespace dynpos::cli {
namespace {

struct AgilityCliOptions {
  std::vector<std::string> windows;  ///< T_STEP,T_END,DIR_DEG[,THRUST_PCT[,YAW_PCT]]
  std::string current;               ///< SPEED_MPS,TO_DEG as observed
  analysis::AgilityRequest request;  ///< the typed options; the parsed ones are added
  analysis::Outputs outputs;         ///< --json, --plot (figures: the SVG file)
};

void run_cli(AgilityCliOptions& o) {
  analysis::AgilityRequest& request = o.request;
  if (!o.current.empty()) request.current = analysis::parse_observed_current(o.current);
  request.windows.clear();
  for (const std::string& w : o.windows)
    request.windows.push_back(analysis::parse_agility_window(w));
  write_and_print(analysis::run_agility(request), o.outputs);
}

}  // namespace

void add_identify_agility(CLI::App& identify) {
  auto o = std::make_shared<AgilityCliOptions>();
  CLI::App* sub = identify.add_subcommand(
      "agility", "Thrust agility: time to 63.2 % per direction and thruster, polar plot");
  add_log_options(*sub, o->request.source,
                  "time, command.surge, command.sway, command.yaw [%], thrust.NAME or rpm.NAME "
                  "per thruster, u, v (speed), wind_speed, wind_dir, heading");
  add_json_option(*sub, o->outputs.json, "Write the response times as JSON to FILE, or '-'");
  output_file(sub->add_option("--plot", o->outputs.figures,
                              "Write the polar plot (SVG), one polar per case"));
  sub->add_option("--window", o->windows,
                  "A step given explicitly (repeatable): T_STEP,T_END,DIR_DEG[,THRUST_PCT"
                  "[,YAW_PCT]]; replaces the joystick demands");
  sub->add_option("--current", o->current,
                  "Current as observed (e.g. on the DP display): SPEED_MPS,TO_DEG, drawn as an "
                  "arrow");
  sub->add_flag("--rpm", o->request.use_rpm,
                "Time the shaft speed (rpm.NAME) even when thrust is logged");
  // The range checks show in --help; AgilityRequest::validate() holds the same bounds.
  sub->add_option("--min-response", o->request.min_response_pct,
                  "A thruster whose change is below this % of its range has no response (null)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 99.0));
  sub->add_option("--min-demand", o->request.min_demand_pct,
                  "Thrust demands below this [%] count as no thrust (no direction)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  sub->footer(
      "Steps: every level of the joystick demands with √(surge²+sway²) ≥ --min-demand, in "
      "direction atan2(sway, surge) (0 = ahead, 90 = starboard), until the next change. "
      "Response time: from the step to the crossing of y0 + 0.632·(y_end − y0), y0 the mean of "
      "the 5 s before, y_end the mean of the last 20 % of the step. Cases (thrust %, yaw %) get "
      "one polar each. Example: dynpos identify agility DIR/log.csv --plot agility.svg --json "
      "agility.json --current 0.2,318");
  sub->callback([o] { run_cli(*o); });
}

}  // namespace dynpos::cli
