// dynpos identify step|thrust-map|agility|four-corner|station-keeping: thesis chapter 3 on any
// CSV log through a column map. `step` is here; the others have a file each.

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/ident/derived_signals.hpp"
#include "dynpos/ident/fit_status.hpp"
#include "dynpos/ident/fopdt_fit.hpp"
#include "dynpos/ident/second_order_fit.hpp"
#include "dynpos/ident/step_detector.hpp"
#include "dynpos/io/column_map.hpp"
#include "dynpos/io/csv_reader.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/report/svg_plot.hpp"
#include "dynpos/report/table.hpp"

namespace dynpos::cli {
namespace {

struct StepOptions {
  std::filesystem::path log;
  std::filesystem::path map_file;
  std::vector<std::string> columns;
  std::vector<std::string> units;
  std::string method = "lsq";
  std::optional<double> t_from, t_to, step_at;
  std::string derive;  // "" or "total-speed"
  std::string json;
  double min_step = 0.0;
  double min_plateau_s = 3.0;
};

core::InputError option_error(const std::string& option, const std::string& problem,
                              const std::string& hint = {}) {
  return core::InputError({{}, {}, {}, option}, problem, hint);
}

nlohmann::json opt_json(const std::optional<double>& v) {
  return v && std::isfinite(*v) ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

nlohmann::json sigma_json(const std::optional<ident::Estimate>& e) {
  return e ? opt_json(e->sigma) : nlohmann::json(nullptr);
}

nlohmann::json warnings_json(const std::vector<ident::FitWarning>& warnings) {
  nlohmann::json out = nlohmann::json::array();
  for (const ident::FitWarning& w : warnings) {
    out.push_back(
        {{"code", std::string(ident::warning_code_name(w.code))}, {"message", w.message}});
  }
  return out;
}

std::string cell(const std::optional<double>& v, const char* spec) {
  return v && std::isfinite(*v) ? fmt::format(fmt::runtime(spec), *v) : std::string("—");
}

std::optional<double> value_of(const std::optional<ident::Estimate>& e) {
  return e ? std::optional<double>(e->value) : std::nullopt;
}

// The log's channels the step analysis needs, in SI.
struct StepSignals {
  std::vector<double> t, input, output, trigger;
  bool has_input = false, has_trigger = false;
  std::string output_unit, input_unit;
};

StepSignals read_signals(const StepOptions& opt) {
  io::ColumnMap map = opt.map_file.empty() ? io::ColumnMap{} : io::load_column_map(opt.map_file);
  io::apply_overrides(map, opt.columns, opt.units);
  if (map.find("time") == nullptr) map.set_column("time", "time");  // our own logs' name
  const bool total_speed = opt.derive == "total-speed";
  if (total_speed) {
    for (const char* role : {"u", "v"}) {
      if (map.find(role) == nullptr) map.set_column(role, role);
    }
  } else if (map.find("output") == nullptr) {
    throw option_error("--col output=COLUMN", "no output column",
                       "map the measured response, e.g. --col output=rpm.stb, or use "
                       "--derive total-speed with u and v");
  }
  const core::Log log = io::read_csv(opt.log, map);
  StepSignals s;
  s.t = log.time();
  if (total_speed) {
    s.output = ident::total_speed(log.values("u"), log.values("v"));  // (3.19)
    s.output_unit = "m/s";
  } else {
    s.output = log.values("output");
    s.output_unit = log.channel("output").unit;
  }
  if (log.has("input")) {
    s.input = log.values("input");
    s.input_unit = log.channel("input").unit;
    s.has_input = true;
  }
  if (log.has("trigger")) {
    s.trigger = log.values("trigger");
    s.has_trigger = true;
  }
  return s;
}

std::vector<ident::Step> find_steps(const StepOptions& opt, const StepSignals& s) {
  ident::StepDetectorOptions d;
  d.min_step = opt.min_step;
  d.min_plateau_s = opt.min_plateau_s;
  const std::vector<double>& u = s.has_input ? s.input : s.trigger;
  d.timing = s.has_input ? ident::StepTiming::kCommand : ident::StepTiming::kTrigger;
  d.input_name = s.has_input ? "input" : "trigger";
  if (opt.t_from || opt.t_to || opt.step_at) {
    const double from = opt.t_from.value_or(s.t.front());
    const double to = opt.t_to.value_or(s.t.back());
    const std::vector<double> none;
    return {ident::step_from_window(s.t, s.has_input || s.has_trigger ? u : none,
                                    {from, to, opt.step_at}, d)};
  }
  if (!s.has_input && !s.has_trigger) {
    throw option_error("--col input=COLUMN", "no input or trigger column to find the steps in",
                       "map the command (--col input=...), a trigger such as power feedback "
                       "(--col trigger=...), or give the window with --from/--to/--step-at");
  }
  return ident::detect_steps(s.t, u, d).steps;
}

void run_step(const StepOptions& opt) {
  const bool second_order = opt.method == "smith2" || opt.method == "rk";
  if (!second_order && opt.method != "lsq" && opt.method != "smith") {
    throw option_error("--method", "unknown method '" + opt.method + "'",
                       "choose lsq (default), smith, smith2 or rk");
  }
  if (!opt.derive.empty() && opt.derive != "total-speed") {
    throw option_error("--derive", "unknown derived output '" + opt.derive + "'",
                       "the one derived output is total-speed, √(u² + v²) (3.19)");
  }
  if (!opt.json.empty() && opt.json != "-") {
    const auto parent = std::filesystem::path(opt.json).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent)) {
      throw option_error("--json", "folder '" + parent.string() + "' does not exist",
                         "create it first, or use --json - for stdout");
    }
  }
  const StepSignals s = read_signals(opt);
  const std::vector<ident::Step> steps = find_steps(opt, s);

