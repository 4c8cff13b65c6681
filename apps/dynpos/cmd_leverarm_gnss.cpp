// dynpos leverarm gnss: GNSS antenna lever arms from vessel motion (thesis 4.2, 4.4.1).

#include <memory>

#include "commands.hpp"
#include "dynpos/analysis/leverarm_gnss.hpp"
#include "dynpos/analysis/leverarm_gnss_text.hpp"
#include "dynpos/analysis/leverarm_mru.hpp"
#include "dynpos/analysis/option_text.hpp"
#include "enum_option.hpp"
#include "live_command.hpp"
#include "log_input.hpp"

namespace dynpos::cli {
namespace {

struct GnssCliOptions {
  analysis::LeverarmGnssRequest request;
  analysis::LeverarmGnssText text;  ///< the options given as text, parsed into the request
  analysis::Outputs outputs;
};

}  // namespace

void add_leverarm_gnss(CLI::App& leverarm, LogMode mode) {
  auto o = std::make_shared<GnssCliOptions>();
  CLI::App* sub = leverarm.add_subcommand(
      "gnss",
      "GNSS antenna (and further MRU) lever arms: from the logger alone by GNSS/INS fusion, or "
      "by the thesis' Luenberger (4.26), adaptive (4.42, 4.48) or least-squares estimators");
  add_log_options(*sub, o->request.source,
                  "ins: mruK.roll/pitch/p/q/r/ax/ay/az and heading; thesis methods: time, roll, "
                  "pitch, heading, p, q, r, u, v, w (optional); per antenna gnssK.lat/lon/height "
                  "or gnssK.north/east/down",
                  mode);
  add_enum_option(*sub, "--method", o->request.method, analysis::gnss_method_from_name,
                  "auto, ins, luenberger, adaptive or lsq (auto: ins when the log has an MRU "
                  "with accelerations and the heading, else lsq)");
  sub->add_option("--imu", o->request.imu,
                  "ins: the MRU of the fusion, mruK (default: the first with every role)");
  sub->add_option("--imu-arm", o->text.imu_arm,
                  "ins: X,Y,Z of that MRU from CO [m]; given, every arm is from CO, else from "
                  "the MRU");
  add_enum_option(*sub, "--accel", o->request.accel, analysis::accel_from_name,
                  "ins: the MRUs' accelerations, kinematic or specific-force");
  sub->add_option("--antennas", o->request.antennas,
                  "Antennas to estimate, e.g. gnss1,gnss2 (default: every gnssK found)")
      ->delimiter(',');
  sub->add_option("--gnss-log", o->text.gnss_log,
                  "gnssK=FILE.csv: the antenna's fixes from a file of its own, own time column "
                  "on the same clock (repeatable)");
  sub->add_option("--nmea", o->text.nmea, "gnssK=FILE: the antenna's fixes from NMEA 0183 (GGA)");
  sub->add_option("--utc-at-zero", o->text.utc_at_zero,
                  "UTC of the log's t = 0, HH:MM:SS[.sss] or YYYY-MM-DDTHH:MM:SS[.sss]Z (for "
                  "--nmea)");
  const calib::GnssArmOptions defaults;
  sub->add_option("--init", o->text.init, "gnssK=X,Y,Z: initial arm of an observer [m]");
  sub->add_option("--w1", o->text.w1, "Luenberger W1 on P0, X,Y,Z [1/s]")
      ->default_str(analysis::vec3_text(defaults.luenberger_w_p0));
  sub->add_option("--w2", o->text.w2, "Luenberger W2 on each arm, X,Y,Z [1/s]")
      ->default_str(analysis::vec3_text(defaults.luenberger_w_arm));
  sub->add_option("--gamma", o->text.gamma,
                  "Adaptive Γ, X,Y,Z (default: rate·L/E|ω|², see --adaptive-rate)");
  sub->add_option("--L", o->text.L, "Adaptive L, X,Y,Z [1/s]")
      ->default_str(analysis::vec3_text(defaults.adaptive_l));
  sub->add_option("--adaptive-rate", o->request.adaptive_rate,
                  "Adaptive: convergence rate that sets Γ when --gamma is not given [1/s]")
      ->capture_default_str();
  sub->add_option("--init-p0", o->text.init_p0,
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
  add_json_option(*sub, o->outputs.json, "Write the results as JSON to FILE, or '-' for stdout");
  output_folder(sub->add_option("--plots", o->outputs.figures,
                                "Write SVG plots (arms over time, P0 NE, excitation)"));
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
  set_run_callback<analysis::LeverarmGnssRequest>(
      *sub, mode,
      [o] {
        analysis::LeverarmGnssRequest request = o->request;
        analysis::parse_text(o->text, request);
        return request;
      },
      analysis::run_leverarm_gnss, o->outputs,
      "dynpos live leverarm gnss --follow DIR/log.csv --imu-arm 0.358,0.804,-4.321 --idle-exit "
      "10");
}

}  // namespace dynpos::cli
