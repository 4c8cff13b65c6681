// The adapters of `leverarm gnss`: JSON, the thesis-style table and text, and the figures.

#include <fmt/core.h>

#include "dynpos/analysis/json_fields.hpp"
#include "dynpos/analysis/leverarm_gnss.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/report/svg_plot.hpp"
#include "leverarm_ins.hpp"

namespace dynpos::analysis {
namespace {

using Vec3 = Eigen::Vector3d;

nlohmann::json vec_json(const Vec3& v) {
  return nlohmann::json::array(
      {io::json_number(v(0)), io::json_number(v(1)), io::json_number(v(2))});
}

nlohmann::json excitation_json(const calib::ExcitationDiagnostics& e) {
  nlohmann::json verdict = nlohmann::json::object();
  const char* axes[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k)
    verdict[axes[k]] = std::string(calib::determinacy_name(e.verdict[static_cast<std::size_t>(k)]));
  return {{"rank3_fraction", e.rank3_fraction},
          {"pe_window_min_eig_rad2ps",
           {io::json_number(e.pe_min_eig_min_rad2ps), io::json_number(e.pe_min_eig_max_rad2ps)}},
          {"gramian_condition", io::json_number(e.gramian_condition)},
          {"predicted_arm_std_m", vec_json(e.predicted_arm_std_m)},
          {"verdict", verdict},
          {"advice", e.advice}};
}

report::Series line(std::string label, const std::vector<double>& x, std::vector<double> y,
                    std::string color = {}, bool dashed = false) {
  report::Series s;
  s.label = std::move(label);
  s.x = x;
  s.y = std::move(y);
  s.color = std::move(color);
  s.dashed = dashed;
  return s;
}

// Figures 4.2–4.5: an arm's coordinates over time, zoomed on the converged interval.
report::Figure arm_figure(const calib::GnssArmResult& r, std::size_t k,
                          const std::map<std::string, Vec3>& truth) {
  const char* axes[3] = {"x", "y", "z"};
  report::Figure f;
  f.title = "Lever arm " + r.arms[k].name + " (" +
            std::string(calib::gnss_arm_method_name(r.method)) + ")";
  for (int j = 0; j < 3; ++j) {
    report::Panel p;
    p.title = std::string(axes[j]) + " (BODY)";
    p.x_axis = {"Time", "s", {}, {}};
    p.y_axis = {std::string("l") + axes[j], "m", {}, {}};
    std::vector<double> y;
    for (const Vec3& a : r.arm_history_b_m[k]) y.push_back(a(j));
    p.series.push_back(line("estimate", r.t_s, y));
    const auto it = truth.find(r.arms[k].name);
    if (it != truth.end())
      p.series.push_back(line("true", {r.t_s.front(), r.t_s.back()}, {it->second(j), it->second(j)},
                              "#d62728", true));
    p.x_markers = {r.converged_from_s};
    // Zoom on the converged interval, where the table's mean and std come from.
    if (r.converged_to_s > r.converged_from_s)
      p.zoom = report::XRange{r.converged_from_s, r.converged_to_s};
    f.panels.push_back(std::move(p));
  }
  return f;
}

// P₀ in the north-east plane: the estimate and what the fixes say with the final arms.
report::Figure p0_figure(const calib::GnssArmResult& r) {
  report::Figure f;
  f.title = "P0, north-east (" + std::string(calib::gnss_arm_method_name(r.method)) + ")";
  f.panel_height_px = 600;
  f.width_px = 700;
  report::Panel p;
  p.x_axis = {"East", "m", {}, {}};
  p.y_axis = {"North", "m", {}, {}};
  std::vector<double> n, e, nm, em;
  for (const Vec3& v : r.p0_n_m) {
    n.push_back(v(0));
    e.push_back(v(1));
  }
  for (const Vec3& v : r.p0_measured_n_m) {
    nm.push_back(v(0));
    em.push_back(v(1));
  }
  // x is east here: an NE plot is not a time series, so x may go back and forth.
  p.series.push_back(line("from the fixes, Pₖ − R·lₖ", em, nm, "#7f7f7f"));
  p.series.push_back(line("estimate", e, n, "#1f77b4"));
  f.panels.push_back(std::move(p));
  return f;
}

// Propositions 1–2 along the log: PE (4.55) and the rank of S² + Ṡ (4.25).
report::Figure excitation_figure(const calib::ExcitationDiagnostics& d) {
  report::Figure f;
  f.title = "Excitation (Propositions 1–2)";
  report::Panel a;
  a.title = "PE: smallest eigenvalue of the windowed integral of SᵀS (4.55)";
  a.x_axis = {"Time", "s", {}, {}};
  a.y_axis = {"λmin", "rad²/s", {}, {}};
  a.series.push_back(line("λmin", d.t_s, d.pe_min_eig_rad2ps));
  report::Panel b;
  b.title = "Observability: rank of S² + Ṡ (4.25)";
  b.x_axis = {"Time", "s", {}, {}};
  b.y_axis = {"rank", "", 0.0, 3.5};
  std::vector<double> rank(d.rank_s2_sdot.begin(), d.rank_s2_sdot.end());
  b.series.push_back(line("rank", d.t_s, rank));
  f.panels = {a, b};
  return f;
}

}  // namespace

nlohmann::json to_json(const LeverarmGnssReport& report) {
  if (report.ins) {
    nlohmann::json j = detail::ins_json(*report.ins);
    j["log"] = report.log.string();
    j["input"] = io::to_json(report.input);
    for (const std::string& n : report.input_notes) j["notes"].push_back(n);
    return j;
  }
  const calib::GnssArmResult& r = report.result;
  nlohmann::json j;
  j["method"] = std::string(calib::gnss_arm_method_name(r.method));
  j["arms"] = nlohmann::json::array();
  for (std::size_t k = 0; k < r.arms.size(); ++k) {
    const calib::ArmEstimate& a = r.arms[k];
    nlohmann::json d = nlohmann::json::array();
    for (const calib::Determinacy x : a.determinacy)
      d.push_back(std::string(calib::determinacy_name(x)));
    j["arms"].push_back({{"name", a.name},
                         {"x", io::json_number(a.l_b_m(0))},
                         {"y", io::json_number(a.l_b_m(1))},
                         {"z", io::json_number(a.l_b_m(2))},
                         {"std", vec_json(a.std_m)},
                         {"determined", d},
                         {"interval_mean", vec_json(r.interval_mean_b_m[k])},
                         {"interval_std", vec_json(r.interval_std_b_m[k])}});
  }
  j["arms_frame"] = "BODY (x forward, y starboard, z down) from P0 [m]";
  j["interval_s"] = {r.converged_from_s, r.converged_to_s};
  const std::size_t last = r.p0_n_m.size() - 1;
  j["p0"] = {{"frame", "local NED of the fixes [m]"},
             {"t_start_s", r.t_s.front()},
             {"start", vec_json(r.p0_n_m.front())},
             {"t_end_s", r.t_s[last]},
             {"end", vec_json(r.p0_n_m[last])}};
  j["excitation"] = excitation_json(r.excitation);
  if (r.method == calib::GnssArmMethod::kAdaptive) j["adaptive_gamma"] = vec_json(r.adaptive_gamma);
  j["time_offset_s"] = r.time_offset_s;
  j["time_offset_estimated"] = r.time_offset_estimated;
  j["time_offset_std_s"] = io::json_number(r.time_offset_std_s);
  j["residual_rms_m"] = vec_json(r.residual_rms_n_m);
  j["epochs"] = r.epochs_used;
  j["notes"] = r.notes;
  j["log"] = report.log.string();
  j["input"] = io::to_json(report.input);
  for (const std::string& n : report.input_notes) j["notes"].push_back(n);
  return j;
}

report::Table arm_table(const LeverarmGnssReport& report) {
  const calib::GnssArmResult& r = report.result;
  report::Table t;
  t.header = {"antenna", "x [m]", "σx [m]", "y [m]", "σy [m]", "z [m]", "σz [m]", "interval [s]"};
  for (const calib::ArmEstimate& a : r.arms) {
    std::vector<std::string> row = {a.name};
    for (int j = 0; j < 3; ++j) {
      row.push_back(number_cell(a.l_b_m(j), "{:.4f}"));
      row.push_back(number_cell(a.std_m(j), "{:.4f}"));
    }
    row.push_back(r.method == calib::GnssArmMethod::kLsq
                      ? fmt::format("{:.0f}–{:.0f} (all)", r.t_s.front(), r.t_s.back())
                      : fmt::format("{:.0f}–{:.0f}", r.converged_from_s, r.converged_to_s));
    t.rows.push_back(std::move(row));
  }
  return t;
}

std::string to_text(const LeverarmGnssReport& report) {
  if (report.ins) {
    std::string out = report.log.string() + ": " + detail::ins_text(*report.ins);
    for (const std::string& n : report.input_notes) out += fmt::format("note: {}\n", n);
    return out + io::to_text(report.input);
  }
  const calib::GnssArmResult& r = report.result;
  std::string out =
      fmt::format("{}: GNSS lever arms, method {}, {} antenna(s), {} epochs\n", report.log.string(),
                  calib::gnss_arm_method_name(r.method), r.arms.size(), r.epochs_used);
  out += report::render_text(arm_table(report));
  if (r.time_offset_estimated)
    out += fmt::format("GNSS time offset: {:.3f} s (±{:.3f} s), estimated\n", r.time_offset_s,
                       r.time_offset_std_s);
  else
    out += fmt::format("GNSS time offset: {:.3f} s (given)\n", r.time_offset_s);
  out += fmt::format("residual rms N/E/D: {:.4f} {:.4f} {:.4f} m\n", r.residual_rms_n_m(0),
                     r.residual_rms_n_m(1), r.residual_rms_n_m(2));
  const calib::ExcitationDiagnostics& e = r.excitation;
  out += fmt::format(
      "excitation: rank[S²+Ṡ] = 3 in {:.0f} % of samples; PE λmin over {:.0f} s windows "
      "{:.3g} … {:.3g} rad²/s; Gramian condition {:.3g}\n",
      100.0 * e.rank3_fraction, report.pe_window_s, e.pe_min_eig_min_rad2ps,
      e.pe_min_eig_max_rad2ps, e.gramian_condition);
  for (const auto& a : r.arms)
    out += fmt::format(
        "  {}: x {}, y {}, z {} determined\n", a.name, calib::determinacy_name(a.determinacy[0]),
        calib::determinacy_name(a.determinacy[1]), calib::determinacy_name(a.determinacy[2]));
  for (const std::string& a : e.advice) out += fmt::format("  advice: {}\n", a);
  for (const std::string& n : r.notes) out += fmt::format("note: {}\n", n);
  for (const std::string& n : report.input_notes) out += fmt::format("note: {}\n", n);
  return out + io::to_text(report.input);
}

std::vector<std::filesystem::path> write_figures(const LeverarmGnssReport& report,
                                                 const std::filesystem::path& dir,
                                                 const std::map<std::string, Vec3>& true_arms_b_m) {
  if (report.ins) return detail::write_ins_figures(*report.ins, dir);
  const calib::GnssArmResult& r = report.result;
  std::filesystem::create_directories(dir);
  std::vector<std::filesystem::path> out;
  for (std::size_t k = 0; k < r.arms.size(); ++k) {
    out.push_back(dir / ("arm-" + r.arms[k].name + ".svg"));
    report::write_svg(out.back(), arm_figure(r, k, true_arms_b_m));
  }
  out.push_back(dir / "p0-ne.svg");
  report::write_svg(out.back(), p0_figure(r));
  out.push_back(dir / "excitation.svg");
  report::write_svg(out.back(), excitation_figure(r.excitation));
  return out;
}

Written write_outputs(const LeverarmGnssReport& report, const Outputs& outputs) {
  Written written;
  if (!outputs.figures.empty()) written = write_figures(report, outputs.figures);
  write_json_output(outputs, to_json(report), written);
  return written;
}

}  // namespace dynpos::analysis
