// The step analysis' report: its JSON document, its text table and its outputs.

#include <fmt/core.h>

#include "dynpos/analysis/json_fields.hpp"
#include "dynpos/analysis/step.hpp"

namespace dynpos::analysis {

nlohmann::json to_json(const StepReport& report) {
  nlohmann::json doc;
  doc["log"] = report.log.string();
  doc["input"] = io::to_json(report.input);
  doc["method"] = to_string(report.method);
  doc["output_unit"] = report.output_unit;
  doc["input_unit"] =
      report.input_unit ? nlohmann::json(*report.input_unit) : nlohmann::json(nullptr);
  doc["timing"] = std::string(timing_name(report.timing));
  doc["step_threshold"] = number_json(report.step_threshold);
  doc["step_threshold_source"] = report.threshold_from_min_step ? "min_step" : "auto";
  doc["input_noise_sigma"] = number_json(report.input_noise_sigma);
  if (!report.segments_file.empty()) doc["segments"] = report.segments_file.string();
  doc["notes"] = report.notes;
  doc["steps"] = nlohmann::json::array();
  for (const StepFit& fit : report.steps) {
    nlohmann::json j;
    j["t_step"] = fit.step.t_step;
    j["t_end"] = fit.step.t_end;
    if (!report.segments_file.empty()) j["segment"] = fit.segment;
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

namespace {

// Why the table is empty, and what to try: no step is a result (exit 0), said in words.
std::string no_step_text(const StepReport& report) {
  const std::string reason =
      report.notes.size() == 1 ? report.notes.front()
      : !report.notes.empty()  ? "see the notes above"
      : report.step_threshold
          ? fmt::format("none of the input's changes reaches the step threshold {:.4g}",
                        *report.step_threshold)
          : "no change of the input is a step";
  return fmt::format(
      "no step found: {}; lower --min-step, or give the step with --from/--to/--step-at\n", reason);
}

}  // namespace

std::string to_text(const StepReport& report) {
  std::string text = fmt::format(
      "{}: {} step(s), method {}, output in {} (SI), input in {}\n", report.log.string(),
      report.steps.size(), to_string(report.method),
      report.output_unit.empty() ? "1" : report.output_unit,
      report.input_unit ? (report.input_unit->empty() ? std::string("1") : *report.input_unit)
                        : std::string("—"));
  if (report.step_threshold) {
    text += fmt::format("step threshold {:.4g} ({}), input noise σ̂ {}\n", *report.step_threshold,
                        report.threshold_from_min_step ? "--min-step" : "adapted to the log",
                        number_cell(report.input_noise_sigma, "{:.3g}"));
  }
  if (!report.segments_file.empty())
    text += "segments from " + report.segments_file.string() + "\n";
  for (const std::string& note : report.notes) text += "note: " + note + "\n";
  if (report.steps.empty()) {
    text += no_step_text(report);
    return text + io::to_text(report.input);
  }
  const bool segments = !report.segments_file.empty();
  text += fmt::format("{}{:>9} {:>21} {:>11} {:>11} {:>9} {:>9} {:>9} {:>7}  {}\n",
                      segments ? fmt::format("{:<16} ", "segment") : "", "t_step", "input",
                      "y before", "y after", "K", "T [s]", "δ [s]", "R²", "notes");
  for (const StepFit& fit : report.steps) {
    const std::string status(ident::fit_status_name(fit.status));
    std::string notes;
    for (const ident::FitWarning& w : fit.warnings) {
      notes += (notes.empty() ? "" : ", ") + std::string(ident::warning_code_name(w.code));
    }
    // A step that is not ok says why: its status, the reason, then the warnings.
    if (status != "ok") {
      notes = status + ": " + fit.message + (notes.empty() ? "" : " [" + notes + "]");
    }
    text += fmt::format(
        "{}{:>9.2f} {:>21} {:>11} {:>11} {:>9} {:>9} {:>9} {:>7}  {}\n",
        segments ? fmt::format("{:<16} ", fit.segment) : "", fit.step.t_step,
        number_cell(fit.step.u_before, "{:.4g}") + " → " + number_cell(fit.step.u_after, "{:.4g}"),
        number_cell(fit.y_before, "{:.4g}"), number_cell(fit.y_after, "{:.4g}"),
        number_cell(fit.gain, "{:.4g}"), number_cell(fit.time_constant_s, "{:.2f}"),
        number_cell(fit.dead_time_s, "{:.2f}"), number_cell(fit.r_squared, "{:.3f}"), notes);
  }
  return text + io::to_text(report.input);
}

Written write_outputs(const StepReport& report, const Outputs& outputs) {
  Written written;
  write_json_output(outputs, to_json(report), written);
  return written;
}

}  // namespace dynpos::analysis
