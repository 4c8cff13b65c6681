// The adapters of the agility report: JSON, the text table and the polar plot.

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "dynpos/analysis/agility.hpp"
#include "dynpos/analysis/json_fields.hpp"
#include "dynpos/report/polar_plot.hpp"
#include "dynpos/report/table.hpp"

namespace dynpos::analysis {
namespace {

double wrap360(double d) {
  d = std::fmod(d, 360.0);
  return d < 0.0 ? d + 360.0 : d;
}

nlohmann::json cases_json(const AgilityReport& report) {
  nlohmann::json cases = nlohmann::json::array();
  for (const AgilityCase& c : report.cases) {
    nlohmann::json j{{"label", c.label}, {"steps", c.steps.size()}};
    j["wind"] = c.wind ? nlohmann::json{{"speed_mps", c.wind->speed_mps},
                                        {"from_deg", c.wind->from_deg},
                                        {"heading_deg", number_json(c.wind->heading_deg)}}
                       : nlohmann::json(nullptr);
    cases.push_back(j);
  }
  return cases;
}

nlohmann::json step_json(const ident::AgilityStep& s, double min_demand_pct) {
  nlohmann::json j;
  j["direction_deg"] = s.direction_deg;
  j["magnitude_pct"] = s.magnitude_pct;
  j["yaw_pct"] = number_json(s.yaw_pct);
  j["case"] = ident::agility_case_label(s, min_demand_pct);
  j["t_step"] = s.t_step;
  j["t_end"] = s.t_end;
  nlohmann::json resp = nlohmann::json::object();
  nlohmann::json notes = nlohmann::json::object();
  for (const auto& r : s.thrusters) {
    resp[r.name] = number_json(r.response_s);
    if (!r.notes.empty()) notes[r.name] = r.notes;
  }
  j["response_s"] = resp;
  j["thrust_envelope_s"] = number_json(thrust_envelope_s(s));
  j["speed_response_s"] = s.speed ? number_json(s.speed->response_s) : nlohmann::json(nullptr);
  if (s.speed && !s.speed->notes.empty()) notes["speed"] = s.speed->notes;
  j["notes"] = notes;
  return j;
}

// One series of a case's panel: the value of each step (NaN when absent) at its direction.
template <class Get>
report::PolarSeries step_series(const std::vector<const ident::AgilityStep*>& steps,
                                const std::string& label, const Get& get) {
  report::PolarSeries s;
  s.label = label;
  for (const ident::AgilityStep* st : steps) {
    s.angle_deg.push_back(st->direction_deg);
    const std::optional<double> v = get(*st);
    s.radius.push_back(v ? *v : std::nan(""));
  }
  return s;
}

report::PolarPanel case_panel(const AgilityReport& report, const AgilityCase& c) {
  std::vector<const ident::AgilityStep*> steps;
  for (const std::size_t k : c.steps) steps.push_back(&report.result.steps[k]);
  std::stable_sort(steps.begin(), steps.end(), [](const auto* a, const auto* b) {
    return wrap360(a->direction_deg) < wrap360(b->direction_deg);
  });
  report::PolarPanel p;
  p.title = c.label;
  p.radial_label = "Time to 63.2 %";
  p.radial_unit = "s";
  for (std::size_t k = 0; k < report.thrusters.size(); ++k) {
    p.series.push_back(step_series(steps, report.thrusters[k], [k](const ident::AgilityStep& s) {
      return s.thrusters[k].response_s;
    }));
  }
  report::PolarSeries envelope = step_series(steps, "thrust envelope", &thrust_envelope_s);
  envelope.dashed = true;
  envelope.markers = false;
  envelope.color = "#000000";
  envelope.width_px = 2.0;
  p.series.push_back(std::move(envelope));
  if (report.has_speed) {
    report::PolarSeries speed =
        step_series(steps, "speed response", [](const ident::AgilityStep& s) {
          return s.speed ? s.speed->response_s : std::optional<double>{};
        });
    speed.dashed = true;
    speed.color = "#1f9e89";
    speed.width_px = 2.0;
    p.series.push_back(std::move(speed));
  }
  // Wind and current relative to the bow, pointing where they go.
  const double heading = c.wind && c.wind->heading_deg ? *c.wind->heading_deg : 0.0;
  if (c.wind) {
    p.arrows.push_back({fmt::format("wind {:.1f} m/s", c.wind->speed_mps),
                        c.wind->from_deg + 180.0 - heading, 0.75, "#2ca02c"});
  }
  if (report.current) {
    p.arrows.push_back({fmt::format("current {:.1f} m/s", report.current->speed_mps),
                        report.current->to_deg - heading, 0.5, "#9467bd"});
  }
  return p;
}

}  // namespace

report::Table agility_table(const AgilityReport& report) {
  report::Table t;
  t.header = {"case", "direction [°]", "t_step [s]"};
  for (const std::string& n : report.thrusters) t.header.push_back(n + " [s]");
  t.header.push_back("thrust envelope [s]");
  t.header.push_back("speed [s]");
  t.first_numeric_column = 1;
  for (const ident::AgilityStep& s : report.result.steps) {
    std::vector<std::string> row = {ident::agility_case_label(s),
                                    fmt::format("{:.0f}", s.direction_deg),
                                    fmt::format("{:.1f}", s.t_step)};
    for (const auto& r : s.thrusters) row.push_back(number_cell(r.response_s, "{:.1f}"));
    row.push_back(number_cell(thrust_envelope_s(s), "{:.1f}"));
    row.push_back(s.speed ? number_cell(s.speed->response_s, "{:.1f}") : std::string("—"));
    t.rows.push_back(std::move(row));
  }
  return t;
}

nlohmann::json to_json(const AgilityReport& report) {
  nlohmann::json doc;
  doc["analysis"] = "agility";
  doc["log"] = report.log.string();
  doc["input"] = io::to_json(report.input);
  doc["definition"] =
      "time from the step to 63.2 % of the response, dead time included (thesis 3.5.1)";
  doc["channel"] = report.channel;
  doc["thrusters"] = report.thrusters;
  doc["min_response_fraction"] = report.min_response_fraction;
  doc["status"] = std::string(core::status_name(report.result.status));
  doc["message"] = report.result.message;
  doc["current"] = report.current ? nlohmann::json{{"speed_mps", report.current->speed_mps},
                                                   {"to_deg", report.current->to_deg}}
                                  : nlohmann::json(nullptr);
  doc["cases"] = cases_json(report);
  doc["directions"] = nlohmann::json::array();
  for (const ident::AgilityStep& s : report.result.steps) {
    doc["directions"].push_back(step_json(s, report.min_demand_pct));
  }
  return doc;
}

std::string to_text(const AgilityReport& report) {
  std::string out = fmt::format(
      "{}: thrust agility, time from the step to 63.2 % of the response ({} of each "
      "thruster{}), dead time included; — = no response\n{}",
      report.log.string(), report.channel, report.has_speed ? "; speed √(u²+v²)" : "",
      report::render_text(agility_table(report)));
  for (const AgilityCase& c : report.cases) {
    if (c.wind) {
      out += fmt::format("{}: wind {:.1f} m/s from {:.0f}°\n", c.label, c.wind->speed_mps,
                         c.wind->from_deg);
    }
  }
  if (report.result.status == core::Status::kFailed) {
    out += fmt::format("warning: {}\n", report.result.message);
  }
  return out + io::to_text(report.input);
}

void write_plot(const AgilityReport& report, const std::filesystem::path& svg,
                const std::string& title) {
  report::PolarFigure f;
  f.title = title.empty() ? "Thrust agility: " + report.log.filename().string() : title;
  f.panel_size_px = 380.0;
  for (const AgilityCase& c : report.cases) f.panels.push_back(case_panel(report, c));
  report::write_polar_svg(svg, f);
}

Written write_outputs(const AgilityReport& report, const Outputs& outputs) {
  Written written;
  if (!outputs.figures.empty()) {
    write_plot(report, outputs.figures);
    written.push_back(outputs.figures);
  }
  write_json_output(outputs, to_json(report), written);
  return written;
}

}  // namespace dynpos::analysis
