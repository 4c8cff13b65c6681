// dynpos identify thrust-map: back-calculate the thrust map T = c·n|n| (3.17) of every thruster
// with logged thrust and shaft speed, or apply a map to a log with shaft speed only (3.18).

#include <memory>

#include "commands.hpp"
#include "dynpos/analysis/thrust_map.hpp"
#include "log_input.hpp"

namespace dynpos::cli {

void add_identify_thrust_map(CLI::App& identify) {
  auto o = std::make_shared<AnalysisOptions<analysis::ThrustMapRequest>>();
  analysis::ThrustMapRequest& r = o->request;
  CLI::App* sub = identify.add_subcommand(
      "thrust-map", "Thrust map: back-calculate c+ and c- of T = c n|n| (3.17), or apply a map");
  add_log_options(*sub, r.source, "time, rpm.NAME (shaft speed), thrust.NAME, per thruster NAME");
  sub->add_option("--min-speed", r.min_speed_rpm,
                  "Leave out samples with |n| below this [rpm]: near zero the thrust is noise")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  add_json_option(*sub, o->outputs.json,
                  "Write the coefficients as JSON to FILE, or '-' for stdout");
  sub->add_flag("--apply", r.apply,
                "Apply the vessel file's maps to a log with shaft speed only; writes --out");
  sub->add_flag("--abs-speed", r.abs_speed,
                "With --apply: the log has |n| only, so use the mean coefficient (3.18)");
  sub->add_option("--vessel", r.vessel, "With --apply: vessel file (default: built-in Gunnerus)")
      ->check(CLI::ExistingFile);
  output_file(
      sub->add_option("--out", r.out, "With --apply: CSV to write (time, rpm.NAME, thrust.NAME)"));
  sub->footer(
      "Back-calculation: for each sign of n, c = Σ T n² / Σ n⁴ (least squares through the "
      "origin), with 1σ from the residuals. Values in N/rps² in JSON (c_pos, c_neg, c_mean), "
      "kN/rps² in the table (thesis table 3.2: 8.13 / -5.8). Example: dynpos identify "
      "thrust-map DIR/log.csv --json map.json");
  sub->callback([o] { write_and_print(analysis::run_thrust_map(o->request), o->outputs); });
}

}  // namespace dynpos::cli
