// dynpos hybrid first-order|dp [--no-jumps] [--sampled] [--seed N] [--out DIR] [--json FILE|-]:
// the chapter 5 case studies, hybrid and conventional integral action side by side, with the
// stability conditions checked first, a table, JSON and SVG plots like thesis figs. 5.1–5.12.

#include <fmt/core.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "dynpos/core/angle.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/hybrid/case_study.hpp"
#include "dynpos/hybrid/stability_check.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/report/svg_plot.hpp"

namespace dynpos::cli {
namespace {

struct HybridOptions {
  bool no_jumps = false;
  bool sampled = false;
  std::uint64_t seed = 1;
  std::filesystem::path out_dir;
  std::string json;
  std::optional<double> lambda;
  std::optional<double> dwell_s;
  std::optional<double> sample_period_s;
  std::optional<double> noise_power;
  std::optional<double> end_time_s;
  std::optional<double> heading_deg;  // dp only
  std::optional<double> ki;           // first-order only
  bool solve_p = false;               // first-order only
};

// What both case studies have in common for output.
struct CaseRun {
  std::string case_name;
  hybrid::JumpSet jump_set = hybrid::JumpSet::kIdeal;
  std::optional<hybrid::CaseResult> hybrid;
  hybrid::CaseResult conventional;
  nlohmann::json parameters;
  nlohmann::json stability;
  std::string stability_line;
  std::vector<std::string> step_labels;
};

// Runs the conventional design and (unless no_jumps) the hybrid one with run.jump_set, and
// records the timing both used.
template <typename CaseOptions, typename RunCase>
void run_both(CaseRun& run, CaseOptions o, bool no_jumps, RunCase run_case) {
  o.params.jump_set = hybrid::JumpSet::kNone;
  run.conventional = run_case(o);
  if (!no_jumps) {
    o.params.jump_set = run.jump_set;
    run.hybrid = run_case(o);
  }
  run.parameters["timing"] = {{"dt_s", o.timing.dt_s},
                              {"end_time_s", o.timing.end_time_s},
                              {"dwell_time_s", o.timing.dwell_time_s},
                              {"sample_period_s", o.timing.sample_period_s},
                              {"noise_power", o.timing.noise_power}};
}

core::InputError option_error(const std::string& option, const std::string& problem,
                              const std::string& hint = {}) {
  return core::InputError({{}, {}, {}, option}, problem, hint);
}

// Applies the common options to the timing; throws InputError on a bad value.
void apply_timing(const HybridOptions& opt, hybrid::CaseTiming& timing) {
  if (opt.dwell_s) timing.dwell_time_s = *opt.dwell_s;
  if (opt.sample_period_s) timing.sample_period_s = *opt.sample_period_s;
  if (opt.noise_power) timing.noise_power = *opt.noise_power;
  if (opt.end_time_s) timing.end_time_s = *opt.end_time_s;
  timing.seed = opt.seed;
  try {
    timing.validate();
  } catch (const std::invalid_argument& e) {
    throw option_error("--dwell/--sample-period/--noise-power/--end-time", e.what(),
                       "times must be multiples of the 1 ms step");
  }
}

std::string prefix_of(const CaseRun& run) {
  if (!run.hybrid) return run.case_name + "-conventional";
  return run.case_name + (run.jump_set == hybrid::JumpSet::kSampled ? "-sampled" : "");
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
std::vector<report::Series> both(const CaseRun& run, const std::string& channel,
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

report::Panel panel(const CaseRun& run, const std::string& title, const std::string& y_label,
                    const std::string& y_unit, std::vector<report::Series> series) {
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
std::optional<report::XRange> jump_zoom(const CaseRun& run) {
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

std::vector<std::filesystem::path> write_plots(const CaseRun& run,
                                               const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> written;
  const std::string prefix = prefix_of(run);
  const std::string what = run.hybrid ? std::string("hybrid (") + hybrid::to_string(run.jump_set) +
                                            " jump set) vs conventional"
                                      : std::string("conventional integral action");
  const auto save = [&](const std::string& name, report::Figure figure) {
    const std::filesystem::path path = dir / (prefix + "_" + name + ".svg");
    report::write_svg(path, figure);
    written.push_back(path);
  };
  const std::optional<report::XRange> zoom = jump_zoom(run);
  if (run.case_name == "first-order") {
    report::Figure states;
    states.title = "First-order system, " + what + " (cf. thesis figs. 5.1, 5.3)";
    states.panels.push_back(panel(run, "Position error x₁ = z − z_d", "x₁", "", both(run, "x1")));
    states.panels.push_back(
        panel(run, "Integral state error x₂ = d − d̂", "x₂", "", both(run, "x2")));
    save("states", states);
    report::Figure lyap;
    lyap.title = "First-order system: Lyapunov function and integral error (cf. figs. 5.2, 5.4)";
    lyap.panels.push_back(panel(run, "Lyapunov function V = xᵀPx (5.13)", "V", "", both(run, "V")));
    lyap.panels.back().zoom = zoom;
    lyap.panels.push_back(panel(run, "Integral state error x₂ = d − d̂", "x₂", "", both(run, "x2")));
    lyap.panels.back().zoom = zoom;
    save("lyapunov", lyap);
    return written;
  }
  const double deg = core::kDegPerRad;
  report::Figure pos;
  pos.title = "DP, position error x₁ = R(ψ)ᵀ(η − η_d), " + what + " (cf. figs. 5.5, 5.9)";
  pos.panels.push_back(panel(run, "Surge", "x₁ surge", "m", both(run, "x1.surge")));
  pos.panels.push_back(panel(run, "Sway", "x₁ sway", "m", both(run, "x1.sway")));
  pos.panels.push_back(panel(run, "Heading", "x₁ yaw", "deg", both(run, "x1.yaw", deg)));
  save("position", pos);
  report::Figure vel;
  vel.title = "DP, velocity error x₂ = ν − μ, " + what + " (cf. figs. 5.6, 5.10)";
  vel.panels.push_back(panel(run, "Surge", "x₂ surge", "m/s", both(run, "x2.surge")));
  vel.panels.push_back(panel(run, "Sway", "x₂ sway", "m/s", both(run, "x2.sway")));
  vel.panels.push_back(panel(run, "Yaw rate", "x₂ yaw", "deg/s", both(run, "x2.yaw", deg)));
  save("velocity", vel);
  report::Figure integral;
  integral.title = "DP, integral error x₃ = b − b̂ (NED), " + what + " (cf. figs. 5.7, 5.11)";
  integral.panels.push_back(panel(run, "North", "x₃ north", "N", both(run, "x3.north")));
  integral.panels.push_back(panel(run, "East", "x₃ east", "N", both(run, "x3.east")));
  integral.panels.push_back(panel(run, "Yaw", "x₃ yaw", "N·m", both(run, "x3.yaw")));
  save("integral", integral);
  report::Figure lyap;
  lyap.title = "DP: Lyapunov function and integral error (cf. figs. 5.8, 5.12)";
  lyap.panels.push_back(panel(run, "Lyapunov function V (5.48)", "V", "", both(run, "V")));
  lyap.panels.back().zoom = zoom;
  const hybrid::CaseResult& main = run.hybrid ? *run.hybrid : run.conventional;
  std::vector<report::Series> x3 = {series_of(main, "x3.north", "north [N]"),
                                    series_of(main, "x3.east", "east [N]"),
                                    series_of(main, "x3.yaw", "yaw [N·m]")};
  lyap.panels.push_back(
      panel(run, std::string("Integral error x₃, ") + (run.hybrid ? "hybrid" : "conventional"),
            "x₃", "N, N·m", std::move(x3)));
  lyap.panels.back().zoom = zoom;
  save("lyapunov", lyap);
  return written;
}

// ---------------------------------------------------------------------------------------------
// The table.

std::string cell(const std::optional<double>& v, const char* format = "{:.3f}") {
  return v && std::isfinite(*v) ? fmt::format(fmt::runtime(format), *v) : "—";
}

void print_table(std::FILE* out, const CaseRun& run) {
  const hybrid::CaseResult& c = run.conventional;
  const hybrid::CaseResult* h = run.hybrid ? &*run.hybrid : nullptr;
  fmt::print(out, "dynpos hybrid {}: {}\n", run.case_name,
             h ? std::string(hybrid::to_string(run.jump_set)) + " jump set vs conventional"
               : std::string("conventional only (--no-jumps)"));
  fmt::print(out, "{}\n\n", run.stability_line);
  const auto row = [&](const std::string& name, const std::string& hv, const std::string& cv) {
    if (h) {
      fmt::print(out, "{:<36} {:>14} {:>14}\n", name, hv, cv);
    } else {
      fmt::print(out, "{:<36} {:>14}\n", name, cv);
    }
  };
  row("", h ? "hybrid" : "", "conventional");
  row("jumps", h ? std::to_string(h->metrics.jumps) : "", std::to_string(c.metrics.jumps));
  for (std::size_t i = 0; i < c.step_times.size(); ++i) {
    row(fmt::format("settle after {} [s]", run.step_labels[i]),
        h ? cell(h->metrics.settle_s[i]) : "", cell(c.metrics.settle_s[i]));
    row(fmt::format("  left at the next step/end [%]"),
        h ? cell(100.0 * h->metrics.residual[i], "{:.2f}") : "",
        cell(100.0 * c.metrics.residual[i], "{:.2f}"));
  }
  const std::string unit = c.error_unit.empty() ? "" : " [" + c.error_unit + "]";
  const std::string unit_s = c.error_unit.empty() ? " [s]" : " [" + c.error_unit + "·s]";
  // IAE = ∫|e|dt; for the dimensionless first-order system its unit is the second.
  row("IAE" + unit_s, h ? cell(h->metrics.iae, "{:.4g}") : "", cell(c.metrics.iae, "{:.4g}"));
  row("peak error" + unit, h ? cell(h->metrics.peak_error, "{:.4g}") : "",
      cell(c.metrics.peak_error, "{:.4g}"));
  if (run.case_name == "dp") {
    row("IAE heading [deg·s]", h ? cell(h->metrics.heading_iae * core::kDegPerRad, "{:.4g}") : "",
        cell(c.metrics.heading_iae * core::kDegPerRad, "{:.4g}"));
  }
  row("max V increase at a jump", h ? cell(h->metrics.v_increase_at_jumps, "{:.3g}") : "",
      cell(c.metrics.v_increase_at_jumps, "{:.3g}"));
  fmt::print(out, "(error: {}; settle: integral error within 5 % of the step; — = none)\n",
             c.error_label);
  for (const hybrid::CaseResult* r : {h, &c}) {
    if (r && !r->ok()) fmt::print(out, "warning: run stopped early: {}\n", r->message);
  }
}

// ---------------------------------------------------------------------------------------------
// The two cases.

CaseRun run_first_order(const HybridOptions& opt) {
  if (opt.heading_deg) {
    throw option_error("--heading", "only the dp case has a heading", "drop --heading");
  }
  hybrid::FirstOrderCaseOptions o;
  apply_timing(opt, o.timing);
  if (opt.lambda) o.params.lambda = *opt.lambda;
  if (opt.ki) o.params.ki = *opt.ki;
  if (opt.solve_p) {
    const auto P = hybrid::solve_lyapunov(o.params.A(), Eigen::Matrix2d::Identity());
    if (!P) throw option_error("--solve-p", "the Lyapunov equation has no unique solution");
    o.params.P = *P;
  }
  const hybrid::FirstOrderCheck check = o.params.check();
  if (!check.ok()) {
    throw option_error(opt.ki ? "--ki" : "--lambda",
                       "the conditions of Theorem 6 fail: " + check.reason,
                       opt.solve_p ? "" : "try --solve-p to compute P from A^T P + PA = -I");
  }
  CaseRun run;
  run.case_name = "first-order";
  run.jump_set = opt.sampled ? hybrid::JumpSet::kSampled : hybrid::JumpSet::kIdeal;
  run.stability_line = fmt::format(
      "Theorem 6: {} (beta = {:.4g}, gamma = {:.4g}; PA + A^T P eigenvalues {:.4g}, "
      "{:.4g})",
      hybrid::to_string(check.status), check.beta, check.gamma, check.flow_eigenvalues(0),
      check.flow_eigenvalues(1));
  run.stability = {{"theorem", 6},
                   {"status", hybrid::to_string(check.status)},
                   {"beta", check.beta},
                   {"gamma", check.gamma},
                   {"P", {{check.P(0, 0), check.P(0, 1)}, {check.P(1, 0), check.P(1, 1)}}},
                   {"flow_eigenvalues", {check.flow_eigenvalues(0), check.flow_eigenvalues(1)}},
                   {"notes", check.notes}};
  nlohmann::json steps = nlohmann::json::array();
  for (const auto& s : o.steps) {
    steps.push_back({{"time_s", s.time_s}, {"delta", s.delta}});
    run.step_labels.push_back(fmt::format("step {:+g} at {:g} s", s.delta, s.time_s));
  }
  run.parameters = {{"a", o.params.a},
                    {"kp", o.params.kp},
                    {"ki", o.params.ki},
                    {"lambda", o.params.lambda},
                    {"epsilon", o.params.epsilon},
                    {"sigma", o.params.sigma},
                    {"steps", steps}};
  run_both(run, o, opt.no_jumps, hybrid::run_first_order_case);
  return run;
}

CaseRun run_dp(const HybridOptions& opt) {
  if (opt.ki || opt.solve_p) {
    throw option_error(opt.ki ? "--ki" : "--solve-p", "only the first-order case has this option",
                       "the dp case uses the gains of thesis section 5.3.2");
  }
  hybrid::DpCaseOptions o;
  apply_timing(opt, o.timing);
  if (opt.lambda) o.params.lambda = *opt.lambda;
  if (opt.heading_deg) o.params.eta_d.z() = core::wrap_pi(core::deg_to_rad(*opt.heading_deg));
  const hybrid::DpCheck check = o.params.check();
  if (!check.ok()) {
    throw option_error("--lambda", "the conditions of Theorem 7 fail: " + check.reason);
  }
  CaseRun run;
  run.case_name = "dp";
  run.jump_set = opt.sampled ? hybrid::JumpSet::kSampled : hybrid::JumpSet::kIdeal;
  run.stability_line = fmt::format(
      "Theorem 7: {} (smallest eigenvalues: K_p {:.4g}, K_d {:.4g}, K_i {:.4g}; beta {:.4g}, "
      "Gamma {:.4g})",
      hybrid::to_string(check.status), check.min_eig_Kp, check.min_eig_Kd, check.min_eig_Ki,
      check.beta_min, check.gamma_min);
  run.stability = {{"theorem", 7},
                   {"status", hybrid::to_string(check.status)},
                   {"min_eig_M", check.min_eig_M},
                   {"min_eig_Kp", check.min_eig_Kp},
                   {"min_eig_Kd", check.min_eig_Kd},
                   {"min_eig_Ki", check.min_eig_Ki},
                   {"beta_min", check.beta_min},
                   {"gamma_min", check.gamma_min},
                   {"notes", check.notes}};
  nlohmann::json steps = nlohmann::json::array();
  for (const auto& s : o.steps) {
    steps.push_back(
        {{"time_s", s.time_s}, {"delta_n", {s.delta_n(0), s.delta_n(1), s.delta_n(2)}}});
    run.step_labels.push_back(fmt::format("bias step at {:g} s", s.time_s));
  }
  const control::DpControllerParams& c = o.params.controller;
  const auto diag = [](const Eigen::Matrix3d& m) {
    return std::vector<double>{m(0, 0), m(1, 1), m(2, 2)};
  };
  run.parameters = {{"M", diag(c.M)},
                    {"Kp", diag(c.Kp)},
                    {"Ki", diag(c.Ki)},
                    {"Kd", diag(c.Kd)},
                    {"lambda", o.params.lambda},
                    {"epsilon1", o.params.epsilon1},
                    {"epsilon2", o.params.epsilon2},
                    {"sigma", o.params.sigma},
                    {"heading_deg", core::rad_to_deg(o.params.eta_d.z())},
                    {"jump_frame", "NED: x3+ = x3 - lambda R(psi) x2"},
                    {"steps", steps}};
  run_both(run, o, opt.no_jumps, hybrid::run_dp_case);
  return run;
}

void check_outputs(const HybridOptions& opt) {
  if (!opt.out_dir.empty() && std::filesystem::exists(opt.out_dir) &&
      !std::filesystem::is_directory(opt.out_dir)) {
    throw option_error("--out", "'" + opt.out_dir.string() + "' exists and is not a folder",
                       "name a folder (it is created if needed)");
  }
  if (!opt.json.empty() && opt.json != "-") {
    const std::filesystem::path parent = std::filesystem::path(opt.json).parent_path();
    const bool in_out_dir =
        !opt.out_dir.empty() && parent.lexically_normal() == opt.out_dir.lexically_normal();
    if (!parent.empty() && !in_out_dir && !std::filesystem::is_directory(parent)) {
      throw option_error("--json", "folder '" + parent.string() + "' does not exist",
                         "create it first, or use --json - for stdout");
    }
  }
}

void run_hybrid(const std::string& which, const HybridOptions& opt) {
  if (opt.no_jumps && opt.sampled) {
    throw option_error("--sampled",
                       "--sampled chooses the jump set of the hybrid run, and "
                       "--no-jumps runs no hybrid run",
                       "drop one of them");
  }
  check_outputs(opt);
  const CaseRun run = which == "dp" ? run_dp(opt) : run_first_order(opt);

  std::vector<std::filesystem::path> plots;
  if (!opt.out_dir.empty()) {
    std::filesystem::create_directories(opt.out_dir);
    plots = write_plots(run, opt.out_dir);
  }
  if (!opt.json.empty()) {
    nlohmann::json doc;
    doc["case"] = run.case_name;
    doc["jump_set"] = run.hybrid ? hybrid::to_string(run.jump_set) : "none";
    doc["seed"] = opt.seed;
    doc["parameters"] = run.parameters;
    doc["stability"] = run.stability;
    if (run.hybrid) doc["hybrid"] = result_json(*run.hybrid, "hybrid");
    doc["conventional"] = result_json(run.conventional, "conventional");
    // The contract's keys at the top level: the hybrid run's (the conventional one's with
    // --no-jumps); both runs in full under "hybrid" and "conventional".
    const nlohmann::json& primary = run.hybrid ? doc["hybrid"] : doc["conventional"];
    doc["variant"] = primary["variant"];
    for (const char* key : {"jumps", "settle_s", "iae", "peak_error", "v_increase_at_jumps"}) {
      doc[key] = primary[key];
    }
    nlohmann::json files = nlohmann::json::array();
    for (const auto& p : plots) files.push_back(p.string());
    doc["plots"] = files;
    io::write_json(opt.json, doc);
  }
  // With the JSON on stdout, the human-readable part goes to stderr.
  std::FILE* out = opt.json == "-" ? stderr : stdout;
  print_table(out, run);
  for (const auto& p : plots) fmt::print(out, "wrote {}\n", p.string());
  if (!opt.json.empty() && opt.json != "-") fmt::print(out, "wrote {}\n", opt.json);
}

void add_case(CLI::App& parent, const std::string& name, const std::string& description,
              bool first_order) {
  auto opt = std::make_shared<HybridOptions>();
  CLI::App* sub = parent.add_subcommand(name, description);
  sub->add_flag("--no-jumps", opt->no_jumps,
                "Run only the conventional (continuous) integral action");
  sub->add_flag("--sampled", opt->sampled,
                "Hybrid run with the practical jump set: the integral error estimated from a "
                "sampled, noisy state derivative (default: the ideal jump set of the theorem)");
  sub->add_option("--seed", opt->seed, "Seed of the derivative noise (--sampled)")
      ->capture_default_str();
  sub->add_option("--out", opt->out_dir, "Folder for the SVG plots (created if needed)");
  sub->add_option("--json", opt->json, "Write the results as JSON to FILE, or '-' for stdout");
  sub->add_option("--lambda", opt->lambda,
                  first_order ? "Jump gain lambda (default 3, (5.76))"
                              : "Jump gain lambda (default 25, (5.88))");
  sub->add_option("--dwell", opt->dwell_s, "Least time between jumps [s] (default 0.1)");
  sub->add_option("--sample-period", opt->sample_period_s,
                  "Derivative sampling period T_s [s] (default 0.03)");
  sub->add_option("--noise-power", opt->noise_power,
                  first_order ? "Power of the derivative noise (default 0.1)"
                              : "Power of the derivative noise per DOF (default 20)");
  sub->add_option("--end-time", opt->end_time_s, "Length of the run [s] (default 60)");
  if (first_order) {
    sub->add_option("--ki", opt->ki, "Integral gain k_i (default 1, (5.72))");
    sub->add_flag("--solve-p", opt->solve_p,
                  "Use P from the Lyapunov equation A^T P + PA = -I instead of (5.75)");
    sub->footer(
        "Thesis section 5.3.1: z' = -z + d + u with u = -9(z - z_d) - d_hat, k_i = 1, "
        "lambda = 3, epsilon = 0.3, disturbance steps +100 at 5 s and -50 at 30 s, dwell 0.1 s; "
        "sampled: T_s = 0.03 s, noise power 0.1. Plots: <case>_states.svg, "
        "<case>_lyapunov.svg.");
  } else {
    sub->add_option("--heading", opt->heading_deg,
                    "Set-point heading [deg] (default 0); the jump acts in NED at any heading");
    sub->footer(
        "Thesis section 5.3.2: M = diag(450, 450, 100), K_p = diag(100, 100, 50), "
        "K_i = diag(10, 10, 5), K_d = diag(500, 500, 200), lambda = 25, epsilon1 = 1e-4, "
        "epsilon2 = 0.01, bias step (3000 N, 2000 N, 1000 N m) at 10 s, dwell 0.1 s, 60 s; "
        "sampled: T_s = 0.03 s, noise power 20. Plots: dp_position.svg, dp_velocity.svg, "
        "dp_integral.svg, dp_lyapunov.svg.");
  }
  sub->callback([opt, name] { run_hybrid(name, *opt); });
}

}  // namespace

void register_hybrid(CLI::App& app) {
  CLI::App* hybrid = app.add_subcommand(
      "hybrid", "Hybrid integral action case studies: jumps of the integral state (thesis ch. 5)");
  // Not require_subcommand(): CLI11 would then answer an unknown case with "A subcommand is
  // required"; a hidden positional catches the word and the message names it.
  hybrid->require_subcommand(0, 1);
  auto unknown = std::make_shared<std::string>();
  hybrid->add_option("case", *unknown, "The case study: first-order, dp or vessel");
  hybrid->callback([hybrid, unknown] {
    if (!hybrid->get_subcommands().empty()) return;
    throw core::InputError(
        {{}, {}, {}, "dynpos hybrid"},
        unknown->empty() ? std::string("no case given") : "unknown case '" + *unknown + "'",
        "choose one of first-order, dp, vessel (dynpos hybrid --help)");
  });
  add_case(*hybrid, "first-order", "First-order system with hybrid integral action (5.3.1)", true);
  add_case(*hybrid, "dp", "DP vessel, backstepping with hybrid integral action (5.3.2)", false);
  add_hybrid_vessel(*hybrid);
}

}  // namespace dynpos::cli
