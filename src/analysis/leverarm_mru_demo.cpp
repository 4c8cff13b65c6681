// The `dynpos demo` section of `leverarm mru`: the turning circle's MRU accelerations against
// the trial's true MRU arms.

#include <fmt/core.h>

#include "dynpos/analysis/demo_sections.hpp"
#include "dynpos/analysis/leverarm_mru.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/scenario/trial_truth.hpp"
#include "leverarm_mru_roles.hpp"

namespace dynpos::analysis {

using Vec3 = Eigen::Vector3d;

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
  const core::Log probe = probe_source.read(detail::is_mru_accel_role);
  for (const std::string& name : detail::mru_names(probe)) q.mru_log[name] = log;
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
