// The adapters of `leverarm mru`: JSON, the thesis-style table and text, and the figures.

#include <fmt/core.h>

#include "dynpos/analysis/json_fields.hpp"
#include "dynpos/analysis/leverarm_mru.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/report/svg_plot.hpp"

namespace dynpos::analysis {

using Vec3 = Eigen::Vector3d;

namespace {

// What the arms are measured from.
std::string origin_name(const LeverarmMruReport& report) {
  return report.reference.empty() ? "the control origin" : report.reference;
}

}  // namespace

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
  doc["reference"] = report.reference.empty() ? "co" : report.reference;
  doc["units"] = "m, BODY (x forward, y starboard, z down) from " + origin_name(report);
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
  std::string out = fmt::format("{}: MRU lever arms ({}), BODY from {}\n{}", report.log.string(),
                                calib::to_string(r.method), origin_name(report),
                                report::render_text(arm_table(report)));
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

Written write_outputs(const LeverarmMruReport& report, const Outputs& outputs) {
  Written written;
  if (!outputs.figures.empty()) written = write_figures(report, outputs.figures);
  write_json_output(outputs, to_json(report), written);
  return written;
}

}  // namespace dynpos::analysis
