// dynpos estimate: a DP observer run over a logged DP run — the low-frequency motion and the
// bias (the environmental load the thrusters held against) as a time series.

#include <memory>
#include <vector>

#include "commands.hpp"
#include "dynpos/analysis/estimate.hpp"
#include "estimate_options.hpp"

namespace dynpos::cli {

void EstimateCliOptions::add(CLI::App& sub) {
  analysis::EstimateRequest& r = request;
  add_log_options(sub, r.source,
                  "time; north, east (m, any offset) or lat, lon; heading; roll, pitch (an arm's "
                  "height); per unit of the vessel thrust.NAME and its angle rudder.NAME or "
                  "azimuth.NAME");
  sub.add_option("--vessel", r.vessel,
                 "Vessel file whose units the log's feedback names (default: "
                 "data/vessels/gunnerus.toml)");
  add_arm_option(sub, arm_m);
  sub.add_option("--observer", r.observer,
                 "passive (Fossen & Strand's nonlinear passive observer) or ekf (the extended "
                 "Kalman filter)")
      ->type_name("NAME")
      ->capture_default_str();
  sub.add_option("--tp", r.tp_s,
                 "Wave peak period [s] the observer's wave model is set for, as the DP operator "
                 "enters it (2-20)")
      ->capture_default_str();
  sub.add_option("--rate", r.rate_hz, "The observer's step rate [Hz]; inputs sampled and held")
      ->capture_default_str();
  sub.add_option("--max-hold", r.max_hold_s,
                 "A sample stands for its input at most this long [s]: a thrust older is "
                 "counted as stale; with the passive observer a position older is missing "
                 "(it coasts; the EKF corrects once per fresh sample)")
      ->capture_default_str();
  sub.add_option("--settle", r.settle_s,
                 "The summary's mean bias leaves out this long after the observer starts [s]")
      ->capture_default_str();
  sub.add_option("--mru", r.mru,
                 "Bridge a GNSS gap longer than --max-hold on this MRU's logged acceleration "
                 "(mruK.ax/ay/az, with roll and pitch; lever arm and noise from the vessel file): "
                 "auto (the first the log has), none, or its name")
      ->type_name("NAME")
      ->capture_default_str();
  sub.add_option("--from", r.t_from_s, "Analyse from this time [s]");
  sub.add_option("--to", r.t_to_s, "Analyse up to this time [s]");
}

analysis::EstimateRequest EstimateCliOptions::resolved() const {
  analysis::EstimateRequest r = request;
  r.arm_m = analysis::arm_from_numbers(arm_m, "arm");
  return r;
}

void register_estimate(CLI::App& app) {
  struct Options {
    EstimateCliOptions estimate;
    analysis::Outputs outputs;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub =
      app.add_subcommand("estimate",
                         "DP observer over a logged DP run: low-frequency motion and the bias (the "
                         "estimated environmental load) as a time series");
  o->estimate.add(*sub);
  output_file(sub->add_option("--out", o->estimate.request.out,
                              "CSV of the time series: lf.north/east/heading/u/v/r, "
                              "bias.north/east/yaw (NED)"));
  add_json_option(*sub, o->outputs.json, "Write the summary as JSON to FILE, or '-' for stdout");
  sub->footer(
      "The observer (docs/theory.md, \"DP observers\") runs on the vessel's DP model with the "
      "position at the control origin, the heading and the thrust of each unit's feedback "
      "(thrust.NAME with rudder.NAME or azimuth.NAME). The bias b̂ is the environmental load in "
      "NED (kN, kN*m in the CSV). Example on a virtual trial log: dynpos estimate DIR/log.csv "
      "--col north=gnss1.north --col east=gnss1.east --col roll=mru1.roll --col "
      "pitch=mru1.pitch --arm 0.202,-0.611,-13.891 --tp 7 --out estimate.csv");
  sub->callback(
      [o] { write_and_print(analysis::run_estimate(o->estimate.resolved()), o->outputs); });
}

}  // namespace dynpos::cli
