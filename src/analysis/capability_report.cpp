// The capability report: its JSON, table and rose, and the files written (analysis/capability.hpp).

#include <fmt/core.h>

#include "dynpos/analysis/capability.hpp"
#include "dynpos/report/polar_plot.hpp"
#include "dynpos/report/table.hpp"

namespace dynpos::analysis {
namespace {

std::string wind_cell(const capability::CapabilityPoint& p) {
  return fmt::format("{}{:.1f}", p.beyond_table ? "≥ " : "", p.max_wind_mps);
}

nlohmann::json points_json(const std::vector<capability::CapabilityPoint>& points) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& p : points) {
    out.push_back({{"direction_deg", p.direction_deg},
                   {"dp_number", p.dp_number},
                   {"max_wind_mps", p.max_wind_mps},
                   {"limiting", p.limiting},
                   {"failure", p.failure},
                   {"beyond_table", p.beyond_table}});
  }
  return out;
}

report::PolarSeries series(const CapabilityCase& c, bool numbers, const std::string& label,
                           const std::string& color, bool dashed) {
  report::PolarSeries s;
  s.label = label;
  s.color = color;
  s.dashed = dashed;
  for (const auto& p : c.points) {
    s.angle_deg.push_back(p.direction_deg);
    s.radius.push_back(numbers ? p.dp_number : p.max_wind_mps);
  }
  return s;
}

}  // namespace

bool thrust_losses(const CapabilityReport& r) { return r.level >= 2 && r.layout == "model"; }

std::string notation_text(const CapabilityReport& r) {
  const auto n = capability_notation(r);
  const auto cell = [](const std::optional<int>& v) {
    return v ? std::to_string(*v) : std::string("NA");
  };
  return fmt::format("DP capability-L{}({},{},{},{})", r.level, cell(n[0]), cell(n[1]), cell(n[2]),
                     cell(n[3]));
}

nlohmann::json to_json(const CapabilityReport& report) {
  nlohmann::json j;
  j["analysis"] = "capability";
  j["level"] = report.level;
  j["vessel"] = report.vessel;
  if (!report.vessel_source.empty()) j["vessel_file"] = report.vessel_source;
  j["layout"] = report.layout;
  j["thrust_losses"] = thrust_losses(report);
  j["environment"] = report.environment;
  j["failure"] = report.failure;
  j["dynamic_allowance"] = report.dynamic_allowance;
  const auto notation = capability_notation(report);
  nlohmann::json n = nlohmann::json::array();
  for (const auto& v : notation) n.push_back(v ? nlohmann::json(*v) : nlohmann::json());
  j["notation"] = n;
  j["points"] = points_json(report.headline().points);
  j["intact"] = points_json(report.intact.points);
  j["cases"] = nlohmann::json::object();
  for (const auto& c : report.failures) j["cases"][c.failure] = points_json(c.points);
  if (report.time_domain) {
    const auto& o = *report.time_domain;
    j["time_domain"] = {{"duration_s", o.duration_s},
                        {"settle_s", o.settle_s},
                        {"footprint_m", o.footprint_m},
                        {"footprint_deg", o.footprint_deg},
                        {"wind_tolerance_mps", o.wind_tolerance_mps},
                        {"seed", o.seed}};
  }
  return j;
}

std::string to_text(const CapabilityReport& r) {
  std::string out = fmt::format(
      "DP capability, level {} ({}), vessel {}: {}\n{}\n", r.level, r.environment, r.vessel,
      notation_text(r),
      r.time_domain ? fmt::format("time domain: {:.0f} s runs after {:.0f} s, footprint {} m / {} "
                                  "deg",
                                  r.time_domain->duration_s, r.time_domain->settle_s,
                                  r.time_domain->footprint_m, r.time_domain->footprint_deg)
                    : fmt::format("mean load × {} (reserve for dynamics)", r.dynamic_allowance));
  report::Table t;
  t.header = {"dir [deg]", "intact", "wind [m/s]", "limiting"};
  const bool with_failure = !r.failures.empty();
  if (with_failure) {
    const std::string name = r.worst ? "worst" : r.failures.front().failure;
    t.header.insert(t.header.end(), {name, "wind [m/s]", "limiting", "failure"});
  }
  const auto& h = r.headline();
  for (std::size_t i = 0; i < r.intact.points.size(); ++i) {
    const auto& p = r.intact.points[i];
    std::vector<std::string> row = {fmt::format("{:.0f}", p.direction_deg),
                                    std::to_string(p.dp_number), wind_cell(p), p.limiting};
    if (with_failure) {
      const auto& f = h.points[i];
      row.insert(row.end(), {std::to_string(f.dp_number), wind_cell(f), f.limiting, f.failure});
    }
    t.rows.push_back(row);
  }
  if (r.level == 2 && !thrust_losses(r)) {
    out +=
        "no thrust losses: a [[thruster]] layout's units keep their ratings at level 2 (give "
        "the ratings the site's current leaves them)\n";
  }
  return out + report::render_text(t);
}

void write_rose(const CapabilityReport& r, const std::filesystem::path& svg) {
  report::PolarFigure fig;
  fig.title = fmt::format("{} — DP capability level {} ({})", r.vessel, r.level, notation_text(r));
  for (const bool numbers : {true, false}) {
    report::PolarPanel panel;
    panel.title = numbers ? "DP capability number" : "Limiting wind speed";
    panel.radial_label = numbers ? "DP number" : "wind";
    panel.radial_unit = numbers ? "" : "m/s";
    if (numbers) {  // one ring per DP capability number, as the standard draws them
      panel.r_max = 11.0;
      panel.ring_step = 1.0;
    }
    panel.angle_step_deg = 30.0;
    panel.series.push_back(series(r.intact, numbers, "intact", "#1f77b4", false));
    if (!r.failures.empty()) {
      const CapabilityCase& f = r.headline();
      const std::string label = r.worst ? "worst single failure" : "failure: " + f.failure;
      panel.series.push_back(series(f, numbers, label, "#d62728", true));
    }
    fig.panels.push_back(panel);
  }
  report::write_polar_svg(svg, fig);
}

Written write_outputs(const CapabilityReport& report, const Outputs& outputs) {
  Written written;
  if (!outputs.figures.empty()) {
    std::filesystem::create_directories(outputs.figures);
    written.push_back(outputs.figures / "rose.svg");
    write_rose(report, written.back());
  }
  write_json_output(outputs, to_json(report), written);
  return written;
}

}  // namespace dynpos::analysis
