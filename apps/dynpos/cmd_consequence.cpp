// dynpos consequence: along a logged DP run, the margin of the worst single failure against the
// estimated environmental load (DP consequence analysis).

#include <memory>

#include "commands.hpp"
#include "dynpos/analysis/consequence.hpp"
#include "estimate_options.hpp"

namespace dynpos::cli {

void register_consequence(CLI::App& app) {
  struct Options {
    EstimateCliOptions estimate;
    analysis::ConsequenceRequest request;
    analysis::Outputs outputs;
  };
  auto o = std::make_shared<Options>();
  analysis::ConsequenceRequest& r = o->request;
  CLI::App* sub = app.add_subcommand(
      "consequence",
      "Consequence analysis along a logged DP run: would the worst single failure have lost "
      "position under the estimated environmental load");
  o->estimate.add(*sub);
  sub->add_option("--step", r.step_s, "One point every this long [s]")->capture_default_str();
  sub->add_option("--window", r.mean_window_s,
                  "The load at a point: the trailing mean of the estimated bias over this [s]")
      ->capture_default_str();
  output_file(sub->add_option("--out", r.out,
                              "CSV of the points: heading, load.x/y/n (BODY), lambda per case, "
                              "worst, lambda, margin"));
  add_json_option(*sub, o->outputs.json, "Write the summary as JSON to FILE, or '-' for stdout");
  sub->footer(
      "The observer of `dynpos estimate` runs over the log; at each point its bias b̂, averaged "
      "over --window and taken into BODY at the estimated heading, is the load. For each single "
      "failure of the vessel (each unit and group:NAME of a [[thruster]] layout; port, stb, "
      "rudder.port, rudder.stb, tunnel of the model) λ is the largest factor of the load the "
      "remaining thrusters hold (docs/theory.md, \"Consequence analysis\"); the margin is λ - 1 "
      "of the worst case, negative where position would have been lost. Example: dynpos "
      "consequence DIR/log.csv --col north=gnss1.north --col east=gnss1.east --col "
      "roll=mru1.roll --col pitch=mru1.pitch --arm 0.202,-0.611,-13.891 --tp 7 --json c.json");
  sub->callback([o] {
    o->request.estimate = o->estimate.resolved();
    write_and_print(analysis::run_consequence(o->request), o->outputs);
  });
}

}  // namespace dynpos::cli
