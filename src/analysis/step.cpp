#include "dynpos/analysis/step.hpp"

#include <fmt/core.h>

#include "dynpos/analysis/json_fields.hpp"
#include "dynpos/analysis/options.hpp"
#include "dynpos/core/log.hpp"
#include "dynpos/ident/derived_signals.hpp"
#include "dynpos/ident/fopdt_fit.hpp"
#include "dynpos/ident/second_order_fit.hpp"
#include "dynpos/io/column_map.hpp"
#include "dynpos/io/csv_reader.hpp"

namespace dynpos::analysis {
namespace {

bool is_second_order(const std::string& method) { return method == "smith2" || method == "rk"; }

// The log's channels the step analysis needs, in SI.
struct StepSignals {
  std::vector<double> t, input, output, trigger;
  bool has_input = false, has_trigger = false;
  std::string output_unit, input_unit;
};

StepSignals read_signals(const StepRequest& request) {
  const LogSource& src = request.source;
  io::ColumnMap map = src.base_map();
  const bool total_speed = request.derive == "total-speed";
  if (total_speed) {
    for (const char* role : {"u", "v"}) {
      if (map.find(role) == nullptr) map.set_column(role, role);
    }
  } else if (map.find("output") == nullptr) {
    throw option_error("col:output", "no output column",
                       "map the measured response, e.g. --col output=rpm.stb, or use "
                       "--derive total-speed with u and v");
  }
  const core::Log log = io::read_csv(src.log, map);
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

std::vector<ident::Step> find_steps(const StepRequest& request, const StepSignals& s) {
  ident::StepDetectorOptions d;
  d.min_step = request.min_step;
  d.min_plateau_s = request.min_plateau_s;
  const std::vector<double>& u = s.has_input ? s.input : s.trigger;
  d.timing = s.has_input ? ident::StepTiming::kCommand : ident::StepTiming::kTrigger;
  d.input_name = s.has_input ? "input" : "trigger";
  if (request.from_s || request.to_s || request.step_at_s) {
    const double from = request.from_s.value_or(s.t.front());
    const double to = request.to_s.value_or(s.t.back());
    const std::vector<double> none;
    return {ident::step_from_window(s.t, s.has_input || s.has_trigger ? u : none,
                                    {from, to, request.step_at_s}, d)};
  }
  if (!s.has_input && !s.has_trigger) {
    throw option_error("col:input", "no input or trigger column to find the steps in",
                       "map the command (--col input=...), a trigger such as power feedback "
                       "(--col trigger=...), or give the window with --from/--to/--step-at");
  }
  return ident::detect_steps(s.t, u, d).steps;
}

// FOPDT (3.7) by least squares or Smith's two-point method (3.8)-(3.9).
StepFit fit_first_order(const std::string& method, const StepSignals& s, const ident::Step& step) {
  ident::FopdtFitOptions f;
  f.method = method == "smith" ? ident::FopdtMethod::kSmith : ident::FopdtMethod::kLeastSquares;
  const ident::FopdtFitResult r = ident::fit_fopdt(s.t, s.output, step, f);
  StepFit out;
  out.step = step;
  out.y_before = value_of(r.y0);
  if (r.y0 && r.amplitude) out.y_after = r.y0->value + r.amplitude->value;
  out.gain = value_of(r.gain);
  out.time_constant_s = value_of(r.time_constant);
  out.dead_time_s = value_of(r.dead_time);
  out.r_squared = r.r_squared;
  out.status = r.status;
  out.message = r.message;
  out.warnings = r.warnings;
  const auto sigma = [](const std::optional<ident::Estimate>& e) {
    return e ? e->sigma : std::nullopt;
  };
  out.fopdt = FopdtFitDetails{sigma(r.gain), sigma(r.time_constant), sigma(r.dead_time),
                              r.gain_from_levels, r.rms_residual};
  return out;
}

// Second order plus dead time by Smith's 20/60 % or Rangaiah-Krishnaswamy's 14/55/91 % points.
StepFit fit_second_order(const std::string& method, const StepSignals& s, const ident::Step& step) {
  ident::SecondOrderFitOptions f;
  f.method = method == "smith2" ? ident::SecondOrderMethod::kSmith
                                : ident::SecondOrderMethod::kRangaiahKrishnaswamy;
  const ident::SecondOrderFitResult r = ident::fit_second_order(s.t, s.output, step, f);
  StepFit out;
  out.step = step;
  out.y_before = r.y0;
  if (r.y0 && r.amplitude) out.y_after = *r.y0 + *r.amplitude;
  out.gain = r.gain;
  out.time_constant_s = r.time_constant_1;
  out.dead_time_s = r.dead_time;
  out.r_squared = r.r_squared;
  out.status = r.status;
  out.message = r.message;
  out.warnings = r.warnings;
  out.second_order = SecondOrderFitDetails{r.time_constant_1, r.time_constant_2, r.damping_ratio};
  return out;
}

}  // namespace

void StepRequest::validate() const {
  if (!is_second_order(method) && method != "lsq" && method != "smith") {
    throw option_error("method", "unknown method '" + method + "'",
                       "choose lsq (default), smith, smith2 or rk");
  }
  if (!derive.empty() && derive != "total-speed") {
    throw option_error("derive", "unknown derived output '" + derive + "'",
                       "the one derived output is total-speed, √(u² + v²) (3.19)");
  }
}

std::string_view timing_name(StepTimingSource timing) {
  switch (timing) {
    case StepTimingSource::kCommand:
      return "command";
    case StepTimingSource::kTrigger:
      return "trigger";
    case StepTimingSource::kWindow:
      return "window";
  }
  return "window";
}

StepReport run_step(const StepRequest& request) {
  request.validate();
  const StepSignals s = read_signals(request);
  const std::vector<ident::Step> steps = find_steps(request, s);
  StepReport report;
  report.log = request.source.log;
  report.method = request.method;
  report.output_unit = s.output_unit;
  if (s.has_input) report.input_unit = s.input_unit;
  report.timing = s.has_input     ? StepTimingSource::kCommand
                  : s.has_trigger ? StepTimingSource::kTrigger
                                  : StepTimingSource::kWindow;
  for (const ident::Step& step : steps) {
    report.steps.push_back(is_second_order(request.method)
                               ? fit_second_order(request.method, s, step)
                               : fit_first_order(request.method, s, step));
  }
  return report;
}

nlohmann::json to_json(const StepReport& report) {
  nlohmann::json doc;
  doc["log"] = report.log.string();
  doc["method"] = report.method;
  doc["output_unit"] = report.output_unit;
  doc["input_unit"] =
      report.input_unit ? nlohmann::json(*report.input_unit) : nlohmann::json(nullptr);
  doc["timing"] = std::string(timing_name(report.timing));
  doc["steps"] = nlohmann::json::array();
  for (const StepFit& fit : report.steps) {
    nlohmann::json j;
    j["t_step"] = fit.step.t_step;
    j["t_end"] = fit.step.t_end;
    j["u_before"] = number_json(fit.step.u_before);
    j["u_after"] = number_json(fit.step.u_after);
    if (fit.fopdt) {
      const FopdtFitDetails& d = *fit.fopdt;
      j["sigma"] = {{"K", number_json(d.gain_sigma)},
                    {"T", number_json(d.time_constant_sigma_s)},
                    {"delay", number_json(d.dead_time_sigma_s)}};
      j["K_levels"] = number_json(d.gain_from_levels);
      j["rms_residual"] = number_json(d.rms_residual);
    }
    if (fit.second_order) {
      j["T1"] = number_json(fit.second_order->time_constant_1_s);
      j["T2"] = number_json(fit.second_order->time_constant_2_s);
      j["damping_ratio"] = number_json(fit.second_order->damping_ratio);
    }
    j["y_before"] = number_json(fit.y_before);
    j["y_after"] = number_json(fit.y_after);
    j["K"] = number_json(fit.gain);
    j["T"] = number_json(fit.time_constant_s);
    j["delay"] = number_json(fit.dead_time_s);
    j["r_squared"] = number_json(fit.r_squared);
    j["status"] = std::string(ident::fit_status_name(fit.status));
    if (!fit.message.empty()) j["message"] = fit.message;
    j["warnings"] = warnings_json(fit.warnings);
    doc["steps"].push_back(j);
  }
  return doc;
}

std::string to_text(const StepReport& report) {
  std::string text = fmt::format(
      "{}: {} step(s), method {}, output in {} (SI), input in {}\n", report.log.string(),
      report.steps.size(), report.method, report.output_unit.empty() ? "1" : report.output_unit,
      report.input_unit ? (report.input_unit->empty() ? std::string("1") : *report.input_unit)
                        : std::string("—"));
  text += fmt::format("{:>9} {:>21} {:>11} {:>11} {:>9} {:>9} {:>9} {:>7}  {}\n", "t_step", "input",
                      "y before", "y after", "K", "T [s]", "δ [s]", "R²", "notes");
  for (const StepFit& fit : report.steps) {
    const std::string status(ident::fit_status_name(fit.status));
    std::string notes;
    for (const ident::FitWarning& w : fit.warnings) {
      notes += (notes.empty() ? "" : ", ") + std::string(ident::warning_code_name(w.code));
    }
    if (status != "ok") notes = status + (notes.empty() ? "" : ": " + notes);
    text += fmt::format(
        "{:>9.2f} {:>21} {:>11} {:>11} {:>9} {:>9} {:>9} {:>7}  {}\n", fit.step.t_step,
        number_cell(fit.step.u_before, "{:.4g}") + " → " + number_cell(fit.step.u_after, "{:.4g}"),
        number_cell(fit.y_before, "{:.4g}"), number_cell(fit.y_after, "{:.4g}"),
        number_cell(fit.gain, "{:.4g}"), number_cell(fit.time_constant_s, "{:.2f}"),
        number_cell(fit.dead_time_s, "{:.2f}"), number_cell(fit.r_squared, "{:.3f}"), notes);
  }
  return text;
}

}  // namespace dynpos::analysis
