#include "dynpos/analysis/step.hpp"
#include "dynpos/analysis/enum_names.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>

#include "dynpos/analysis/json_fields.hpp"
#include "dynpos/analysis/log_source.hpp"
#include "dynpos/analysis/options.hpp"
#include "dynpos/core/log.hpp"
#include "dynpos/core/parallel_for.hpp"
#include "dynpos/ident/derived_signals.hpp"
#include "dynpos/ident/fopdt_fit.hpp"
#include "dynpos/ident/second_order_fit.hpp"
#include "dynpos/io/segments.hpp"

namespace dynpos::analysis {
namespace {

bool is_second_order(StepMethod method) {
  return method == StepMethod::kSmithSecondOrder || method == StepMethod::kRangaiahKrishnaswamy;
}

// The log's channels the step analysis needs, in SI.
// Views into the loaded log (no copy of a day-long log), or into `derived` for the total speed.
struct StepSignals {
  core::Log log;
  std::vector<double> derived;
  std::span<const double> t, input, output, trigger;
  double log_start_s = 0.0, log_end_s = 0.0;  // how far the file reaches (LoadedLog)
  bool has_input = false, has_trigger = false;
  std::string output_unit, input_unit;
  io::InputReport read;  // what was read
};

StepSignals read_signals(const StepRequest& request) {
  // The window is the source's: only its rows are read (the step threshold is then the
  // window's), and LogSource::load judges it.
  LogSource src = request.source;
  src.window_from_s = request.from_s;
  src.window_to_s = request.to_s;
  const bool total_speed = request.derive == StepDerive::kTotalSpeed;
  // Only the step roles are picked up by name: u and v for the total speed (3.19), else the
  // input, output and trigger the user mapped.
  const RoleFilter wanted = [total_speed](const std::string& role) {
    return total_speed && (role == "u" || role == "v");
  };
  if (!total_speed && !src.gives("output", wanted)) {
    throw option_error("col:output", "no output column",
                       "map the measured response, e.g. --col output=rpm.stb, or use "
                       "--derive total-speed with u and v");
  }
  LoadedLog loaded = src.load(wanted);
  StepSignals s;
  s.log = std::move(loaded.log);
  s.log_start_s = loaded.log_start_s;
  s.log_end_s = loaded.log_end_s;
  const core::Log& log = s.log;
  if (total_speed && !(log.has("u") && log.has("v"))) {
    throw src.error("u, v", "no surge and sway speed columns",
                    "map them, e.g. --col u=SOG_surge --col v=SOG_sway");
  }
  s.read = std::move(loaded.input);
  s.t = log.time();
  if (total_speed) {
    s.derived = ident::total_speed(log.values("u"), log.values("v"));  // (3.19)
    s.output = s.derived;
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

ident::StepDetectorOptions detector_options(const StepRequest& request, const StepSignals& s) {
  ident::StepDetectorOptions d;
  d.min_step = request.min_step;
  d.min_plateau_s = request.min_plateau_s;
  d.timing = s.has_input ? ident::StepTiming::kCommand : ident::StepTiming::kTrigger;
  d.input_name = s.has_input ? "input" : "trigger";
  d.jobs = request.source.jobs;
  return d;
}

// A step found in a stretch of the log, and the segment it belongs to.
struct FoundStep {
  ident::Step step;
  std::string segment;
};

// The steps of each segment (--segments), on the whole log's threshold; why a segment has none
// goes to `notes`.
std::vector<FoundStep> detect_in_segments(const StepRequest& request, const StepSignals& s,
                                          const ident::StepDetectorOptions& d,
                                          const ident::StepThreshold& scale,
                                          std::vector<std::string>& notes) {
  const std::span<const double> u = s.has_input ? s.input : s.trigger;
  std::vector<FoundStep> found;
  const std::span<const double> t = s.t;
  for (const io::Segment& seg : io::read_segments(request.segments_file)) {
    const auto i0 =
        static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), seg.start_s) - t.begin());
    const auto i1 =
        static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), seg.end_s) - t.begin());
    const std::span<const double> useg = u.subspan(i0, i1 - i0);
    const auto valid =
        std::count_if(useg.begin(), useg.end(), [](double x) { return !std::isnan(x); });
    const std::string where = "segment '" + seg.name + "' [" + fmt::format("{:g}", seg.start_s) +
                              ", " + fmt::format("{:g}", seg.end_s) + "] s";
    if (valid < 3) {
      notes.push_back(where + ": fewer than 3 valid input samples in the log");
      continue;
    }
    const ident::StepDetection r = ident::detect_steps(t.subspan(i0, i1 - i0), useg, d, scale);
    if (!r.message.empty()) notes.push_back(where + ": " + r.message);
    for (const ident::Step& step : r.steps) found.push_back({step, seg.name});
  }
  return found;
}

