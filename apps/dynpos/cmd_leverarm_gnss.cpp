// dynpos leverarm gnss: GNSS antenna lever arms from vessel motion (thesis 4.2, 4.4.1).

#include <fmt/core.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "dynpos/analysis/leverarm_gnss.hpp"
#include "dynpos/io/json_writer.hpp"
#include "log_input.hpp"

namespace dynpos::cli {
namespace {

struct GnssCliOptions {
  LogInput input;
  analysis::LeverarmGnssRequest request;
  std::string json;
  std::filesystem::path plots;
};

void run_gnss(GnssCliOptions& o) {
  o.request.source = o.input;
  o.request.validate();
  check_json_target(o.json);
  const analysis::LeverarmGnssReport report = analysis::run_leverarm_gnss(o.request);
  std::vector<std::filesystem::path> plots;
  if (!o.plots.empty()) plots = analysis::write_figures(report, o.plots);
  if (!o.json.empty()) io::write_json(o.json, analysis::to_json(report));
  std::FILE* out = o.json == "-" ? stderr : stdout;
  print_text(out, "{}", analysis::to_text(report));
  for (const auto& p : plots) print_text(out, "wrote {}\n", p.string());
  if (!o.json.empty() && o.json != "-") print_text(out, "wrote {}\n", o.json);
}

}  // namespace

void add_leverarm_gnss(CLI::App& leverarm) {
  auto o = std::make_shared<GnssCliOptions>();
  CLI::App* sub = leverarm.add_subcommand(
      "gnss",
      "GNSS antenna (and further MRU) lever arms: from the logger alone by GNSS/INS fusion, or "
      "by the thesis' Luenberger (4.26), adaptive (4.42, 4.48) or least-squares estimators");
  o->input.add_options(*sub,
                       "ins: mruK.roll/pitch/p/q/r/ax/ay/az and heading; thesis methods: time, "
                       "roll, pitch, heading, p, q, r, u, v, w (optional); per antenna "
                       "gnssK.lat/lon/height or gnssK.north/east/down");
  sub->add_option("--method", o->request.method,
                  "auto, ins, luenberger, adaptive or lsq (auto: ins when the log has an MRU "
                  "with accelerations and the heading, else lsq)")
      ->capture_default_str();
  sub->add_option("--imu", o->request.imu,
                  "ins: the MRU of the fusion, mruK (default: the first with every role)");
  sub->add_option("--imu-arm", o->request.imu_arm,
                  "ins: X,Y,Z of that MRU from CO [m]; given, every arm is from CO, else from "
                  "the MRU");
  sub->add_option("--accel", o->request.accel,
                  "ins: the MRUs' accelerations, kinematic or specific-force")
      ->capture_default_str();
  sub->add_option("--antennas", o->request.antennas,
                  "Antennas to estimate, e.g. gnss1,gnss2 (default: every gnssK found)")
      ->delimiter(',');
  sub->add_option("--gnss-log", o->request.gnss_log,
                  "gnssK=FILE.csv: the antenna's fixes from a file of its own, own time column "
                  "on the same clock (repeatable)");
  sub->add_option("--nmea", o->request.nmea,
                  "gnssK=FILE: the antenna's fixes from NMEA 0183 (GGA)");
  sub->add_option("--utc-at-zero", o->request.utc_at_zero,
                  "UTC of the log's t = 0, HH:MM:SS[.sss] or YYYY-MM-DDTHH:MM:SS[.sss]Z (for "
                  "--nmea)");
  sub->add_option("--init", o->request.init, "gnssK=X,Y,Z: initial arm of an observer [m]");
  sub->add_option("--w1", o->request.w1,
                  "Luenberger W1 on P0, X,Y,Z [1/s] (default 0.001,0.001,0.001)");
  sub->add_option("--w2", o->request.w2,
                  "Luenberger W2 on each arm, X,Y,Z [1/s] (default 30,30,30)");
  sub->add_option("--gamma", o->request.gamma,
                  "Adaptive Γ, X,Y,Z (default: rate·L/E|ω|², see --adaptive-rate)");
  sub->add_option("--L", o->request.L, "Adaptive L, X,Y,Z [1/s] (default 1,1,1)");
  sub->add_option("--adaptive-rate", o->request.adaptive_rate,
                  "Adaptive: convergence rate that sets Γ when --gamma is not given [1/s]")
      ->capture_default_str();
  sub->add_option("--init-p0", o->request.init_p0,
                  "N,E,D: initial P0 of the Luenberger observer in the fixes' local NED frame "
                  "(origin at the first fix) [m]; default from the first fixes and --init");
  sub->add_option("--lag", o->request.lag, "lsq: difference fixes this many epochs apart")
      ->capture_default_str();
  sub->add_option("--time-offset", o->request.time_offset,
                  "GNSS time offset [s]: a fix stamped t holds the position at t − offset "
                  "(ins estimates it unless given)");
  sub->add_flag("--estimate-time-offset", o->request.estimate_time_offset,
                "Thesis methods: estimate the GNSS time offset by the least-squares residual");
  sub->add_option("--max-time-offset", o->request.max_time_offset, "Search range of the offset [s]")
      ->capture_default_str();
  sub->add_option("--converged-from", o->request.converged_from,
                  "Observers: average from this fraction of the log on (the table's interval)")
      ->capture_default_str();
  sub->add_option("--pe-window", o->request.pe_window, "PE window T of (4.51) [s]")
      ->capture_default_str();
  sub->add_option("--gnss-std", o->request.gnss_std,
                  "GNSS noise per horizontal axis [m]: the predicted σ of the verdict, or ins's "
                  "starting value (vertical twice it; both then found from the data)")
      ->capture_default_str();
  add_json_option(*sub, o->json, "Write the results as JSON to FILE, or '-' for stdout");
  output_folder(
      sub->add_option("--plots", o->plots, "Write SVG plots (arms over time, P0 NE, excitation)"));
  sub->footer(
      "Arms in BODY (x fwd, y stb, z down). ins (the default with an MRU in the log) needs no "
      "velocity: from the GNSS fixes, one MRU and the heading it estimates every antenna's and "
      "every further MRU's arm, the GNSS time offset and the accelerometer bias, each with its "
      "1σ and a per-axis verdict; e.g. dynpos leverarm gnss DIR/log.csv --imu-arm "
      "0.358,0.804,-4.321. The thesis' methods give arms from the point whose velocity u, v, w "
      "is logged: lsq reports the estimator's own 1σ; the observers report mean and std over "
      "the converged interval (thesis tables 4.2–4.5). The velocity must carry the "
      "wave-frequency motion (heave w included) for the absolute arms; the baselines between "
      "antennas need none. Example on a virtual trial, motion from the 100 Hz reference: dynpos "
      "leverarm gnss DIR/truth.csv --gnss-log gnss1=DIR/log.csv --gnss-log gnss2=DIR/log.csv "
      "--estimate-time-offset; from the logger's MRU and speed log: dynpos leverarm gnss "
      "DIR/log.csv --col roll=mru1.roll --col pitch=mru1.pitch --col p=mru1.p --col q=mru1.q "
      "--col r=mru1.r");
  sub->callback([o] { run_gnss(*o); });
}

}  // namespace dynpos::cli
