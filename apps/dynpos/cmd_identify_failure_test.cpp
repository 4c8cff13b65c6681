// dynpos identify failure-test: thruster trips found in a log (DP annual trials, FMEA proving
// trials), with the position and heading excursion, the recovery and the thrust redistribution.

#include <memory>
#include <vector>

#include "commands.hpp"
#include "dynpos/analysis/failure_test.hpp"
#include "dynpos/analysis/option_text.hpp"
#include "log_input.hpp"

namespace dynpos::cli {
namespace {

struct FailureTestCliOptions {
  std::vector<double> arm_m;  ///< X,Y[,Z] [m]
  analysis::FailureTestRequest request;
  analysis::Outputs outputs;
};

}  // namespace

void add_identify_failure_test(CLI::App& identify) {
  auto o = std::make_shared<FailureTestCliOptions>();
  analysis::FailureTestRequest& r = o->request;
  CLI::App* sub = identify.add_subcommand(
      "failure-test", "Thruster trips: position excursion, recovery and thrust redistribution");
  add_log_options(*sub, r.source,
                  "time; north, east (m, any offset) or lat, lon; heading; per unit thrust.NAME "
                  "or rpm.NAME");
  add_arm_option(*sub, o->arm_m);
  sub->add_flag("--rpm", r.use_rpm, "Use the shaft speed (rpm.NAME) even when thrust is logged");
  sub->add_option("--from", r.t_from_s, "Analyse from this time [s]");
  sub->add_option("--to", r.t_to_s, "Analyse up to this time [s]");
  sub->add_option("--pre-window", r.pre_window_s,
                  "Pre-failure window [s]: mean position, mean heading and footprint")
      ->capture_default_str();
  sub->add_option("--redistribution-window", r.redistribution_window_s,
                  "Window [s] before and after the failure of the other units' mean feedback")
      ->capture_default_str();
  sub->add_option("--hold", r.hold_s, "Recovered once back within the footprint for this long [s]")
      ->capture_default_str();
  sub->add_option("--response-window", r.response_window_s,
                  "Peak and recovery are searched this long after the failure [s] (at most up "
                  "to the next event)")
      ->capture_default_str();
  sub->add_option("--max-fall", r.max_fall_s,
                  "A trip brings the feedback to near zero within this [s]")
      ->capture_default_str();
  sub->add_option("--min-off", r.min_off_s, "A tripped unit stays near zero this long [s]")
      ->capture_default_str();
  add_json_option(*sub, o->outputs.json, "Write the results as JSON to FILE, or '-' for stdout");
  sub->footer(
      "A trip: a unit's feedback (thrust, else shaft speed) falls from a clearly non-zero level "
      "to near zero within --max-fall, stays there --min-off, and another unit takes over. The "
      "failure instant is the start of the fall (a first-order-plus-dead-time fit). Per event: "
      "peak excursion of the control origin from its pre-failure mean [m], time to peak [s], "
      "recovery [s] (back within the pre-failure footprint for --hold; null if never), peak "
      "heading change [deg], and each other unit's mean feedback before and after. Example: "
      "dynpos identify failure-test trial.csv --col north=gnss1.north --col east=gnss1.east "
      "--arm 0.2,-0.6");
  sub->callback([o] {
    o->request.arm_m = analysis::arm_from_numbers(o->arm_m, "arm");
    write_and_print(analysis::run_failure_test(o->request), o->outputs);
  });
}

}  // namespace dynpos::cli
