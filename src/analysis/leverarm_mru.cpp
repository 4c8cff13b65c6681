#include "dynpos/analysis/leverarm_mru.hpp"

#include <fmt/core.h>

#include <cmath>

#include "dynpos/analysis/demo_sections.hpp"
#include "dynpos/analysis/json_fields.hpp"
#include "dynpos/analysis/options.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/report/svg_plot.hpp"
#include "dynpos/scenario/trial_truth.hpp"

namespace dynpos::analysis {
namespace {

using Vec3 = Eigen::Vector3d;

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

// The MRU names K with all of mruK.ax/ay/az in `log`, in channel order.
std::vector<std::string> mru_names(const core::Log& log) {
  std::vector<std::string> out;
  for (const std::string& c : log.channel_names()) {
    if (!is_mru_accel_role(c) || c.substr(c.find('.') + 1) != "ax") continue;
    const std::string name = c.substr(0, c.find('.'));
    if (log.has(name + ".ay") && log.has(name + ".az")) out.push_back(name);
  }
  return out;
}

// One MRU's accelerations in a file of its own.
struct MruFile {
  std::string name, file;
  core::Log log;
  io::InputReport input;
};

// The files of mru_log, each read with its own role mapping NAME.ax/ay/az by header name.
std::vector<MruFile> read_mru_files(const LeverarmMruRequest& q) {
  std::vector<MruFile> out;
  for (const std::string& spec : q.mru_log) {
    const auto eq = spec.find('=');
    const std::string name = spec.substr(0, eq);
    LogSource in = q.source;
    in.log = spec.substr(eq + 1);
    LoadedLog loaded = in.load([name](const std::string& role) {
      return role == name + ".ax" || role == name + ".ay" || role == name + ".az";
    });
    out.push_back({name, in.log.string(), std::move(loaded.log), std::move(loaded.input)});
  }
  return out;
}

}  // namespace

void LeverarmMruRequest::validate() const {
  if (!calib::parse_mru_accel(accel)) {
    throw option_error("accel", "unknown acceleration convention '" + accel + "'",
                       "use --accel kinematic or --accel specific-force");
  }
  if (!calib::parse_mru_method(method)) {
    throw option_error("method", "unknown method '" + method + "'",
                       "use --method lsq or --method observer");
  }
  // The smoother's window is a count of samples: bounded so that it is one at any log rate.
  if (!(window_s > 0.0 && window_s <= 600.0)) {
    throw option_error("window_s", fmt::format("{} s is not a window in (0, 600] s", window_s),
                       "about 1 s suits a 100 Hz MRU");
  }
  if (!(tau_s > 0.0 && tau_s <= 3600.0)) {
    throw option_error("tau_s", fmt::format("{} s is not a time constant in (0, 3600] s", tau_s),
                       "the default is 5 s");
  }
  if (!(w1 > 0.0) || !std::isfinite(w1)) {
    throw option_error("w1", fmt::format("{} is not a gain W₁ > 0 [1/s]", w1),
                       "the default is 0.01");
  }
  for (const std::string& spec : mru_log) {
    const auto eq = spec.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size()) {
      throw option_error("mru_log", "malformed argument '" + spec + "'",
                         "expected NAME=FILE, e.g. --mru-log mru1=mru1.csv");
    }
  }
}

LeverarmMruReport run_leverarm_mru(const LeverarmMruRequest& q) {
  q.validate();
  LoadedLog loaded = q.source.load(wanted_role);
  const core::Log& motion = loaded.log;
  const std::vector<MruFile> files = read_mru_files(q);
  std::vector<calib::MruSource> sources;
  for (const MruFile& e : files) {
    sources.push_back({e.name, &e.log, e.file});
    loaded.input.append(e.input);
  }
  for (const std::string& name : mru_names(motion)) {
    bool dup = false;
    for (const auto& s : sources) dup = dup || s.name == name;
    if (!dup) sources.push_back({name, &motion, q.source.log.string()});
  }
  calib::MruSignalOptions so;
  so.accel = *calib::parse_mru_accel(q.accel);
  so.smooth_window_s = q.window_s;
  const calib::MruSignals signals = calib::mru_signals_from_logs(motion, sources, so);
  calib::MruEstimateOptions eo;
  eo.method = *calib::parse_mru_method(q.method);
  eo.tau_s = q.tau_s;
  eo.w1_per_s = q.w1;
  LeverarmMruReport report;
  report.log = q.source.log;
  report.input = std::move(loaded.input);
  report.result = calib::estimate_mru_arms(signals, eo);
  if (report.result.status != core::Status::kOk) {
    throw core::InputError({q.source.log.string(), {}, {}, "time"}, report.result.message,
                           "log a longer maneuver with rotation (a turning circle in waves)");
  }
  report.notes = signals.notes;
  return report;
}

