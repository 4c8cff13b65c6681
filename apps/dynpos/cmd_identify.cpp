// dynpos identify step|thrust-map|agility|four-corner|station-keeping: thesis chapter 3 on any
// CSV log through a column map. `step` is here; the others have a file each.

#include <fmt/core.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
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

scenario::ReportSection step_demo_section(const std::filesystem::path& /*campaign_dir*/) {
  return {};
}

}  // namespace dynpos::cli
