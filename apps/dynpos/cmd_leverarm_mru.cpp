// dynpos leverarm mru: MRU lever arms from MRU accelerations and vessel motion (thesis 4.3,
// case study 4.4.2): the Luenberger observer (4.80) or batch least squares, with the
// excitation diagnostics of Proposition 3, a thesis-style table, JSON and plots (figure 4.13).

#include <fmt/core.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "dynpos/calib/mru_observer.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/report/svg_plot.hpp"
#include "dynpos/report/table.hpp"
#include "log_input.hpp"

namespace dynpos::cli {
namespace {

struct MruCliOptions {
  LogInput input;
  std::vector<std::string> mru_logs;  ///< NAME=FILE
  std::string accel = "kinematic";
  std::string method = "lsq";
  std::string json;
  std::string plots;
  double window_s = 1.0;
  double tau_s = 5.0;
  double w1_per_s = 0.01;
};

bool is_mru_accel_role(const std::string& role) {
  if (role.rfind("mru", 0) != 0) return false;
  const auto dot = role.find('.');
  if (dot == std::string::npos) return false;
  const std::string ch = role.substr(dot + 1);
  return ch == "ax" || ch == "ay" || ch == "az";
}

bool wanted_role(const std::string& role) {
  for (const char* r : {"roll", "pitch", "heading", "p", "q", "r", "u", "v", "w"}) {
    if (role == r) return true;
  }
  return is_mru_accel_role(role);
}

/// The MRU names K with all of mruK.ax/ay/az in `log`, in channel order.
std::vector<std::string> mru_names(const core::Log& log) {
  std::vector<std::string> out;
  for (const std::string& c : log.channel_names()) {
    if (!is_mru_accel_role(c) || c.substr(c.find('.') + 1) != "ax") continue;
    const std::string name = c.substr(0, c.find('.'));
    if (log.has(name + ".ay") && log.has(name + ".az")) out.push_back(name);
  }
  return out;
}

struct MruRun {
  calib::MruSignals signals;
  calib::MruEstimateResult result;
  std::string log_name;
};

MruRun analyse(const MruCliOptions& o) {
  const auto accel = calib::parse_mru_accel(o.accel);
  if (!accel) {
    throw core::InputError({"", {}, {}, "--accel"},
                           "unknown acceleration convention '" + o.accel + "'",
                           "use --accel kinematic or --accel specific-force");
  }
  const auto method = calib::parse_mru_method(o.method);
  if (!method) {
    throw core::InputError({"", {}, {}, "--method"}, "unknown method '" + o.method + "'",
                           "use --method lsq or --method observer");
  }
  if (!(o.window_s > 0.0) || !(o.tau_s > 0.0)) {
    throw core::InputError({"", {}, {}, "--window-s/--tau-s"}, "must be > 0", "give seconds");
  }
  const core::Log motion = o.input.read(wanted_role);
  // Separate MRU files: each read with its own role mapping NAME.ax/ay/az by header name.
  struct Extra {
    std::string name, file;
    core::Log log;
  };
  std::vector<Extra> extra;
  for (const std::string& spec : o.mru_logs) {
    const auto eq = spec.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size()) {
      throw core::InputError({"", {}, {}, "--mru-log"}, "malformed argument '" + spec + "'",
                             "expected NAME=FILE, e.g. --mru-log mru1=mru1.csv");
    }
    const std::string name = spec.substr(0, eq);
    LogInput in = o.input;
    in.log = spec.substr(eq + 1);
    extra.push_back({name, in.log.string(), in.read([name](const std::string& role) {
                       return role == name + ".ax" || role == name + ".ay" || role == name + ".az";
                     })});
  }
  std::vector<calib::MruSource> sources;
  for (const Extra& e : extra) sources.push_back({e.name, &e.log, e.file});
  for (const std::string& name : mru_names(motion)) {
    bool dup = false;
    for (const auto& s : sources) dup = dup || s.name == name;
    if (!dup) sources.push_back({name, &motion, o.input.log.string()});
  }
  MruRun run;
  run.log_name = o.input.log.string();
  calib::MruSignalOptions so;
  so.accel = *accel;
  so.smooth_window_s = o.window_s;
  run.signals = calib::mru_signals_from_logs(motion, sources, so);
  calib::MruEstimateOptions eo;
  eo.method = *method;
  eo.tau_s = o.tau_s;
  eo.w1_per_s = o.w1_per_s;
  run.result = calib::estimate_mru_arms(run.signals, eo);
  if (run.result.status != core::Status::kOk) {
    throw core::InputError({o.input.log.string(), {}, {}, "time"}, run.result.message,
                           "log a longer maneuver with rotation (a turning circle in waves)");
  }
  return run;
}

nlohmann::json num(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

nlohmann::json run_json(const MruRun& run) {
  const calib::MruEstimateResult& r = run.result;
  nlohmann::json doc;
  doc["method"] = std::string(calib::to_string(r.method));
  doc["arms"] = nlohmann::json::array();
  for (const calib::ArmEstimate& a : r.arms) {
    nlohmann::json arm;
    arm["name"] = a.name;
    arm["x"] = num(a.l_b_m.x());
    arm["y"] = num(a.l_b_m.y());
    arm["z"] = num(a.l_b_m.z());
    arm["std"] = {num(a.std_m.x()), num(a.std_m.y()), num(a.std_m.z())};
    arm["determinacy"] = {std::string(calib::determinacy_name(a.determinacy[0])),
                          std::string(calib::determinacy_name(a.determinacy[1])),
                          std::string(calib::determinacy_name(a.determinacy[2]))};
    doc["arms"].push_back(arm);
  }
  doc["interval_s"] = {r.interval_from_s, r.interval_to_s};
  const calib::MruExcitation& e = r.excitation;
  doc["excitation"] = {{"g_rank3_fraction", e.rank3_fraction},
                       {"g_min_singular_value_median_per_s3", num(e.g_min_sv_median)},
                       {"g_condition_median", num(e.g_condition_median)},
                       {"information_min_eigenvalue_per_s4", num(e.info_min_eig)},
                       {"information_condition", num(e.info_condition)},
                       {"advice", e.advice}};
  doc["notes"] = run.signals.notes;
  doc["units"] = "m, BODY (x forward, y starboard, z down) from the control origin";
  return doc;
}

std::string fmt_or_dash(double v, const char* f) {
  return std::isfinite(v) ? fmt::format(fmt::runtime(f), v) : std::string("—");
}

/// Thesis-table style (tables 4.2–4.5): mean and std per coordinate and the interval; with
/// `truth`, the true arm and the error.
report::Table arm_table(const MruRun& run, const std::map<std::string, Eigen::Vector3d>& truth) {
  report::Table t;
  t.header = {"arm",       "x [m]", "std x [m]", "y [m]",
              "std y [m]", "z [m]", "std z [m]", "interval [s]"};
  if (!truth.empty()) {
    t.header.insert(t.header.end(), {"true x, y, z [m]", "error x, y, z [mm]"});
  }
  for (const calib::ArmEstimate& a : run.result.arms) {
    std::vector<std::string> row = {a.name};
    for (int k = 0; k < 3; ++k) {
      row.push_back(fmt_or_dash(a.l_b_m[k], "{:.4f}"));
      row.push_back(fmt_or_dash(a.std_m[k], "{:.4f}"));
    }
    row.push_back(
        fmt::format("{:.0f} – {:.0f}", run.result.interval_from_s, run.result.interval_to_s));
    if (!truth.empty()) {
      const auto it = truth.find(a.name);
      if (it == truth.end()) {
        row.insert(row.end(), {"—", "—"});
      } else {
        const Eigen::Vector3d& l = it->second;
        const Eigen::Vector3d e = (a.l_b_m - l) * 1000.0;
        row.push_back(fmt::format("{:.3f}, {:.3f}, {:.3f}", l.x(), l.y(), l.z()));
        row.push_back(fmt::format("{:.1f}, {:.1f}, {:.1f}", e.x(), e.y(), e.z()));
      }
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

std::vector<std::filesystem::path> write_plots(
    const MruRun& run, const std::filesystem::path& dir,
    const std::map<std::string, Eigen::Vector3d>& truth) {
  std::filesystem::create_directories(dir);
  std::vector<std::filesystem::path> out;
  const char* axes[3] = {"x", "y", "z"};
  const auto& r = run.result;
  for (std::size_t j = 0; j < r.arms.size(); ++j) {
    report::Figure f;
    f.title =
        "Lever arm " + r.arms[j].name + " (" + std::string(calib::to_string(r.method)) + "), BODY";
    for (int k = 0; k < 3; ++k) {
      report::Panel p;
      p.title = std::string(axes[k]) + " coordinate";
      p.x_axis = {"Time", "s", {}, {}};
      p.y_axis = {std::string("l") + axes[k], "m", {}, {}};
      report::Series s;
      s.label = "estimate";
      s.x = r.history_t_s;
      for (const auto& v : r.history_l_b_m[j]) s.y.push_back(v[k]);
      p.series.push_back(std::move(s));
      const auto it = truth.find(r.arms[j].name);
      if (it != truth.end() && !r.history_t_s.empty()) {
        report::Series tr;
        tr.label = "true";
        tr.x = {r.history_t_s.front(), r.history_t_s.back()};
        tr.y = {it->second[k], it->second[k]};
        tr.dashed = true;
        p.series.push_back(std::move(tr));
      }
      p.x_markers = {r.interval_from_s};
      f.panels.push_back(std::move(p));
    }
    const std::filesystem::path path = dir / (r.arms[j].name + ".svg");
    report::write_svg(path, f);
    out.push_back(path);
  }
  report::Figure g;
  g.title = "Excitation: smallest singular value of G(t) (4.77)";
  report::Panel p;
  p.x_axis = {"Time", "s", {}, {}};
  p.y_axis = {"σ_min(G)", "1/s³", {}, {}};
  p.series.push_back({"σ_min(G)", r.excitation.t_s, r.excitation.g_min_sv, "", 1.5, false});
  p.legend = false;
  g.panels.push_back(std::move(p));
  const std::filesystem::path path = dir / "mru-excitation.svg";
  report::write_svg(path, g);
  out.push_back(path);
  return out;
}

std::map<std::string, Eigen::Vector3d> truth_arms(const std::filesystem::path& truth_json) {
  std::map<std::string, Eigen::Vector3d> out;
  if (!std::filesystem::exists(truth_json)) return out;
  std::ifstream in(truth_json);
  const nlohmann::json doc = nlohmann::json::parse(in, nullptr, false);
  if (doc.is_discarded() || !doc.contains("lever_arms")) return out;
  for (const auto& [name, v] : doc["lever_arms"].items()) {
    if (name.rfind("mru", 0) != 0) continue;
    if (v.is_array() && v.size() == 3) {
      out[name] = {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
    } else if (v.is_object() && v.contains("x_m")) {
      out[name] = {v["x_m"].get<double>(), v["y_m"].get<double>(), v["z_m"].get<double>()};
    }
  }
  return out;
}

void run_cli(const MruCliOptions& o) {
  check_json_target(o.json);
  const MruRun run = analyse(o);
  std::vector<std::filesystem::path> plots;
  if (!o.plots.empty()) plots = write_plots(run, o.plots, {});
  if (!o.json.empty()) io::write_json(o.json, run_json(run));
  std::FILE* out = o.json == "-" ? stderr : stdout;
  const auto& e = run.result.excitation;
  fmt::print(out, "{}: MRU lever arms ({}), BODY from the control origin\n{}", run.log_name,
             calib::to_string(run.result.method), report::render_text(arm_table(run, {})));
  fmt::print(out,
             "excitation (Proposition 3): G(t) rank 3 in {:.0f} % of the samples, median "
             "σ_min(G) {:.2e} 1/s³, median cond(G) {:.1f}; information matrix cond {:.1f}\n",
             100.0 * e.rank3_fraction, e.g_min_sv_median, e.g_condition_median, e.info_condition);
  for (const calib::ArmEstimate& a : run.result.arms) {
    fmt::print(out, "{}: x {}, y {}, z {} determined\n", a.name,
               calib::determinacy_name(a.determinacy[0]), calib::determinacy_name(a.determinacy[1]),
               calib::determinacy_name(a.determinacy[2]));
  }
  for (const std::string& a : e.advice) fmt::print(out, "advice: {}\n", a);
  for (const std::string& n : run.signals.notes) fmt::print(out, "note: {}\n", n);
  for (const auto& p : plots) fmt::print(out, "wrote {}\n", p.string());
  if (!o.json.empty() && o.json != "-") fmt::print(out, "wrote {}\n", o.json);
}

}  // namespace

void add_leverarm_mru(CLI::App& leverarm) {
  auto o = std::make_shared<MruCliOptions>();
  CLI::App* sub = leverarm.add_subcommand(
      "mru", "MRU lever arms: observer (4.80) or least squares, excitation diagnostics (4.77)");
  o->input.add_options(*sub,
                       "time, roll, pitch, heading, p, q, r, u, v, w (optional), and per MRU "
                       "mruK.ax, mruK.ay, mruK.az (or --mru-log)");
  sub->add_option("--mru-log", o->mru_logs,
                  "MRU accelerations in a file of their own (repeatable): NAME=FILE with "
                  "columns time, NAME.ax, NAME.ay, NAME.az");
  sub->add_option("--accel", o->accel,
                  "What the MRU acceleration channels hold: kinematic (gravity removed) or "
                  "specific-force (g rotated into BODY is added back)")
      ->capture_default_str();
  sub->add_option("--method", o->method,
                  "lsq (batch least squares, the default: most accurate) or observer "
                  "(Luenberger observer (4.80))")
      ->capture_default_str();
  sub->add_option("--json", o->json, "Write the arms as JSON to FILE, or '-'");
  sub->add_option("--plots", o->plots, "Write SVG plots of the estimates over time into DIR");
  sub->add_option("--window-s", o->window_s,
                  "Savitzky–Golay smoothing window for ω̇, ν̇ and every term [s]")
      ->capture_default_str();
  sub->add_option("--tau-s", o->tau_s, "Observer convergence time constant [s] (sets W₂)")
      ->capture_default_str();
  sub->add_option("--w1", o->w1_per_s, "Observer gain W₁ on A₀ [1/s] (4.80)")
      ->capture_default_str();
  sub->footer(
      "Model (4.65) in BODY: a_i − a₀ = (S(ω)² + S(ω̇))·l_i, a₀ = ν̇ + ω × ν (4.69). Needs "
      "rotation: a turning circle in waves. Example: dynpos leverarm mru DIR/truth.csv "
      "--mru-log mru1=DIR/log.csv --mru-log mru2=DIR/log.csv --json arms.json --plots plots");
  sub->callback([o] { run_cli(*o); });
}

scenario::ReportSection leverarm_mru_demo_section(const std::filesystem::path& campaign_dir) {
  const std::filesystem::path dir = campaign_dir / "turning-circle";
  const std::filesystem::path log = dir / "log.csv";
  if (!std::filesystem::exists(log)) return {};
  MruCliOptions o;
  // The trial logger has u, v at 1 Hz and no w, too slow for a₀ (4.69) in waves; the motion is
  // taken from the reference motion file when there is one, the accelerations from the log.
  const bool reference = std::filesystem::exists(dir / "truth.csv");
  o.input.log = reference ? dir / "truth.csv" : log;
  if (!reference) {
    o.input.columns = {"roll=mru1.roll", "pitch=mru1.pitch", "p=mru1.p", "q=mru1.q", "r=mru1.r"};
  }
  const core::Log probe = analysis::LogSource{log, {}, {}, {}}.read(is_mru_accel_role);
  for (const std::string& name : mru_names(probe)) o.mru_logs.push_back(name + "=" + log.string());
  const MruRun run = analyse(o);
  const auto truth = truth_arms(dir / "truth.json");
  const std::filesystem::path out = campaign_dir / "analysis" / "leverarm";
  std::filesystem::create_directories(out);
  const auto plots = write_plots(run, out, truth);
  nlohmann::json doc = run_json(run);
  doc["log"] = "turning-circle/log.csv";
  io::write_json(out / "mru.json", doc);
  const report::Table table = arm_table(run, truth);
  const std::string intro = fmt::format(
      "MRU lever arms (`leverarm mru`, thesis 4.3 and 4.4.2) on the turning circle: {} of the "
      "MRU accelerations against the vessel motion{}. Mean and 1σ of each coordinate over the "
      "interval; G(t) (4.77) has rank 3 in {:.0f} % of the samples. JSON: "
      "analysis/leverarm/mru.json.",
      run.result.method == calib::MruMethod::kLsq ? "batch least squares" : "the observer (4.80)",
      reference ? " (motion from truth.csv: the logger's 1 Hz speed log cannot give a₀)" : "",
      100.0 * run.result.excitation.rank3_fraction);
  scenario::ReportSection s;
  s.title = "MRU lever arms";
  s.markdown = intro + "\n\n" + report::render_markdown(table) + "\n";
  s.html = "<p>" + intro + "</p>\n" + report::render_html(table);
  for (const auto& p : plots) {
    const std::string rel = "analysis/leverarm/" + p.filename().string();
    s.markdown += "\n![" + p.stem().string() + "](" + rel + ")\n";
    s.html += "<p><img src=\"" + rel + "\" alt=\"" + p.stem().string() + "\"></p>\n";
  }
  return s;
}

}  // namespace dynpos::cli