// The steps of the whole log, its threshold found in the same pass over the input (as
// step_threshold() would find it).
std::vector<FoundStep> detect_in_whole_log(const StepSignals& s, std::span<const double> u,
                                           const ident::StepDetectorOptions& d,
                                           StepReport& report) {
  const ident::StepDetection r = ident::detect_steps(s.log, u, d);
  report.step_threshold = r.threshold;
  report.threshold_from_min_step = d.min_step > 0.0;
  report.input_noise_sigma = r.noise_sigma;
  if (!r.message.empty()) report.notes.push_back(r.message);
  std::vector<FoundStep> found;
  for (const ident::Step& step : r.steps) found.push_back({step, ""});
  return found;
}

// Finds the steps and sets the report's threshold and notes.
std::vector<FoundStep> find_steps(const StepRequest& request, const StepSignals& s,
                                  StepReport& report) {
  ident::StepDetectorOptions d = detector_options(request, s);
  const std::span<const double> u = s.has_input ? s.input : s.trigger;
  const bool window = request.from_s || request.to_s || request.step_at_s;
  if (!s.has_input && !s.has_trigger && !window) {
    throw option_error("col:input", "no input or trigger column to find the steps in",
                       "map the command (--col input=...), a trigger such as power feedback "
                       "(--col trigger=...), or give the window with --from/--to/--step-at");
  }
  ident::StepThreshold scale;
  if ((s.has_input || s.has_trigger) && !request.step_at_s) {
    if (!window && request.segments_file.empty()) return detect_in_whole_log(s, u, d, report);
    // One threshold for what was read (the whole log, or the window), whatever stretch of it
    // is searched (a segment).
    scale = ident::step_threshold(s.t, u, d);
    report.step_threshold = scale.threshold;
    report.threshold_from_min_step = scale.from_min_step;
    report.input_noise_sigma = scale.noise_sigma;
    d.min_step = scale.threshold;
    d.band = scale.band;
  }
  if (window) {
    if (s.t.empty()) throw core::InputError({"", {}, {}, "time"}, "the log has no rows", "");
    const double from = request.from_s.value_or(s.t.front());
    const double to = request.to_s.value_or(s.t.back());
    return {
        {ident::step_from_window(s.t, s.has_input || s.has_trigger ? u : std::span<const double>(),
                                 {from, to, request.step_at_s, s.log_start_s, s.log_end_s}, d),
         ""}};
  }
  return detect_in_segments(request, s, d, scale, report.notes);
}