  nlohmann::json doc;
  doc["log"] = opt.log.string();
  doc["method"] = opt.method;
  doc["output_unit"] = s.output_unit;
  doc["input_unit"] = s.has_input ? nlohmann::json(s.input_unit) : nlohmann::json(nullptr);
  doc["timing"] = s.has_input ? "command" : (s.has_trigger ? "trigger" : "window");
  doc["steps"] = nlohmann::json::array();
  std::string table =
      fmt::format("{:>9} {:>21} {:>11} {:>11} {:>9} {:>9} {:>9} {:>7}  {}\n", "t_step", "input",
                  "y before", "y after", "K", "T [s]", "δ [s]", "R²", "notes");
  for (const ident::Step& step : steps) {
    nlohmann::json j;
    j["t_step"] = step.t_step;
    j["t_end"] = step.t_end;
    j["u_before"] = opt_json(step.u_before);
    j["u_after"] = opt_json(step.u_after);
    std::optional<double> y0, y1, K, T, delay, r2;
    std::vector<ident::FitWarning> warnings;
    std::string status, message;
    if (!second_order) {
      ident::FopdtFitOptions f;
      f.method =
          opt.method == "smith" ? ident::FopdtMethod::kSmith : ident::FopdtMethod::kLeastSquares;
      const ident::FopdtFitResult r = ident::fit_fopdt(s.t, s.output, step, f);
      y0 = value_of(r.y0);
      if (r.y0 && r.amplitude) y1 = r.y0->value + r.amplitude->value;
      K = r.gain ? std::optional<double>(r.gain->value) : std::nullopt;
      T = value_of(r.time_constant);
      delay = value_of(r.dead_time);
      r2 = r.r_squared;
      warnings = r.warnings;
      status = ident::fit_status_name(r.status);
      message = r.message;
      j["sigma"] = {{"K", sigma_json(r.gain)},
                    {"T", sigma_json(r.time_constant)},
                    {"delay", sigma_json(r.dead_time)}};
      j["K_levels"] = opt_json(r.gain_from_levels);
      j["rms_residual"] = opt_json(r.rms_residual);
    } else {
      ident::SecondOrderFitOptions f;
      f.method = opt.method == "smith2" ? ident::SecondOrderMethod::kSmith
                                        : ident::SecondOrderMethod::kRangaiahKrishnaswamy;
      const ident::SecondOrderFitResult r = ident::fit_second_order(s.t, s.output, step, f);
      y0 = r.y0;
      if (r.y0 && r.amplitude) y1 = *r.y0 + *r.amplitude;
      K = r.gain;
      T = r.time_constant_1;
      delay = r.dead_time;
      r2 = r.r_squared;
      warnings = r.warnings;
      status = ident::fit_status_name(r.status);
      message = r.message;
      j["T1"] = opt_json(r.time_constant_1);
      j["T2"] = opt_json(r.time_constant_2);
      j["damping_ratio"] = opt_json(r.damping_ratio);
    }
    j["y_before"] = opt_json(y0);
    j["y_after"] = opt_json(y1);
    j["K"] = opt_json(K);
    j["T"] = opt_json(T);
    j["delay"] = opt_json(delay);
    j["r_squared"] = opt_json(r2);
    j["status"] = status;
    if (!message.empty()) j["message"] = message;
    j["warnings"] = warnings_json(warnings);
    doc["steps"].push_back(j);
    std::string notes;
    for (const ident::FitWarning& w : warnings) {
      notes += (notes.empty() ? "" : ", ") + std::string(ident::warning_code_name(w.code));
    }
    if (status != "ok") notes = status + (notes.empty() ? "" : ": " + notes);
    table += fmt::format("{:>9.2f} {:>21} {:>11} {:>11} {:>9} {:>9} {:>9} {:>7}  {}\n", step.t_step,
                         cell(step.u_before, "{:.4g}") + " → " + cell(step.u_after, "{:.4g}"),
                         cell(y0, "{:.4g}"), cell(y1, "{:.4g}"), cell(K, "{:.4g}"),
                         cell(T, "{:.2f}"), cell(delay, "{:.2f}"), cell(r2, "{:.3f}"), notes);
  }
  if (!opt.json.empty()) io::write_json(opt.json, doc);
  std::FILE* out = opt.json == "-" ? stderr : stdout;
  fmt::print(
      out, "{}: {} step(s), method {}, output in {} (SI), input in {}\n{}", opt.log.string(),
      steps.size(), opt.method, s.output_unit.empty() ? "1" : s.output_unit,
      s.has_input ? (s.input_unit.empty() ? std::string("1") : s.input_unit) : std::string("—"),
      table);
  if (!opt.json.empty() && opt.json != "-") fmt::print(out, "wrote {}\n", opt.json);
}

}  // namespace