nlohmann::json to_json(const LeverarmMruReport& report) {
  const calib::MruEstimateResult& r = report.result;
  nlohmann::json doc;
  doc["method"] = std::string(calib::to_string(r.method));
  doc["input"] = io::to_json(report.input);
  doc["arms"] = nlohmann::json::array();
  for (const calib::ArmEstimate& a : r.arms) {
    nlohmann::json arm;
    arm["name"] = a.name;
    arm["x"] = number_json(a.l_b_m.x());
    arm["y"] = number_json(a.l_b_m.y());
    arm["z"] = number_json(a.l_b_m.z());
    arm["std"] = {number_json(a.std_m.x()), number_json(a.std_m.y()), number_json(a.std_m.z())};
    arm["determinacy"] = {std::string(calib::determinacy_name(a.determinacy[0])),
                          std::string(calib::determinacy_name(a.determinacy[1])),
                          std::string(calib::determinacy_name(a.determinacy[2]))};
    doc["arms"].push_back(arm);
  }
  doc["interval_s"] = {r.interval_from_s, r.interval_to_s};
  const calib::MruExcitation& e = r.excitation;
  doc["excitation"] = {{"g_rank3_fraction", e.rank3_fraction},
                       {"g_min_singular_value_median_per_s3", number_json(e.g_min_sv_median)},
                       {"g_condition_median", number_json(e.g_condition_median)},
                       {"information_min_eigenvalue_per_s4", number_json(e.info_min_eig)},
                       {"information_condition", number_json(e.info_condition)},
                       {"advice", e.advice}};
  doc["notes"] = report.notes;
  doc["units"] = "m, BODY (x forward, y starboard, z down) from the control origin";
  return doc;
}