// FOPDT (3.7) by least squares or Smith's two-point method (3.8)-(3.9).
StepFit fit_first_order(StepMethod method, const StepSignals& s, const ident::Step& step) {
  ident::FopdtFitOptions f;
  f.method =
      method == StepMethod::kSmith ? ident::FopdtMethod::kSmith : ident::FopdtMethod::kLeastSquares;
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
StepFit fit_second_order(StepMethod method, const StepSignals& s, const ident::Step& step) {
  ident::SecondOrderFitOptions f;
  f.method = method == StepMethod::kSmithSecondOrder
                 ? ident::SecondOrderMethod::kSmith
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

const std::vector<std::pair<std::string, StepMethod>>& step_method_names() {
  static const std::vector<std::pair<std::string, StepMethod>> names = {
      {"lsq", StepMethod::kLeastSquares},
      {"smith", StepMethod::kSmith},
      {"smith2", StepMethod::kSmithSecondOrder},
      {"rk", StepMethod::kRangaiahKrishnaswamy}};
  return names;
}

const std::vector<std::pair<std::string, StepDerive>>& step_derive_names() {
  static const std::vector<std::pair<std::string, StepDerive>> names = {
      {"", StepDerive::kNone}, {"total-speed", StepDerive::kTotalSpeed}};
  return names;
}

StepMethod step_method_from_name(const std::string& name) {
  return enum_by_name(step_method_names(), name, "method");
}

StepDerive step_derive_from_name(const std::string& name) {
  return enum_by_name(step_derive_names(), name, "derive");
}

std::string to_string(StepMethod method) {
  for (const auto& [name, m] : step_method_names()) {
    if (m == method) return name;
  }
  return "lsq";
}

std::string to_string(StepDerive derive) {
  return derive == StepDerive::kTotalSpeed ? "total-speed" : "";
}

void StepRequest::validate() const {
  if (!std::isfinite(min_step) || min_step < 0.0) {
    throw option_error("min_step", fmt::format("the smallest step must be ≥ 0, got {}", min_step),
                       "give it in the input's SI unit, or 0 to adapt it to the log");
  }
  if (!std::isfinite(min_plateau_s) || min_plateau_s <= 0.0) {
    throw option_error("min_plateau",
                       fmt::format("the shortest plateau must be > 0 s, got {}", min_plateau_s),
                       "give the time [s] the input holds a level to count as a step");
  }
  for (const auto& [key, value] :
       {std::pair{"from", from_s}, {"to", to_s}, {"step_at", step_at_s}}) {
    if (value && !std::isfinite(*value)) {
      throw option_error(key, fmt::format("the time must be finite, got {}", *value));
    }
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

namespace {

// A step the fit cannot take (too short, no valid output after it, no input change) is a row
// with the reason: one bad step never costs the others.
StepFit fit_step(const StepRequest& request, const StepSignals& s, const FoundStep& found) {
  StepFit fit;
  try {
    fit = is_second_order(request.method) ? fit_second_order(request.method, s, found.step)
                                          : fit_first_order(request.method, s, found.step);
  } catch (const core::InputError& e) {
    fit = StepFit{};
    fit.step = found.step;
    fit.status = core::Status::kFailed;
    fit.message = e.problem() + (e.hint().empty() ? "" : "; " + e.hint());
  }
  fit.segment = found.segment;
  return fit;
}

StepReport run_step_on_log(const StepRequest& request) {
  const StepSignals s = read_signals(request);
  StepReport report;
  report.log = request.source.log;
  report.input = s.read;
  report.method = request.method;
  report.output_unit = s.output_unit;
  if (s.has_input) report.input_unit = s.input_unit;
  report.timing = s.has_input     ? StepTimingSource::kCommand
                  : s.has_trigger ? StepTimingSource::kTrigger
                                  : StepTimingSource::kWindow;
  report.segments_file = request.segments_file;
  const std::vector<FoundStep> found = find_steps(request, s, report);
  report.steps.resize(found.size());
  // The fits are independent: one per step, on every core, each into its own row.
  core::parallel_for(found.size(), request.source.jobs,
                     [&](std::size_t i) { report.steps[i] = fit_step(request, s, found[i]); });
  std::stable_sort(
      report.steps.begin(), report.steps.end(),
      [](const StepFit& a, const StepFit& b) { return a.step.t_step < b.step.t_step; });
  return report;
}

}  // namespace

StepReport run_step(const StepRequest& request) {
  request.validate();
  try {
    return run_step_on_log(request);
  } catch (const core::InputError& e) {
    throw request.source.in_log(e);  // errors from inside name a channel or an option
  }
}

}  // namespace dynpos::analysis