void register_identify(CLI::App& app) {
  CLI::App* identify = app.add_subcommand(
      "identify", "Identify thruster and vessel dynamics from sea-trial logs (thesis ch. 3)");
  identify->require_subcommand(1, 1);

  auto opt = std::make_shared<StepOptions>();
  CLI::App* step = identify->add_subcommand(
      "step", "Step-test identification: FOPDT gain, time constant and dead time per step");
  step->add_option("log", opt->log, "CSV log")->required()->check(CLI::ExistingFile);
  step->add_option("--map", opt->map_file, "Column map (TOML): roles → columns, units, scales")
      ->check(CLI::ExistingFile);
  step->add_option("--col", opt->columns,
                   "ROLE=COLUMN (repeatable): time, input (the command), output (the "
                   "response), trigger (e.g. power feedback, to time steps without a command)");
  step->add_option("--unit", opt->units, "ROLE=UNIT (repeatable), e.g. output=rpm");
  step->add_option("--method", opt->method,
                   "lsq: least squares with the dead time (default); smith: Smith's two-point "
                   "method (3.8)-(3.9); smith2: Smith's second-order 20/60 %; rk: "
                   "Rangaiah-Krishnaswamy 14/55/91 %")
      ->capture_default_str();
  step->add_option("--from", opt->t_from, "Window start [s] (one step in the window)");
  step->add_option("--to", opt->t_to, "Window end [s]");
  step->add_option("--step-at", opt->step_at, "Step time [s] (with or without a window)");
  step->add_option("--derive", opt->derive,
                   "total-speed: fit sqrt(u^2 + v^2) (3.19) from the roles u and v (sway tests)");
  step->add_option("--min-step", opt->min_step,
                   "Smallest input change counted as a step, in the input's SI unit (default: "
                   "from the noise)");
  step->add_option("--min-plateau", opt->min_plateau_s,
                   "Shortest time [s] the input holds a level to count as a step")
      ->capture_default_str();
  step->add_option("--json", opt->json, "Write the results as JSON to FILE, or '-' for stdout");
  step->footer(
      "Finds every step of the input (or trigger) automatically, or takes the window given, and "
      "fits y = y0 + K*du*(1 - exp(-(t - t0 - delay)/T)) (3.7) to the output after each. Values "
      "are SI: y in the output's SI unit, K in output unit per input unit, T and delay in s. "
      "Warnings: steady_state_not_reached, poor_fit, short_window, few_samples, ... "
      "Example on a virtual trial log: dynpos identify step DIR/log.csv "
      "--col input=command.rpm.stb --col output=rpm.stb");
  step->callback([opt] { run_step(*opt); });

  add_identify_thrust_map(*identify);
  add_identify_agility(*identify);
  add_identify_four_corner(*identify);
  add_identify_station_keeping(*identify);
}

