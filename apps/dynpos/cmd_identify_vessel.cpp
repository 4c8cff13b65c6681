// dynpos identify vessel LOG... --out FILE: the hull model of a vessel file fitted to logged
// tests (output-error, the simulator's own model driven by the logged feedback), and
// dynpos compare-trial LOG --vessel FILE: one logged test re-simulated with a vessel file.

#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "dynpos/analysis/vessel_id.hpp"
#include "log_input.hpp"

namespace dynpos::cli {
namespace {

constexpr const char* kRoles =
    "time, heading, u, v, r (or mruK.r), thrust.NAME, rudder.NAME / azimuth.NAME of every unit; "
    "wind_speed, wind_dir and north, east (or gnss1.north/east) when logged";

struct VesselIdOptions {
  std::vector<std::string> logs;
  analysis::LogSource log_options;  // every LOG's, but its path
  analysis::VesselIdRequest request;
  std::string out;
  std::string report;
  analysis::Outputs outputs;
};

struct CompareTrialOptions {
  analysis::CompareTrialRequest request;
  std::string plot;
  analysis::Outputs outputs;
};

}  // namespace

void add_identify_vessel_command(CLI::App& identify) {
  auto o = std::make_shared<VesselIdOptions>();
  CLI::App* sub = identify.add_subcommand(
      "vessel", "Hull model of a vessel file (added mass, damping, coupling) fitted to trial logs");
  sub->add_option("logs", o->logs,
                  "Logs, one per test: step tests, zig-zags, turning circles, 4-corner, "
                  "station-keeping (CSV as the other analyses read them)")
      ->required()
      ->check(CLI::ExistingPath);  // a file, or a ROS 2 bag folder
  add_log_source_options(*sub, o->log_options, kRoles);
  sub->add_option("--vessel", o->request.vessel_file,
                  "Starting vessel file: its values start the fit and are kept where the logs do "
                  "not determine them (default: the built-in Gunnerus)")
      ->check(CLI::ExistingFile);
  output_file(sub->add_option("--out", o->out, "Write the identified vessel file here"))
      ->required();
  output_folder(
      sub->add_option("--report", o->report, "Write the report (index.html and SVGs) here"));
  add_json_option(*sub, o->outputs.json, "Write the results as JSON to FILE, or '-' for stdout");
  sub->add_option("--holdout", o->request.holdout,
                  "The LOG held out of the fit and scored (cross-validation); 'none' for none "
                  "(default: the last LOG of two or more)");
  sub->add_option("--max-rel-sigma", o->request.max_rel_sigma,
                  "Largest σ/|value| of a determined value")
      ->capture_default_str();
  sub->add_option("--max-rel-sigma-fitted", o->request.max_rel_sigma_fitted,
                  "Largest σ/|value| of a value fitted at all (between the two: weakly "
                  "determined, fitted and written but not counted as determined)")
      ->capture_default_str();
  sub->add_option("--step", o->request.step_s, "Re-simulation step [s]")->capture_default_str();
  sub->add_option("--sample", o->request.sample_s, "Spacing of the fitted u, v, r samples [s]")
      ->capture_default_str();
  sub->add_option("--stretch", o->request.stretch_s,
                  "Length [s] of the stretches a log is cut into, each with its own start "
                  "velocity and drifting current")
      ->capture_default_str();
  sub->footer(
      "Fits the hull keys of the vessel file by an output-error fit of the simulator's own model "
      "driven by each log's thrust and rudder feedback to the logged u, v and r (Ceres), each "
      "test with its own start velocity and constant current. A value is determined when its "
      "σ/|value| is at most --max-rel-sigma; the others keep the starting file's value and are "
      "reported with the excitation a trial would need. Example on the virtual programme: "
      "dynpos identify vessel RUN/surge-steps-forward/log.csv RUN/yaw-steps/log.csv "
      "RUN/zig-zag/log.csv --out my-vessel.toml --report vessel-report");
  sub->callback([o] {
    analysis::add_logs(o->request, o->log_options, o->logs);
    o->outputs.figures = o->report;
    const analysis::VesselIdReport report = analysis::run_vessel_id(o->request);
    print_report(text_out(o->outputs), report, analysis::write_outputs(report, o->out, o->outputs));
  });
}

void register_compare_trial(CLI::App& app) {
  auto o = std::make_shared<CompareTrialOptions>();
  CLI::App* sub = app.add_subcommand(
      "compare-trial", "Re-simulate a logged test with its logged feedback and a vessel file");
  add_log_options(*sub, o->request.source, kRoles);
  sub->add_option("--vessel", o->request.vessel_file,
                  "Vessel file (default: the built-in Gunnerus)")
      ->check(CLI::ExistingFile);
  add_json_option(*sub, o->outputs.json, "Write the results as JSON to FILE, or '-' for stdout");
  output_file(sub->add_option("--plot", o->plot,
                              "Write measured and re-simulated u, v, r and track to FILE.svg"));
  sub->add_option("--step", o->request.step_s, "Re-simulation step [s]")->capture_default_str();
  sub->add_option("--stretch", o->request.stretch_s,
                  "Length [s] of the stretches the log is cut into")
      ->capture_default_str();
  sub->footer(
      "NRMSE = RMSE / (max - min of the logged signal) of u, v, r and of the track (RMS "
      "distance over the track's extent). The test's start velocity and constant current are "
      "fitted; the vessel is the file's. Example: dynpos compare-trial RUN/zig-zag/log.csv "
      "--vessel my-vessel.toml");
  sub->callback([o] {
    o->outputs.figures = o->plot;
    write_and_print(analysis::run_compare_trial(o->request), o->outputs);
  });
}

}  // namespace dynpos::cli
