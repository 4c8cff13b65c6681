// The adapters of the hybrid case studies: JSON, the side-by-side table and the plots.

#include <fmt/core.h>

#include <algorithm>

#include "dynpos/analysis/hybrid_case.hpp"
#include "dynpos/analysis/json_fields.hpp"
#include "dynpos/core/angle.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/report/svg_plot.hpp"

namespace dynpos::analysis {
namespace {

nlohmann::json timing_json(const hybrid::CaseTiming& t) {
  return {{"dt_s", t.dt_s},
          {"end_time_s", t.end_time_s},
          {"dwell_time_s", t.dwell_time_s},
          {"sample_period_s", t.sample_period_s},
          {"noise_power", t.noise_power}};
}

nlohmann::json parameters_json(const FirstOrderStudy& s) {
  const hybrid::FirstOrderCaseOptions& o = s.options;
  nlohmann::json steps = nlohmann::json::array();
  for (const auto& step : o.steps)
    steps.push_back({{"time_s", step.time_s}, {"delta", step.delta}});
  return {{"a", o.params.a},
          {"kp", o.params.kp},
          {"ki", o.params.ki},
          {"lambda", o.params.lambda},
          {"epsilon", o.params.epsilon},
          {"sigma", o.params.sigma},
          {"steps", steps},
          {"timing", timing_json(o.timing)}};
}

nlohmann::json parameters_json(const DpStudy& s) {
  const hybrid::DpCaseOptions& o = s.options;
  nlohmann::json steps = nlohmann::json::array();
  for (const auto& step : o.steps) {
    steps.push_back({{"time_s", step.time_s},
                     {"delta_n", {step.delta_n(0), step.delta_n(1), step.delta_n(2)}}});
  }
  const control::DpControllerParams& c = o.params.controller;
  const auto diag = [](const Eigen::Matrix3d& m) {
    return std::vector<double>{m(0, 0), m(1, 1), m(2, 2)};
  };
  return {{"M", diag(c.M)},
          {"Kp", diag(c.Kp)},
          {"Ki", diag(c.Ki)},
          {"Kd", diag(c.Kd)},
          {"lambda", o.params.lambda},
          {"epsilon1", o.params.epsilon1},
          {"epsilon2", o.params.epsilon2},
          {"sigma", o.params.sigma},
          {"heading_deg", core::rad_to_deg(o.params.eta_d.z())},
          {"jump_frame", "NED: x3+ = x3 - lambda R(psi) x2"},
          {"steps", steps},
          {"timing", timing_json(o.timing)}};
}

nlohmann::json stability_json(const FirstOrderStudy& s) {
  const hybrid::FirstOrderCheck& c = s.check;
  return {{"theorem", 6},
          {"status", hybrid::to_string(c.status)},
          {"beta", c.beta},
          {"gamma", c.gamma},
          {"P", {{c.P(0, 0), c.P(0, 1)}, {c.P(1, 0), c.P(1, 1)}}},
          {"flow_eigenvalues", {c.flow_eigenvalues(0), c.flow_eigenvalues(1)}},
          {"notes", c.notes}};
}

nlohmann::json stability_json(const DpStudy& s) {
  const hybrid::DpCheck& c = s.check;
  return {{"theorem", 7},
          {"status", hybrid::to_string(c.status)},
          {"min_eig_M", c.min_eig_M},
          {"min_eig_Kp", c.min_eig_Kp},
          {"min_eig_Kd", c.min_eig_Kd},
          {"min_eig_Ki", c.min_eig_Ki},
          {"beta_min", c.beta_min},
          {"gamma_min", c.gamma_min},
          {"notes", c.notes}};
}

std::string stability_line(const FirstOrderStudy& s) {
  const hybrid::FirstOrderCheck& c = s.check;
  return fmt::format(
      "Theorem 6: {} (beta = {:.4g}, gamma = {:.4g}; PA + A^T P eigenvalues {:.4g}, {:.4g})",
      hybrid::to_string(c.status), c.beta, c.gamma, c.flow_eigenvalues(0), c.flow_eigenvalues(1));
}

std::string stability_line(const DpStudy& s) {
  const hybrid::DpCheck& c = s.check;
  return fmt::format(
      "Theorem 7: {} (smallest eigenvalues: K_p {:.4g}, K_d {:.4g}, K_i {:.4g}; beta {:.4g}, "
      "Gamma {:.4g})",
      hybrid::to_string(c.status), c.min_eig_Kp, c.min_eig_Kd, c.min_eig_Ki, c.beta_min,
      c.gamma_min);
}

std::vector<std::string> step_labels(const FirstOrderStudy& s) {
  std::vector<std::string> labels;
  for (const auto& step : s.options.steps) {
    labels.push_back(fmt::format("step {:+g} at {:g} s", step.delta, step.time_s));
  }
  return labels;
}

std::vector<std::string> step_labels(const DpStudy& s) {
  std::vector<std::string> labels;
  for (const auto& step : s.options.steps) {
    labels.push_back(fmt::format("bias step at {:g} s", step.time_s));
  }
  return labels;
}

nlohmann::json result_json(const hybrid::CaseResult& r, const std::string& variant) {
  nlohmann::json j;
  j["case"] = r.case_name;
  j["variant"] = variant;
  j["jump_set"] = hybrid::to_string(r.jump_set);
  j["status"] = sim::to_string(r.status);
  if (!r.ok()) j["message"] = r.message;
  j["jumps"] = r.metrics.jumps;
  nlohmann::json settle = nlohmann::json::array();
  for (const auto& s : r.metrics.settle_s) settle.push_back(io::json_number(s));
  j["settle_s"] = settle;
  j["residual"] = io::json_numbers(r.metrics.residual);
  j["iae"] = io::json_number(r.metrics.iae);
  j["peak_error"] = io::json_number(r.metrics.peak_error);
  j["error"] = r.error_label;
  j["error_unit"] = r.error_unit;
  if (r.case_name == "dp") {
    j["heading_iae_rad_s"] = io::json_number(r.metrics.heading_iae);
    j["heading_peak_rad"] = io::json_number(r.metrics.heading_peak);
  }
  j["v_increase_at_jumps"] = io::json_number(r.metrics.v_increase_at_jumps);
  j["v_max"] = io::json_number(r.metrics.v_max);
  j["jump_times_s"] = io::json_numbers(r.jump_times);
  return j;
}

// ---------------------------------------------------------------------------------------------
// Plots.

report::Series series_of(const hybrid::CaseResult& r, const std::string& channel,
                         const std::string& label, double scale = 1.0) {
  report::Series s;
  s.label = label;
  s.x = r.trace.t;
  s.y = r.trace.values(channel);
  if (scale != 1.0) {
    for (double& v : s.y) v *= scale;
  }
  return s;
}

// Hybrid (solid blue) and conventional (dashed red) of one channel.
std::vector<report::Series> both(const HybridCaseReport& run, const std::string& channel,
                                 double scale = 1.0) {
  std::vector<report::Series> out;
  if (run.hybrid) {
    report::Series h = series_of(*run.hybrid, channel, "hybrid", scale);
    h.color = "#1f77b4";
    out.push_back(std::move(h));
  }
  report::Series c = series_of(run.conventional, channel, "conventional", scale);
  c.color = "#d62728";
  c.dashed = run.hybrid.has_value();
  out.push_back(std::move(c));
  return out;
}

report::Panel panel(const HybridCaseReport& run, const std::string& title,
                    const std::string& y_label, const std::string& y_unit,
                    std::vector<report::Series> series) {
  report::Panel p;
  p.title = title;
  p.x_axis = {"Time", "s", 0.0, run.conventional.trace.t.back()};
  p.y_axis = {y_label, y_unit, {}, {}};
  p.series = std::move(series);
  p.x_markers = run.conventional.step_times;
  return p;
}

// The zoom window on the jumps after the first step: from just before the step to half as long
// again as the hybrid run took to settle (or to its last jump in that step's window).
std::optional<report::XRange> jump_zoom(const HybridCaseReport& run) {
  if (!run.hybrid || run.hybrid->step_times.empty()) return std::nullopt;
  const hybrid::CaseResult& h = *run.hybrid;
  const double t0 = h.step_times.front();
  const double t_next = h.step_times.size() > 1 ? h.step_times[1] : h.trace.t.back();
  double span = 0.0;
  if (h.metrics.settle_s.front()) {
    span = 1.5 * *h.metrics.settle_s.front();
  } else {
    for (const double t : h.jump_times) {
      if (t >= t0 && t < t_next) span = t - t0;
    }
  }
  span = std::max(span, 1.0);
  return report::XRange{std::max(0.0, t0 - 0.1 * span), std::min(t_next, t0 + span)};
}

std::string prefix_of(const HybridCaseReport& run) {
  if (!run.hybrid) return to_string(run.study_case) + "-conventional";
  return to_string(run.study_case) + (run.jump_set == hybrid::JumpSet::kSampled ? "-sampled" : "");
}

std::string designs_of(const HybridCaseReport& run) {
  return run.hybrid ? std::string("hybrid (") + hybrid::to_string(run.jump_set) +
                          " jump set) vs conventional"
                    : std::string("conventional integral action");
}

// Thesis figs. 5.1–5.4.
std::vector<std::pair<std::string, report::Figure>> first_order_figures(
    const HybridCaseReport& run) {
  const std::optional<report::XRange> zoom = jump_zoom(run);
  report::Figure states;
  states.title = "First-order system, " + designs_of(run) + " (cf. thesis figs. 5.1, 5.3)";
  states.panels.push_back(panel(run, "Position error x₁ = z − z_d", "x₁", "", both(run, "x1")));
  states.panels.push_back(panel(run, "Integral state error x₂ = d − d̂", "x₂", "", both(run, "x2")));
  report::Figure lyap;
  lyap.title = "First-order system: Lyapunov function and integral error (cf. figs. 5.2, 5.4)";
  lyap.panels.push_back(panel(run, "Lyapunov function V = xᵀPx (5.13)", "V", "", both(run, "V")));
  lyap.panels.back().zoom = zoom;
  lyap.panels.push_back(panel(run, "Integral state error x₂ = d − d̂", "x₂", "", both(run, "x2")));
  lyap.panels.back().zoom = zoom;
  return {{"states", std::move(states)}, {"lyapunov", std::move(lyap)}};
}

// Thesis figs. 5.5–5.12.
std::vector<std::pair<std::string, report::Figure>> dp_figures(const HybridCaseReport& run) {
  const std::string what = designs_of(run);
  const double deg = core::kDegPerRad;
  report::Figure pos;
  pos.title = "DP, position error x₁ = R(ψ)ᵀ(η − η_d), " + what + " (cf. figs. 5.5, 5.9)";
  pos.panels.push_back(panel(run, "Surge", "x₁ surge", "m", both(run, "x1.surge")));
  pos.panels.push_back(panel(run, "Sway", "x₁ sway", "m", both(run, "x1.sway")));
  pos.panels.push_back(panel(run, "Heading", "x₁ yaw", "deg", both(run, "x1.yaw", deg)));
  report::Figure vel;
  vel.title = "DP, velocity error x₂ = ν − μ, " + what + " (cf. figs. 5.6, 5.10)";
  vel.panels.push_back(panel(run, "Surge", "x₂ surge", "m/s", both(run, "x2.surge")));
  vel.panels.push_back(panel(run, "Sway", "x₂ sway", "m/s", both(run, "x2.sway")));
  vel.panels.push_back(panel(run, "Yaw rate", "x₂ yaw", "deg/s", both(run, "x2.yaw", deg)));
  report::Figure integral;
  integral.title = "DP, integral error x₃ = b − b̂ (NED), " + what + " (cf. figs. 5.7, 5.11)";
  integral.panels.push_back(panel(run, "North", "x₃ north", "N", both(run, "x3.north")));
  integral.panels.push_back(panel(run, "East", "x₃ east", "N", both(run, "x3.east")));
  integral.panels.push_back(panel(run, "Yaw", "x₃ yaw", "N·m", both(run, "x3.yaw")));
  report::Figure lyap;
  lyap.title = "DP: Lyapunov function and integral error (cf. figs. 5.8, 5.12)";
  lyap.panels.push_back(panel(run, "Lyapunov function V (5.48)", "V", "", both(run, "V")));
  const std::optional<report::XRange> zoom = jump_zoom(run);
  lyap.panels.back().zoom = zoom;
  const hybrid::CaseResult& main = run.hybrid ? *run.hybrid : run.conventional;
  std::vector<report::Series> x3 = {series_of(main, "x3.north", "north [N]"),
                                    series_of(main, "x3.east", "east [N]"),
                                    series_of(main, "x3.yaw", "yaw [N·m]")};
  lyap.panels.push_back(
      panel(run, std::string("Integral error x₃, ") + (run.hybrid ? "hybrid" : "conventional"),
            "x₃", "N, N·m", std::move(x3)));
  lyap.panels.back().zoom = zoom;
  return {{"position", std::move(pos)},
          {"velocity", std::move(vel)},
          {"integral", std::move(integral)},
          {"lyapunov", std::move(lyap)}};
}

}  // namespace

nlohmann::json to_json(const HybridCaseReport& report,
                       const std::vector<std::filesystem::path>& plots) {
  nlohmann::json doc;
  doc["case"] = to_string(report.study_case);
  doc["jump_set"] = report.hybrid ? hybrid::to_string(report.jump_set) : "none";
  doc["seed"] = report.seed;
  doc["parameters"] = std::visit([](const auto& s) { return parameters_json(s); }, report.study);
  doc["stability"] = std::visit([](const auto& s) { return stability_json(s); }, report.study);
  if (report.hybrid) doc["hybrid"] = result_json(*report.hybrid, "hybrid");
  doc["conventional"] = result_json(report.conventional, "conventional");
  // The contract's keys at the top level: the hybrid run's (the conventional one's with
  // --no-jumps); both runs in full under "hybrid" and "conventional".
  const nlohmann::json& primary = report.hybrid ? doc["hybrid"] : doc["conventional"];
  doc["variant"] = primary["variant"];
  for (const char* key : {"jumps", "settle_s", "iae", "peak_error", "v_increase_at_jumps"}) {
    doc[key] = primary[key];
  }
  nlohmann::json files = nlohmann::json::array();
  for (const auto& p : plots) files.push_back(p.string());
  doc["plots"] = files;
  return doc;
}

std::string to_text(const HybridCaseReport& report) {
  const hybrid::CaseResult& c = report.conventional;
  const hybrid::CaseResult* h = report.hybrid ? &*report.hybrid : nullptr;
  std::string out =
      fmt::format("dynpos hybrid {}: {}\n", to_string(report.study_case),
                  h ? std::string(hybrid::to_string(report.jump_set)) + " jump set vs conventional"
                    : std::string("conventional only (--no-jumps)"));
  out += std::visit([](const auto& s) { return stability_line(s); }, report.study) + "\n\n";
  const auto row = [&](const std::string& name, const std::string& hv, const std::string& cv) {
    out += h ? fmt::format("{:<36} {:>14} {:>14}\n", name, hv, cv)
             : fmt::format("{:<36} {:>14}\n", name, cv);
  };
  const std::vector<std::string> labels =
      std::visit([](const auto& s) { return step_labels(s); }, report.study);
  row("", h ? "hybrid" : "", "conventional");
  row("jumps", h ? std::to_string(h->metrics.jumps) : "", std::to_string(c.metrics.jumps));
  for (std::size_t i = 0; i < c.step_times.size(); ++i) {
    row(fmt::format("settle after {} [s]", labels[i]),
        h ? number_cell(h->metrics.settle_s[i], "{:.3f}") : "",
        number_cell(c.metrics.settle_s[i], "{:.3f}"));
    row("  left at the next step/end [%]",
        h ? number_cell(100.0 * h->metrics.residual[i], "{:.2f}") : "",
        number_cell(100.0 * c.metrics.residual[i], "{:.2f}"));
  }
  const std::string unit = c.error_unit.empty() ? "" : " [" + c.error_unit + "]";
  const std::string unit_s = c.error_unit.empty() ? " [s]" : " [" + c.error_unit + "·s]";
  // IAE = ∫|e|dt; for the dimensionless first-order system its unit is the second.
  row("IAE" + unit_s, h ? number_cell(h->metrics.iae, "{:.4g}") : "",
      number_cell(c.metrics.iae, "{:.4g}"));
  row("peak error" + unit, h ? number_cell(h->metrics.peak_error, "{:.4g}") : "",
      number_cell(c.metrics.peak_error, "{:.4g}"));
  if (report.study_case == HybridCase::kDp) {
    row("IAE heading [deg·s]",
        h ? number_cell(h->metrics.heading_iae * core::kDegPerRad, "{:.4g}") : "",
        number_cell(c.metrics.heading_iae * core::kDegPerRad, "{:.4g}"));
  }
  row("max V increase at a jump", h ? number_cell(h->metrics.v_increase_at_jumps, "{:.3g}") : "",
      number_cell(c.metrics.v_increase_at_jumps, "{:.3g}"));
  out += fmt::format("(error: {}; settle: integral error within 5 % of the step; — = none)\n",
                     c.error_label);
  for (const hybrid::CaseResult* r : {h, &c}) {
    if (r && !r->ok()) out += fmt::format("warning: run stopped early: {}\n", r->message);
  }
  return out;
}

std::vector<std::filesystem::path> write_figures(const HybridCaseReport& run,
                                                 const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  const auto figures = std::holds_alternative<FirstOrderStudy>(run.study) ? first_order_figures(run)
                                                                          : dp_figures(run);
  std::vector<std::filesystem::path> written;
  for (const auto& [name, figure] : figures) {
    written.push_back(dir / (prefix_of(run) + "_" + name + ".svg"));
    report::write_svg(written.back(), figure);
  }
  return written;
}

Written write_outputs(const HybridCaseReport& report, const Outputs& outputs) {
  Written written;
  if (!outputs.figures.empty()) written = write_figures(report, outputs.figures);
  write_json_output(outputs, to_json(report, written), written);
  return written;
}

}  // namespace dynpos::analysis
