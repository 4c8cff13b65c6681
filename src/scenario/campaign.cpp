#include "dynpos/scenario/campaign.hpp"

#include <fmt/core.h>

#include <chrono>
#include <cmath>

#include "dynpos/io/atomic_file.hpp"
#include "dynpos/io/csv_writer.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/scenario/runner.hpp"
#include "dynpos/sim/random.hpp"

namespace dynpos::scenario {
namespace {

RunSummary summarise(const ScenarioSpec& spec, const ScenarioRun& run, std::uint64_t seed) {
  RunSummary s;
  s.name = spec.name;
  s.description = spec.description;
  s.duration_s = spec.duration_s;
  s.rows = run.log.size();
  s.seed = seed;
  const core::Log& truth = run.truth_log;  // the summary describes what truly happened
  const auto& t = truth.time();
  const auto& u = truth.values("u");
  const auto& v = truth.values("v");
  const auto& r = truth.values("r");
  const auto& n = truth.values("north");
  const auto& e = truth.values("east");
  const auto& pp = truth.values("power.port");
  const auto& ps = truth.values("power.stb");
  const auto& pt = truth.values("power.tunnel");
  double energy_J = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    s.max_speed_mps = std::max(s.max_speed_mps, std::hypot(u[i], v[i]));
    s.max_yaw_rate_dps = std::max(s.max_yaw_rate_dps, std::abs(r[i]) * 180.0 / M_PI);
    if (i > 0) {
      const double dt = t[i] - t[i - 1];
      s.distance_m += std::hypot(n[i] - n[i - 1], e[i] - e[i - 1]);
      // Trapezoidal ∫P dt over the log samples.
      energy_J += 0.5 * dt * (pp[i] + ps[i] + pt[i] + pp[i - 1] + ps[i - 1] + pt[i - 1]);
    }
  }
  s.energy_kJ = energy_J / 1e3;
  return s;
}

nlohmann::json to_json(const RunSummary& s) {
  return {{"name", s.name},
          {"description", s.description},
          {"duration_s", s.duration_s},
          {"rows", s.rows},
          {"seed", s.seed},
          {"max_speed_mps", s.max_speed_mps},
          {"max_yaw_rate_dps", s.max_yaw_rate_dps},
          {"distance_m", s.distance_m},
          {"energy_kJ", s.energy_kJ},
          {"log", s.name + "/log.csv"},
          {"truth_log", s.name + "/truth.csv"},
          {"truth", s.name + "/truth.json"}};
}

std::string markdown_table(const std::vector<RunSummary>& runs) {
  std::string md =
      "| scenario | duration [s] | rows | max speed [kn] | max yaw rate [deg/s] | track [m] | "
      "energy [kJ] | log |\n|---|---:|---:|---:|---:|---:|---:|---|\n";
  for (const RunSummary& s : runs) {
    md += fmt::format(
        "| {} | {:.0f} | {} | {:.2f} | {:.2f} | {:.0f} | {:.0f} | [{}/log.csv]({}/log.csv) |\n",
        s.name, s.duration_s, s.rows, s.max_speed_mps * 3600.0 / 1852.0, s.max_yaw_rate_dps,
        s.distance_m, s.energy_kJ, s.name, s.name);
  }
  return md;
}

std::string html_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string html_page(const std::vector<RunSummary>& runs, const VesselConfig& vessel,
                      std::uint64_t master_seed, const std::vector<ReportSection>& sections) {
  std::string extra;
  for (const ReportSection& sec : sections) {
    extra += "<h2>" + html_escape(sec.title) + "</h2>\n" + sec.html + "\n";
  }
  std::string rows;
  for (const RunSummary& s : runs) {
    rows += fmt::format(
        "<tr><td><a href=\"{0}/log.csv\">{0}</a></td><td>{1}</td><td>{2:.0f}</td><td>{3}</td>"
        "<td>{4:.2f}</td><td>{5:.2f}</td><td>{6:.0f}</td><td>{7:.0f}</td>"
        "<td><a href=\"{0}/truth.json\">truth</a></td></tr>\n",
        html_escape(s.name), html_escape(s.description), s.duration_s, s.rows,
        s.max_speed_mps * 3600.0 / 1852.0, s.max_yaw_rate_dps, s.distance_m, s.energy_kJ);
  }
  return fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
      "<title>dynpos virtual sea trial — {0}</title>\n<style>body{{font-family:sans-serif;"
      "margin:2em;max-width:70em}}table{{border-collapse:collapse}}td,th{{border:1px solid #ccc;"
      "padding:0.3em 0.6em;text-align:right}}td:nth-child(2){{text-align:left}}</style></head>\n"
      "<body><h1>Virtual sea trial: {0}</h1>\n<p>Master seed {1}. Each scenario folder holds "
      "<code>log.csv</code> (the trial logger: sensors at their rates, commands; columns in "
      "docs/log-format.md), <code>truth.csv</code> (the true motion) and <code>truth.json</code> "
      "(the true parameters, lever arms, command times and time "
      "constants).</p>\n<table><tr><th>scenario</th>"
      "<th>what</th><th>duration [s]</th><th>rows</th><th>max speed [kn]</th>"
      "<th>max yaw rate [deg/s]</th><th>track [m]</th><th>energy [kJ]</th><th></th></tr>\n{2}"
      "</table>\n{3}</body></html>\n",
      html_escape(vessel.name), master_seed, rows, extra);
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  io::AtomicFile file(path);
  file.stream() << text;
  file.commit();
}

}  // namespace