namespace {

// One step test of the campaign, shaped like a table of thesis 3.23–3.31.
struct StepDemoTest {
  const char* scenario;
  const char* id;          // file stem under analysis/steps/
  const char* quantity;    // what the table is about
  const char* input;       // column of the command the steps are found in
  const char* output;      // column fitted; "" with total_speed
  bool total_speed;        // fit √(u² + v²) (3.19) instead of `output`
  const char* truth;       // "shaft_speed"/"thrust" (propeller_steps), "nomoto" (rudder_steps), ""
  const char* thesis;      // the thesis' figures for comparison (DESIGN.md calibration table)
  const char* input_unit;  // the input as the trial logger shows it ...
  double input_scale;      // ... = SI value × this
};

constexpr StepDemoTest kStepDemoTests[] = {
    {"surge-steps-forward", "surge-forward_rpm", "Shaft speed, starboard propeller",
     "command.rpm.stb", "rpm.stb", false, "shaft_speed",
     "table 3.23: T_n 0.5–5.5 s, δ_n 1.2–3.3 s; larger steps slower", "rpm", 60.0},
    {"surge-steps-forward", "surge-forward_thrust", "Thrust, starboard propeller",
     "command.rpm.stb", "thrust.stb", false, "thrust", "table 3.23: T 0.3–4.7 s, δ 1–5.6 s", "rpm",
     60.0},
    {"surge-steps-forward", "surge-forward_speed", "Surge speed u", "lever.surge", "u", false, "",
     "table 3.24: T 16 s (0–80 %), 34 s (25–40 %), 59 s (15–25 %), 60–135 s (small steps)", "%",
     100.0},
    {"surge-steps-backward", "surge-backward_rpm", "Shaft speed, starboard propeller",
     "command.rpm.stb", "rpm.stb", false, "shaft_speed",
     "table 3.25: T_n 0.5–5.5 s, δ_n 1.2–3.3 s; larger steps slower", "rpm", 60.0},
    {"surge-steps-backward", "surge-backward_thrust", "Thrust, starboard propeller",
     "command.rpm.stb", "thrust.stb", false, "thrust", "table 3.25: T 0.3–4.7 s, δ 1–5.6 s", "rpm",
     60.0},
    {"surge-steps-backward", "surge-backward_speed", "Surge speed u", "lever.surge", "u", false, "",
     "table 3.26: T 31–77 s (backward)", "%", 100.0},
    {"sway-steps-starboard", "sway-starboard_speed", "Total speed √(u² + v²) (3.19)", "lever.sway",
     "", true, "", "table 3.28: T 9–19 s, δ 1–4 s; larger steps faster", "%", 100.0},
    {"sway-steps-port", "sway-port_speed", "Total speed √(u² + v²) (3.19)", "lever.sway", "", true,
     "", "table 3.30: T 9–19 s, δ 1–4 s; larger steps faster", "%", 100.0},
    {"yaw-steps", "yaw_rate", "Yaw rate r (MRU 1), starboard rudder steps", "command.rudder.stb",
     "mru1.r", false, "nomoto",
     "table 3.31 (rudder 0→20°): T 4.7–5.6 s at 3 kn, 2.9–3.0 s at 6 kn, δ ≈ 2 s", "deg",
     57.29577951308232},
};

struct TruthValue {
  std::optional<double> T_s, delay_s;
};

// The truth of the step at `t_step`: the nearest step of truth.json within 1 s (the command is
// logged at the step time; 1 s is far below the shortest spacing of steps, 60 s).
TruthValue truth_for(const nlohmann::json& truth, const StepDemoTest& test, double t_step) {
  TruthValue out;
  if (std::string(test.truth).empty() || truth.is_null()) return out;
  const bool rudder = std::string(test.truth) == "nomoto";
  const char* list = rudder ? "rudder_steps" : "propeller_steps";
  if (!truth.contains(list)) return out;
  for (const nlohmann::json& s : truth.at(list)) {
    if (!rudder && s.value("thruster", "") != "stb") continue;
    if (std::abs(s.value("t_s", -1e9) - t_step) > 1.0) continue;
    if (rudder) {
      // Nomoto's first-order yaw-rate time constant (truth.json "Tr_s"); the dead time of the
      // yaw-rate response has no single truth (servo + hull), so it stays missing.
      if (s.contains("nomoto") && s.at("nomoto").contains("Tr_s")) {
        out.T_s = s.at("nomoto").at("Tr_s").get<double>();
      }
    } else if (s.contains(test.truth)) {
      out.T_s = s.at(test.truth).at("T_s").get<double>();
      out.delay_s = s.at(test.truth).at("delay_s").get<double>();
    }
    break;
  }
  return out;
}

std::string step_cell(const std::optional<double>& v, const char* spec) {
  return v && std::isfinite(*v) ? fmt::format(fmt::runtime(spec), *v) : std::string("—");
}

struct StepDemoOutcome {
  report::Table table;
  std::string plot;  // file name under analysis/steps/, or empty
  std::size_t steps = 0, with_truth = 0;
  double worst_error_pct = 0.0;
};

StepDemoOutcome run_step_demo_test(const std::filesystem::path& campaign_dir,
                                   const StepDemoTest& test, const std::filesystem::path& out_dir) {
  const std::filesystem::path run_dir = campaign_dir / test.scenario;
  io::ColumnMap map;
  map.set_column("time", "time");
  map.set_column("input", test.input);
  if (test.total_speed) {
    map.set_column("u", "u");
    map.set_column("v", "v");
  } else {
    map.set_column("output", test.output);
  }
  const core::Log log = io::read_csv(run_dir / "log.csv", map);
  const std::vector<double>& t = log.time();
  const std::vector<double> y =
      test.total_speed ? ident::total_speed(log.values("u"), log.values("v"))  // (3.19)
                       : log.values("output");
  const std::string y_unit = test.total_speed ? "m/s" : log.channel("output").unit;
  const std::string u_unit = log.channel("input").unit;
  nlohmann::json truth;
  if (std::ifstream in(run_dir / "truth.json"); in) truth = nlohmann::json::parse(in);

  // Smith's two-point method (3.8)-(3.9): the method that defines truth.json's time constants.
  ident::FopdtFitOptions f;
  f.method = ident::FopdtMethod::kSmith;
  const std::vector<ident::Step> steps = ident::detect_steps(t, log.values("input")).steps;

  const auto in_logger_unit = [&test](const std::optional<double>& v) {
    return v ? std::optional<double>(*v * test.input_scale) : std::nullopt;
  };
  StepDemoOutcome out;
  out.table.header = {"t_step [s]",  fmt::format("input [{}]", test.input_unit),
                      "T [s]",       "δ [s]",
                      "R²",          "T truth [s]",
                      "δ truth [s]", "T error [%]",
                      "status"};
  out.table.first_numeric_column = 0;
  nlohmann::json doc;
  doc["analysis"] = "step";
  doc["log"] = std::string(test.scenario) + "/log.csv";  // relative: the report is relocatable
  doc["method"] = "smith";
  doc["quantity"] = test.quantity;
  doc["output_unit"] = y_unit;
  doc["input_unit"] = u_unit;
  doc["thesis"] = test.thesis;
  doc["steps"] = nlohmann::json::array();
  std::vector<double> fit_t, fit_y, markers;
  for (const ident::Step& step : steps) {
    const ident::FopdtFitResult r = ident::fit_fopdt(t, y, step, f);
    const TruthValue tv = truth_for(truth, test, step.t_step);
    const std::optional<double> T = value_of(r.time_constant), delay = value_of(r.dead_time);
    std::optional<double> err;
    if (T && tv.T_s && *tv.T_s > 0.0) {
      err = 100.0 * (*T - *tv.T_s) / *tv.T_s;
      out.worst_error_pct = std::max(out.worst_error_pct, std::abs(*err));
      ++out.with_truth;
    }
    ++out.steps;
    std::string notes(ident::fit_status_name(r.status));
    for (const ident::FitWarning& w : r.warnings) {
      notes += (notes.empty() ? "" : ", ") + std::string(ident::warning_code_name(w.code));
    }
    nlohmann::json j;
    j["t_step"] = step.t_step;
    j["u_before"] = opt_json(step.u_before);
    j["u_after"] = opt_json(step.u_after);
    j["T"] = opt_json(T);
    j["delay"] = opt_json(delay);
    j["K"] = r.gain ? nlohmann::json(r.gain->value) : nlohmann::json(nullptr);
    j["r_squared"] = opt_json(r.r_squared);
    j["status"] = std::string(ident::fit_status_name(r.status));
    j["warnings"] = warnings_json(r.warnings);
    j["truth"] = {{"T", opt_json(tv.T_s)}, {"delay", opt_json(tv.delay_s)}};
    j["T_error_pct"] = opt_json(err);
    doc["steps"].push_back(j);
    out.table.rows.push_back({fmt::format("{:.1f}", step.t_step),
                              step_cell(in_logger_unit(step.u_before), "{:.4g}") + " → " +
                                  step_cell(in_logger_unit(step.u_after), "{:.4g}"),
                              step_cell(T, "{:.2f}"), step_cell(delay, "{:.2f}"),
                              step_cell(r.r_squared, "{:.3f}"), step_cell(tv.T_s, "{:.2f}"),
                              step_cell(tv.delay_s, "{:.2f}"), step_cell(err, "{:+.1f}"), notes});
    // The fitted FOPDT (3.7) over the step's window, for the plot; gaps between steps.
    markers.push_back(step.t_step);
    if (const auto model = r.model()) {
      for (std::size_t i = 0; i < t.size(); ++i) {
        if (t[i] < step.t_begin || t[i] > step.t_end) continue;
        fit_t.push_back(t[i]);
        fit_y.push_back((*model)(t[i]));
      }
      fit_t.push_back(std::nan(""));
      fit_y.push_back(std::nan(""));
    }
  }
  io::write_json((out_dir / (std::string(test.id) + ".json")).string(), doc);

  report::Figure fig;
  fig.title = fmt::format("{}: {} — data and fitted FOPDT (3.7)", test.scenario, test.quantity);
  report::Panel panel;
  panel.x_axis = {"Time", "s", {}, {}};
  panel.y_axis = {test.quantity, y_unit, {}, {}};
  panel.series.push_back({"logged", t, y, "#1f77b4", 1.0, false});
  panel.series.push_back({"FOPDT fit (Smith)", fit_t, fit_y, "#d62728", 1.5, true});
  panel.x_markers = markers;
  fig.panels.push_back(std::move(panel));
  out.plot = std::string(test.id) + ".svg";
  report::write_svg(out_dir / out.plot, fig);
  return out;
}

}  // namespace

