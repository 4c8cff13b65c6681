// The `dynpos demo` section of `leverarm mru`: the turning circle's MRU arms from the logger
// alone (log.csv), checked against the trial's true arms.

#include <fmt/core.h>

#include "dynpos/analysis/demo_sections.hpp"
#include "dynpos/analysis/leverarm_mru.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/scenario/trial_truth.hpp"

namespace dynpos::analysis {

using Vec3 = Eigen::Vector3d;

namespace {

// The MRU to measure from: the logger's INS unit, as `leverarm gnss --method ins` takes it.
constexpr const char* kReference = "mru1";

// The true arms [m, BODY] of a trial's truth.json from its MRU `reference`, the check of the
// estimate (never its input); none when the file is missing.
std::map<std::string, Vec3> true_arms_from(const std::filesystem::path& truth_json,
                                           const std::string& reference) {
  std::map<std::string, Vec3> out;
  if (!std::filesystem::exists(truth_json)) return out;
  const auto arms = scenario::read_trial_truth(truth_json).lever_arms;
  const auto ref = arms.find(reference);
  if (ref == arms.end()) return out;
  for (const auto& [name, arm_b] : arms)
    if (name.rfind("mru", 0) == 0 && name != reference) out[name] = arm_b - ref->second;
  return out;
}

}  // namespace

ReportSection leverarm_mru_demo_section(const std::filesystem::path& campaign_dir) {
  const std::filesystem::path dir = campaign_dir / "turning-circle";
  const std::filesystem::path log = dir / "log.csv";
  if (!std::filesystem::exists(log)) return {};
  // The logger alone: the logger's 1 Hz speed log cannot give a₀ (4.69) in waves, so the arms
  // are measured from MRU 1, whose own accelerations stand in for a₀.
  LeverarmMruRequest q;
  q.source.log = log;
  q.reference = kReference;
  q.window_s = 2.0;  // as the ins estimate: half the 1σ of 1 s from the gyros' noise in ω̇
  const LeverarmMruReport report = run_leverarm_mru(q);
  const auto truth = true_arms_from(dir / "truth.json", q.reference);
  const std::filesystem::path out = campaign_dir / "analysis" / "leverarm";
  std::filesystem::create_directories(out);
  const auto plots = write_figures(report, out, truth);
  nlohmann::json doc = to_json(report);
  doc["log"] = "turning-circle/log.csv";
  doc["input"] = io::to_json(relative_to(report.input, campaign_dir));
  io::write_json(out / "mru.json", doc);
  const report::Table table = arm_table(report, truth);
  const std::string intro = fmt::format(
      "MRU lever arms from the logger alone (`leverarm mru --reference {0}`, thesis 4.3 and "
      "4.4.2 with the reference point at {0}) on the turning circle's log.csv: {1} of the other "
      "MRUs' accelerations against {0}'s, with {0}'s rates and the gyro heading, smoothed over "
      "2 s. No velocity "
      "is read (the logger's 1 Hz speed log cannot give the origin's acceleration in waves), so "
      "the arms are from {0}; the true arms' differences (truth.json) are the check. Mean and "
      "1σ of each coordinate over the interval; G(t) (4.77) has rank 3 in {2:.0f} % of the "
      "samples. JSON: analysis/leverarm/mru.json.",
      q.reference,
      report.result.method == calib::MruMethod::kLsq ? "batch least squares"
                                                     : "the observer (4.80)",
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