std::uint64_t campaign_seed(std::uint64_t master_seed, const std::string& scenario_name) {
  return sim::stream_seed(master_seed, scenario_name);
}

void write_scenario_run(const ScenarioRun& run, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  io::write_csv(dir / "log.csv", run.log);
  io::write_csv(dir / "truth.csv", run.truth_log);
  io::write_json((dir / "truth.json").string(), run.truth);
}

std::vector<RunSummary> run_campaign(const std::vector<ScenarioSpec>& scenarios,
                                     const VesselConfig& vessel, std::uint64_t master_seed,
                                     const std::filesystem::path& out_dir) {
  std::vector<RunSummary> summaries;
  for (const ScenarioSpec& spec : scenarios) {
    const std::uint64_t seed = campaign_seed(master_seed, spec.name);
    const auto start = std::chrono::steady_clock::now();
    const ScenarioRun run = run_scenario(spec, vessel, seed);
    const std::filesystem::path dir = out_dir / spec.name;
    write_scenario_run(run, dir);
    RunSummary s = summarise(spec, run, seed);
    s.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    summaries.push_back(s);
  }
  nlohmann::json summary;
  summary["vessel"] = vessel.name;
  summary["master_seed"] = master_seed;
  summary["scenarios"] = nlohmann::json::array();
  for (const RunSummary& s : summaries) summary["scenarios"].push_back(to_json(s));
  io::write_json((out_dir / "summary.json").string(), summary);
  write_campaign_report(summaries, vessel, master_seed, out_dir, {});
  return summaries;
}

void write_campaign_report(const std::vector<RunSummary>& summaries, const VesselConfig& vessel,
                           std::uint64_t master_seed, const std::filesystem::path& out_dir,
                           const std::vector<ReportSection>& sections) {
  std::string md = fmt::format("# Virtual sea trial: {}\n\nMaster seed {}.\n\n{}", vessel.name,
                               master_seed, markdown_table(summaries));
  for (const ReportSection& sec : sections) md += "\n## " + sec.title + "\n\n" + sec.markdown;
  write_text(out_dir / "summary.md", md);
  write_text(out_dir / "index.html", html_page(summaries, vessel, master_seed, sections));
}

}  // namespace dynpos::scenario