report::Table arm_table(const LeverarmMruReport& report,
                        const std::map<std::string, Vec3>& true_arms_b_m) {
  const calib::MruEstimateResult& r = report.result;
  report::Table t;
  t.header = {"arm",       "x [m]", "std x [m]", "y [m]",
              "std y [m]", "z [m]", "std z [m]", "interval [s]"};
  if (!true_arms_b_m.empty()) {
    t.header.insert(t.header.end(), {"true x, y, z [m]", "error x, y, z [mm]"});
  }
  for (const calib::ArmEstimate& a : r.arms) {
    std::vector<std::string> row = {a.name};
    for (int k = 0; k < 3; ++k) {
      row.push_back(number_cell(a.l_b_m[k], "{:.4f}"));
      row.push_back(number_cell(a.std_m[k], "{:.4f}"));
    }
    row.push_back(fmt::format("{:.0f} – {:.0f}", r.interval_from_s, r.interval_to_s));
    if (!true_arms_b_m.empty()) {
      const auto it = true_arms_b_m.find(a.name);
      if (it == true_arms_b_m.end()) {
        row.insert(row.end(), {"—", "—"});
      } else {
        const Vec3& l = it->second;
        const Vec3 e = (a.l_b_m - l) * 1000.0;
        row.push_back(fmt::format("{:.3f}, {:.3f}, {:.3f}", l.x(), l.y(), l.z()));
        row.push_back(fmt::format("{:.1f}, {:.1f}, {:.1f}", e.x(), e.y(), e.z()));
      }
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

std::string to_text(const LeverarmMruReport& report) {
  const calib::MruEstimateResult& r = report.result;
  const auto& e = r.excitation;
  std::string out =
      fmt::format("{}: MRU lever arms ({}), BODY from the control origin\n{}", report.log.string(),
                  calib::to_string(r.method), report::render_text(arm_table(report)));
  out += fmt::format(
      "excitation (Proposition 3): G(t) rank 3 in {:.0f} % of the samples, median "
      "σ_min(G) {:.2e} 1/s³, median cond(G) {:.1f}; information matrix cond {:.1f}\n",
      100.0 * e.rank3_fraction, e.g_min_sv_median, e.g_condition_median, e.info_condition);
  for (const calib::ArmEstimate& a : r.arms) {
    out += fmt::format(
        "{}: x {}, y {}, z {} determined\n", a.name, calib::determinacy_name(a.determinacy[0]),
        calib::determinacy_name(a.determinacy[1]), calib::determinacy_name(a.determinacy[2]));
  }
  for (const std::string& a : e.advice) out += fmt::format("advice: {}\n", a);
  for (const std::string& n : report.notes) out += fmt::format("note: {}\n", n);
  return out + io::to_text(report.input);
}

std::vector<std::filesystem::path> write_figures(const LeverarmMruReport& report,
                                                 const std::filesystem::path& dir,
                                                 const std::map<std::string, Vec3>& true_arms_b_m) {
  std::filesystem::create_directories(dir);
  std::vector<std::filesystem::path> out;
  const char* axes[3] = {"x", "y", "z"};
  const auto& r = report.result;
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
      const auto it = true_arms_b_m.find(r.arms[j].name);
      if (it != true_arms_b_m.end() && !r.history_t_s.empty()) {
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
    out.push_back(dir / (r.arms[j].name + ".svg"));
    report::write_svg(out.back(), f);
  }
  report::Figure g;
  g.title = "Excitation: smallest singular value of G(t) (4.77)";
  report::Panel p;
  p.x_axis = {"Time", "s", {}, {}};
  p.y_axis = {"σ_min(G)", "1/s³", {}, {}};
  p.series.push_back({"σ_min(G)", r.excitation.t_s, r.excitation.g_min_sv, "", 1.5, false});
  p.legend = false;
  g.panels.push_back(std::move(p));
  out.push_back(dir / "mru-excitation.svg");
  report::write_svg(out.back(), g);
  return out;
}

namespace {

// The true MRU arms [m, BODY] of a trial's truth.json; none when the file is missing.
std::map<std::string, Vec3> true_mru_arms(const std::filesystem::path& truth_json) {
  std::map<std::string, Vec3> out;
  if (!std::filesystem::exists(truth_json)) return out;
  for (const auto& [name, arm_b] : scenario::read_trial_truth(truth_json).lever_arms)
    if (name.rfind("mru", 0) == 0) out[name] = arm_b;
  return out;
}

}  // namespace

ReportSection leverarm_mru_demo_section(const std::filesystem::path& campaign_dir) {
  const std::filesystem::path dir = campaign_dir / "turning-circle";
  const std::filesystem::path log = dir / "log.csv";
  if (!std::filesystem::exists(log)) return {};
  LeverarmMruRequest q;
  // The trial logger has u, v at 1 Hz and no w, too slow for a₀ (4.69) in waves; the motion is
  // taken from the reference motion file when there is one, the accelerations from the log.
  const bool reference = std::filesystem::exists(dir / "truth.csv");
  q.source.log = reference ? dir / "truth.csv" : log;
  if (!reference) {
    q.source.columns = {"roll=mru1.roll", "pitch=mru1.pitch", "p=mru1.p", "q=mru1.q", "r=mru1.r"};
  }
  LogSource probe_source;
  probe_source.log = log;
  const core::Log probe = probe_source.read(is_mru_accel_role);
  for (const std::string& name : mru_names(probe)) q.mru_log.push_back(name + "=" + log.string());
  const LeverarmMruReport report = run_leverarm_mru(q);
  const auto truth = true_mru_arms(dir / "truth.json");
  const std::filesystem::path out = campaign_dir / "analysis" / "leverarm";
  std::filesystem::create_directories(out);
  const auto plots = write_figures(report, out, truth);
  nlohmann::json doc = to_json(report);
  doc["log"] = "turning-circle/log.csv";
  doc["input"] = io::to_json(relative_to(report.input, campaign_dir));
  io::write_json(out / "mru.json", doc);
  const report::Table table = arm_table(report, truth);
  const std::string intro = fmt::format(
      "MRU lever arms (`leverarm mru`, thesis 4.3 and 4.4.2) on the turning circle: {} of the "
      "MRU accelerations against the vessel motion{}. Mean and 1σ of each coordinate over the "
      "interval; G(t) (4.77) has rank 3 in {:.0f} % of the samples. JSON: "
      "analysis/leverarm/mru.json.",
      report.result.method == calib::MruMethod::kLsq ? "batch least squares"
                                                     : "the observer (4.80)",
      reference ? " (motion from truth.csv: the logger's 1 Hz speed log cannot give a₀)" : "",
      100.0 * report.result.excitation.rank3_fraction);
  ReportSection s;
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

}  // namespace dynpos::analysis
