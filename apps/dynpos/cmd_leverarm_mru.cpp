// dynpos leverarm mru: MRU lever arms from MRU accelerations and vessel motion (thesis 4.3,
// case study 4.4.2): the Luenberger observer (4.80) or batch least squares, with the
// excitation diagnostics of Proposition 3, a thesis-style table, JSON and plots (figure 4.13).

#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "dynpos/analysis/leverarm_mru.hpp"
#include "dynpos/analysis/leverarm_mru_text.hpp"
#include "enum_option.hpp"
#include "log_input.hpp"

namespace dynpos::cli {
namespace {

struct MruCliOptions {
  analysis::LeverarmMruRequest request;
  analysis::Outputs outputs;
  std::vector<std::string> mru_log;  ///< NAME=FILE, made request.mru_log when the command runs
};

}  // namespace

void add_leverarm_mru(CLI::App& leverarm) {
  auto o = std::make_shared<MruCliOptions>();
  CLI::App* sub = leverarm.add_subcommand(
      "mru", "MRU lever arms: observer (4.80) or least squares, excitation diagnostics (4.77)");
  add_log_options(*sub, o->request.source,
                  "time, roll, pitch, heading, p, q, r, u, v, w (optional), and per MRU mruK.ax, "
                  "mruK.ay, mruK.az (or --mru-log)");
  sub->add_option("--mru-log", o->mru_log,
                  "MRU accelerations in a file of their own (repeatable): NAME=FILE with "
                  "columns time, NAME.ax, NAME.ay, NAME.az");
  sub->add_option("--reference", o->request.reference,
                  "An MRU of LOG (e.g. mru1) to measure the other MRUs' arms from: its "
                  "accelerations stand in for the origin's, so no velocity is needed (the logger "
                  "alone: its roll, pitch, p, q, r, ax, ay, az and the heading)");
  add_enum_option(*sub, "--accel", o->request.accel, analysis::accel_from_name,
                  "What the MRU acceleration channels hold: kinematic (gravity removed) or "
                  "specific-force (g rotated into BODY is added back)");
  add_enum_option(*sub, "--method", o->request.method, analysis::mru_method_from_name,
                  "lsq (batch least squares, the default: most accurate) or observer "
                  "(Luenberger observer (4.80))");
  add_json_option(*sub, o->outputs.json, "Write the arms as JSON to FILE, or '-'");
  output_folder(sub->add_option("--plots", o->outputs.figures,
                                "Write SVG plots of the estimates over time into DIR"));
  sub->add_option("--window-s", o->request.window_s,
                  "Savitzky–Golay smoothing window for ω̇, ν̇ and every term [s]")
      ->capture_default_str();
  sub->add_option("--tau-s", o->request.tau_s, "Observer convergence time constant [s] (sets W₂)")
      ->capture_default_str();
  sub->add_option("--w1", o->request.w1, "Observer gain W₁ on A₀ [1/s] (4.80)")
      ->capture_default_str();
  sub->footer(
      "Model (4.65) in BODY: a_i − a₀ = (S(ω)² + S(ω̇))·l_i, a₀ = ν̇ + ω × ν (4.69). Needs "
      "rotation: a turning circle in waves. Example: dynpos leverarm mru DIR/truth.csv "
      "--mru-log mru1=DIR/log.csv --mru-log mru2=DIR/log.csv --json arms.json --plots plots; from "
      "the logger alone: dynpos leverarm mru DIR/log.csv --reference mru1");
  sub->callback([o] {
    o->request.mru_log = analysis::parse_mru_logs(o->mru_log);
    write_and_print(analysis::run_leverarm_mru(o->request), o->outputs);
  });
}

}  // namespace dynpos::cli
