#include "dynpos/analysis/campaign_report.hpp"

#include <fmt/core.h>

#include "dynpos/io/atomic_file.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/io/markup.hpp"

namespace dynpos::analysis {
namespace {

// [kn] of a speed [m/s] (1 kn = 1852 m/h).
double knots(double speed_mps) { return speed_mps * 3600.0 / 1852.0; }

nlohmann::json run_json(const scenario::RunSummary& s) {
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

std::string markdown_table(const std::vector<scenario::RunSummary>& runs) {
  std::string md =
      "| scenario | duration [s] | rows | max speed [kn] | max yaw rate [deg/s] | track [m] | "
      "energy [kJ] | log |\n|---|---:|---:|---:|---:|---:|---:|---|\n";
  for (const scenario::RunSummary& s : runs) {
    md += fmt::format(
        "| {} | {:.0f} | {} | {:.2f} | {:.2f} | {:.0f} | {:.0f} | [{}/log.csv]({}/log.csv) |\n",
        s.name, s.duration_s, s.rows, knots(s.max_speed_mps), s.max_yaw_rate_dps, s.distance_m,
        s.energy_kJ, s.name, s.name);
  }
  return md;
}

std::string html_page(const std::vector<scenario::RunSummary>& runs,
                      const scenario::VesselConfig& vessel, std::uint64_t master_seed,
                      const std::vector<ReportSection>& sections) {
  std::string extra;
  for (const ReportSection& sec : sections) {
    extra += "<h2>" + io::escape_markup(sec.title) + "</h2>\n" + sec.html + "\n";
  }
  std::string rows;
  for (const scenario::RunSummary& s : runs) {
    rows += fmt::format(
        "<tr><td><a href=\"{0}/log.csv\">{0}</a></td><td>{1}</td><td>{2:.0f}</td><td>{3}</td>"
        "<td>{4:.2f}</td><td>{5:.2f}</td><td>{6:.0f}</td><td>{7:.0f}</td>"
        "<td><a href=\"{0}/truth.json\">truth</a></td></tr>\n",
        io::escape_markup(s.name), io::escape_markup(s.description), s.duration_s, s.rows,
        knots(s.max_speed_mps), s.max_yaw_rate_dps, s.distance_m, s.energy_kJ);
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
      io::escape_markup(vessel.name), master_seed, rows, extra);
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  io::AtomicFile file(path);
  file.stream() << text;
  file.commit();
}

}  // namespace

nlohmann::json campaign_json(const std::vector<scenario::RunSummary>& runs,
                             const scenario::VesselConfig& vessel, std::uint64_t master_seed) {
  nlohmann::json summary;
  summary["vessel"] = vessel.name;
  summary["master_seed"] = master_seed;
  summary["scenarios"] = nlohmann::json::array();
  for (const scenario::RunSummary& s : runs) summary["scenarios"].push_back(run_json(s));
  return summary;
}

void write_campaign_report(const std::vector<scenario::RunSummary>& runs,
                           const scenario::VesselConfig& vessel, std::uint64_t master_seed,
                           const std::filesystem::path& out_dir,
                           const std::vector<ReportSection>& sections) {
  std::vector<ReportSection> titled;
  for (const ReportSection& sec : sections) {
    if (!sec.title.empty()) titled.push_back(sec);
  }
  io::write_json(out_dir / "summary.json", campaign_json(runs, vessel, master_seed));
  std::string md = fmt::format("# Virtual sea trial: {}\n\nMaster seed {}.\n\n{}", vessel.name,
                               master_seed, markdown_table(runs));
  for (const ReportSection& sec : titled) md += "\n## " + sec.title + "\n\n" + sec.markdown;
  write_text(out_dir / "summary.md", md);
  write_text(out_dir / "index.html", html_page(runs, vessel, master_seed, titled));
}

std::string campaign_text(const std::vector<scenario::RunSummary>& runs,
                          const std::filesystem::path& out_dir) {
  std::string out;
  double simulated = 0.0, wall = 0.0;
  for (const scenario::RunSummary& r : runs) {
    out += fmt::format("{:<24} {:>6.0f} s simulated in {:5.2f} s  max {:5.2f} kn  {:8.0f} kJ\n",
                       r.name, r.duration_s, r.wall_time_s, knots(r.max_speed_mps), r.energy_kJ);
    simulated += r.duration_s;
    wall += r.wall_time_s;
  }
  out += fmt::format("{} scenarios, {:.0f} s of sea trial in {:.1f} s\n", runs.size(), simulated,
                     wall);
  out += fmt::format("report: {}\n", (out_dir / "index.html").string());
  return out;
}

}  // namespace dynpos::analysis