scenario::ReportSection step_demo_section(const std::filesystem::path& campaign_dir) {
  const std::filesystem::path out_dir = campaign_dir / "analysis" / "steps";
  scenario::ReportSection section;
  std::string md, html;
  for (const StepDemoTest& test : kStepDemoTests) {
    if (!std::filesystem::exists(campaign_dir / test.scenario / "log.csv")) continue;
    std::filesystem::create_directories(out_dir);
    const StepDemoOutcome o = run_step_demo_test(campaign_dir, test, out_dir);
    const std::string head = fmt::format("{} — {} ({} step(s)); thesis {}.", test.scenario,
                                         test.quantity, o.steps, test.thesis);
    std::string note;
    if (std::string(test.truth) == "nomoto") {
      note =
          " T truth is Nomoto's T_r = T1 + T2 − T3 (truth.json) at the speed of each step; a "
          "FOPDT fit from the rudder command includes the servo ramp and the speed loss in "
          "the turn, so it is not expected to equal T_r.";
    }
    if (o.with_truth > 0) {
      note += fmt::format(" Largest |T error| against truth.json: {:.1f} % over {} step(s).",
                          o.worst_error_pct, o.with_truth);
    }
    const std::string rel = "analysis/steps/" + o.plot;
    md += fmt::format("**{}**{}\n\n{}\n![{}]({})\n\n", head, note, report::render_markdown(o.table),
                      o.plot, rel);
    html += fmt::format("<p><b>{}</b>{}</p>\n{}<p><img src=\"{}\" alt=\"{}\"></p>\n", head, note,
                        report::render_html(o.table), rel, o.plot);
  }
  if (md.empty()) return section;
  section.title = "Step tests: time constants and dead times (thesis tables 3.23–3.31)";
  const std::string intro =
      "FOPDT (3.7) fitted by Smith's two-point method (3.8)-(3.9) to each step the command "
      "columns show; the truth is the simulator's own response evaluated the same way. Data and "
      "fits: analysis/steps/*.json and *.svg.";
  section.markdown = intro + "\n\n" + md;
  section.html = "<p>" + intro + "</p>\n" + html;
  return section;
}

}  // namespace dynpos::cli
