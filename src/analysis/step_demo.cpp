// The step-test section of the `dynpos demo` report: thesis tables 3.23–3.31 on the campaign's
// logs, each fitted time constant against the simulator's truth.

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynpos/analysis/demo_sections.hpp"
#include "dynpos/analysis/json_fields.hpp"
#include "dynpos/analysis/step.hpp"
#include "dynpos/core/log.hpp"
#include "dynpos/ident/derived_signals.hpp"
#include "dynpos/ident/fopdt_fit.hpp"
#include "dynpos/io/column_map.hpp"
#include "dynpos/io/csv_reader.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/report/svg_plot.hpp"
#include "dynpos/report/table.hpp"
#include "dynpos/scenario/trial_truth.hpp"

namespace dynpos::analysis {
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

// One step of a run's truth for the quantity a table compares.
struct TruthStep {
  double t_s = -1e9;     // step time; far from every step when truth.json lacks it
  std::string thruster;  // propeller steps: "port", "stb", ...; rudder steps: ""
  std::optional<double> T_s, delay_s;
};

// A time constant of truth.json as an optional: null (NaN) is missing.
std::optional<double> known(double v) {
  return std::isnan(v) ? std::nullopt : std::optional<double>(v);
}

// The truth of `quantity` ("shaft_speed" or "thrust": truth.json's propeller_steps; "nomoto":
// its rudder_steps) for every step of the run in `run_dir`; none without truth.json or for the
// quantity "". The one place the demo reads truth.json.
std::vector<TruthStep> read_truth_steps(const std::filesystem::path& run_dir,
                                        const std::string& quantity) {
  std::vector<TruthStep> out;
  const std::filesystem::path file = run_dir / "truth.json";
  if (quantity.empty() || !std::filesystem::exists(file)) return out;
  const scenario::TrialTruth truth = scenario::read_trial_truth(file);
  if (quantity == "nomoto") {
    // Nomoto's first-order yaw-rate time constant T_r; the dead time of the yaw-rate response
    // has no single truth (servo + hull), so it stays missing.
    for (const scenario::RudderStepTruth& s : truth.rudder_steps) {
      TruthStep step;
      step.t_s = s.t_s;
      if (s.nomoto) step.T_s = known(s.nomoto->Tr_s);
      out.push_back(std::move(step));
    }
    return out;
  }
  for (const scenario::PropellerStepTruth& s : truth.propeller_steps) {
    const model::FopdtTruth& f = quantity == "thrust" ? s.thrust : s.shaft_speed;
    out.push_back({s.t_s, s.thruster, known(f.time_constant), known(f.dead_time)});
  }
  return out;
}

// The truth of the step at `t_step`: the nearest step of the truth within 1 s (the command is
// logged at the step time; 1 s is far below the shortest spacing of steps, 60 s).
TruthStep truth_for(const std::vector<TruthStep>& truth, const StepDemoTest& test, double t_step) {
  const bool rudder = std::string(test.truth) == "nomoto";
  for (const TruthStep& s : truth) {
    if (!rudder && s.thruster != "stb") continue;
    if (std::abs(s.t_s - t_step) > 1.0) continue;
    return s;
  }
  return {};
}

struct StepDemoOutcome {
  report::Table table;
  std::string plot;  // file name under analysis/steps/, or empty
  std::size_t steps = 0, with_truth = 0;
  double worst_error_pct = 0.0;
};

// The logged response of a test, for the plot: time, y and their units.
struct StepDemoSignals {
  std::vector<double> t, u, y;
  std::string u_unit, y_unit;
};

StepDemoSignals read_demo_signals(const std::filesystem::path& run_dir, const StepDemoTest& test) {
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
  StepDemoSignals s;
  s.t = log.time();
  s.u = log.values("input");
  s.y = test.total_speed ? ident::total_speed(log.values("u"), log.values("v"))  // (3.19)
                         : log.values("output");
  s.y_unit = test.total_speed ? "m/s" : log.channel("output").unit;
  s.u_unit = log.channel("input").unit;
  return s;
}

// The data and the fitted FOPDT (3.7) of every step, with the step times marked.
void write_step_demo_plot(const std::filesystem::path& file, const StepDemoTest& test,
                          const StepDemoSignals& s, const std::vector<double>& fit_t,
                          const std::vector<double>& fit_y, const std::vector<double>& markers) {
  report::Figure fig;
  fig.title = fmt::format("{}: {} — data and fitted FOPDT (3.7)", test.scenario, test.quantity);
  report::Panel panel;
  panel.x_axis = {"Time", "s", {}, {}};
  panel.y_axis = {test.quantity, s.y_unit, {}, {}};
  panel.series.push_back({"logged", s.t, s.y, "#1f77b4", 1.0, false});
  panel.series.push_back({"FOPDT fit (Smith)", fit_t, fit_y, "#d62728", 1.5, true});
  panel.x_markers = markers;
  fig.panels.push_back(std::move(panel));
  report::write_svg(file, fig);
}

// The public request of a test: the command and the response (or u and v) of the run's log,
// fitted by Smith's two-point method (3.8)-(3.9), the method that defines truth.json's time
// constants; the steps found with the analysis' defaults.
StepRequest demo_request(const std::filesystem::path& run_dir, const StepDemoTest& test) {
  StepRequest request;
  request.source.log = run_dir / "log.csv";
  request.source.columns = {std::string("input=") + test.input};
  if (test.total_speed) {
    request.derive = StepDerive::kTotalSpeed;
  } else {
    request.source.columns.push_back(std::string("output=") + test.output);
  }
  request.method = StepMethod::kSmith;
  return request;
}

// The fitted FOPDT (3.7) of a step, when the fit gave every parameter.
std::optional<ident::FopdtModel> fitted_model(const StepFit& fit) {
  if (fit.status == core::Status::kFailed || !fit.y_before || !fit.y_after ||
      !fit.time_constant_s || !fit.dead_time_s) {
    return std::nullopt;
  }
  return ident::FopdtModel{fit.step.t_step, *fit.y_before, *fit.y_after - *fit.y_before,
                           *fit.time_constant_s, *fit.dead_time_s};
}

StepDemoOutcome run_step_demo_test(const std::filesystem::path& campaign_dir,
                                   const StepDemoTest& test, const std::filesystem::path& out_dir) {
  const std::filesystem::path run_dir = campaign_dir / test.scenario;
  const StepReport report = run_step(demo_request(run_dir, test));
  const StepDemoSignals s = read_demo_signals(run_dir, test);
  const std::vector<TruthStep> truth = read_truth_steps(run_dir, test.truth);

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
  std::vector<double> fit_t, fit_y, markers;
  for (const StepFit& fit : report.steps) {
    const ident::Step& step = fit.step;
    const TruthStep tv = truth_for(truth, test, step.t_step);
    const std::optional<double> T = fit.time_constant_s, delay = fit.dead_time_s;
    std::optional<double> err;
    if (T && tv.T_s && *tv.T_s > 0.0) {
      err = 100.0 * (*T - *tv.T_s) / *tv.T_s;
      out.worst_error_pct = std::max(out.worst_error_pct, std::abs(*err));
      ++out.with_truth;
    }
    ++out.steps;
    std::string notes(ident::fit_status_name(fit.status));
    for (const ident::FitWarning& w : fit.warnings) {
      notes += (notes.empty() ? "" : ", ") + std::string(ident::warning_code_name(w.code));
    }
    out.table.rows.push_back({fmt::format("{:.1f}", step.t_step),
                              number_cell(in_logger_unit(step.u_before), "{:.4g}") + " → " +
                                  number_cell(in_logger_unit(step.u_after), "{:.4g}"),
                              number_cell(T, "{:.2f}"), number_cell(delay, "{:.2f}"),
                              number_cell(fit.r_squared, "{:.3f}"), number_cell(tv.T_s, "{:.2f}"),
                              number_cell(tv.delay_s, "{:.2f}"), number_cell(err, "{:+.1f}"),
                              notes});
    // The fitted FOPDT (3.7) over the step's window, for the plot; gaps between steps.
    markers.push_back(step.t_step);
    if (const auto model = fitted_model(fit)) {
      for (std::size_t i = 0; i < s.t.size(); ++i) {
        if (s.t[i] < step.t_begin || s.t[i] > step.t_end) continue;
        fit_t.push_back(s.t[i]);
        fit_y.push_back((*model)(s.t[i]));
      }
      fit_t.push_back(std::nan(""));
      fit_y.push_back(std::nan(""));
    }
  }
  // The analysis' own document, as `identify step --json` writes it; paths relative to the
  // report, so that it is relocatable.
  nlohmann::json doc = to_json(report);
  doc["log"] = std::string(test.scenario) + "/log.csv";
  doc["input"] = io::to_json(relative_to(report.input, campaign_dir));
  io::write_json((out_dir / (std::string(test.id) + ".json")).string(), doc);
  out.plot = std::string(test.id) + ".svg";
  write_step_demo_plot(out_dir / out.plot, test, s, fit_t, fit_y, markers);
  return out;
}

}  // namespace

ReportSection step_demo_section(const std::filesystem::path& campaign_dir) {
  const std::filesystem::path out_dir = campaign_dir / "analysis" / "steps";
  ReportSection section;
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

}  // namespace dynpos::analysis
