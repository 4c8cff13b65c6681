// dynpos identify thrust-map: back-calculate the thrust map T = c·n|n| (3.17) of every thruster
// with logged thrust and shaft speed, or apply a map to a log with shaft speed only (3.18).

#include <fmt/core.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "commands.hpp"
#include "dynpos/analysis/options.hpp"
#include "dynpos/analysis/thrust_map.hpp"
#include "dynpos/io/csv_writer.hpp"
#include "dynpos/io/json_writer.hpp"
#include "log_input.hpp"

namespace dynpos::cli {
namespace {

struct ThrustMapOptions {
  LogInput input;
  analysis::ThrustMapRequest request;
  std::string json;
  std::filesystem::path out;
};

void run_thrust_map(ThrustMapOptions& o) {
  o.request.source = o.input;
  o.request.validate();
  if (o.request.apply && o.out.empty()) {
    throw analysis::option_error("out", "--apply needs --out FILE.csv",
                                 "name the CSV to write the computed thrust into");
  }
  if (o.request.apply) analysis::check_output_file("out", o.out.string());
  if (!o.request.apply) analysis::check_output_file("json", o.json);
  const analysis::ThrustMapReport report = analysis::run_thrust_map(o.request);
  if (report.applied) {
    io::write_csv(o.out, report.applied->log);
    print_text(stdout, "{}", analysis::to_text(report, o.out));
    return;
  }
  if (!o.json.empty()) io::write_json(o.json, analysis::to_json(report));
  std::FILE* out = o.json == "-" ? stderr : stdout;
  print_text(out, "{}", analysis::to_text(report));
  if (!o.json.empty() && o.json != "-") print_text(out, "wrote {}\n", o.json);
}

}  // namespace

void add_identify_thrust_map(CLI::App& identify) {
  auto o = std::make_shared<ThrustMapOptions>();
  analysis::ThrustMapRequest& r = o->request;
  CLI::App* sub = identify.add_subcommand(
      "thrust-map", "Thrust map: back-calculate c+ and c- of T = c n|n| (3.17), or apply a map");
  o->input.add_options(*sub, "time, rpm.NAME (shaft speed), thrust.NAME, per thruster NAME");
  sub->add_option("--min-speed", r.min_speed_rpm,
                  "Leave out samples with |n| below this [rpm]: near zero the thrust is noise")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  add_json_option(*sub, o->json, "Write the coefficients as JSON to FILE, or '-' for stdout");
  sub->add_flag("--apply", r.apply,
                "Apply the vessel file's maps to a log with shaft speed only; writes --out");
  sub->add_flag("--abs-speed", r.abs_speed,
                "With --apply: the log has |n| only, so use the mean coefficient (3.18)");
  sub->add_option("--vessel", r.vessel, "With --apply: vessel file (default: built-in Gunnerus)")
      ->check(CLI::ExistingFile);
  output_file(
      sub->add_option("--out", o->out, "With --apply: CSV to write (time, rpm.NAME, thrust.NAME)"));
  sub->footer(
      "Back-calculation: for each sign of n, c = Σ T n² / Σ n⁴ (least squares through the "
      "origin), with 1σ from the residuals. Values in N/rps² in JSON (c_pos, c_neg, c_mean), "
      "kN/rps² in the table (thesis table 3.2: 8.13 / -5.8). Example: dynpos identify "
      "thrust-map DIR/log.csv --json map.json");
  sub->callback([o] { run_thrust_map(*o); });
}

}  // namespace dynpos::cli
