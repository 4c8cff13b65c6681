// The adapters of the 4-corner report: JSON, table 3.6 and the NE plot.

#include <fmt/core.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "dynpos/analysis/four_corner.hpp"
#include "dynpos/analysis/json_fields.hpp"
#include "dynpos/report/svg_plot.hpp"

namespace dynpos::analysis {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

nlohmann::json leg_json(const ident::Leg& leg, bool with_move) {
  nlohmann::json j;
  j["name"] = leg.name;
  j["t_start"] = leg.t_start_s;
  j["t_end"] = leg.t_end_s;
  j["duration_s"] = leg.duration_s;
  j["reached"] = leg.reached;
  if (with_move) {
    j["move"] = {{"forward_m", leg.forward_m},
                 {"starboard_m", leg.starboard_m},
                 {"heading_change_deg", leg.heading_change_rad * kDeg}};
    if (leg.setpoint_north_m || leg.setpoint_east_m || leg.setpoint_heading_rad) {
      j["setpoint"] = {{"north_m", number_json(leg.setpoint_north_m)},
                       {"east_m", number_json(leg.setpoint_east_m)},
                       {"heading_deg", number_json(leg.setpoint_heading_rad, kDeg)}};
    } else {
      j["setpoint"] = nullptr;
    }
  }
  nlohmann::json thrust = nlohmann::json::object(), energy = nlohmann::json::object();
  for (const auto& t : leg.thrusters) {
    thrust[t.name] = number_json(t.accumulated_thrust_Ns, 1e-3);
    energy[t.name] = number_json(t.energy_J, 1e-3);
  }
  thrust["total"] = number_json(leg.total_accumulated_thrust_Ns, 1e-3);
  energy["total"] = number_json(leg.total_energy_J, 1e-3);
  j["thrust_kNs"] = thrust;
  j["energy_kJ"] = energy;
  return j;
}

// A figure of a leg in kilo-units [kNs, kJ] with no decimals, "—" when missing.
std::string kilo_cell(const std::optional<double>& v) {
  return number_cell(v ? std::optional<double>(*v * 1e-3) : std::nullopt, "{:.0f}");
}

// The accumulated thrust and energy of the thruster `name` over a leg; "total" is the sum.
std::pair<std::optional<double>, std::optional<double>> leg_figures(const ident::Leg& leg,
                                                                    const std::string& name) {
  if (name == "total") return {leg.total_accumulated_thrust_Ns, leg.total_energy_J};
  for (const auto& t : leg.thrusters) {
    if (t.name == name) return {t.accumulated_thrust_Ns, t.energy_J};
  }
  return {std::nullopt, std::nullopt};
}

std::vector<std::string> leg_row(const ident::Leg& leg, std::string name,
                                 const std::vector<std::string>& thrusters) {
  if (!leg.reached) name += " (not reached)";
  std::vector<std::string> r = {name, fmt::format("{:.1f}", leg.t_start_s),
                                fmt::format("{:.1f}", leg.t_end_s),
                                fmt::format("{:.0f}", leg.duration_s)};
  for (const auto& n : thrusters) r.push_back(kilo_cell(leg_figures(leg, n).first));
  for (const auto& n : thrusters) r.push_back(kilo_cell(leg_figures(leg, n).second));
  return r;
}

// The points of the track with time in [t0, t1] and a position.
report::Series track_series(const ident::FourCornerInput& in, report::Series s, double t0,
                            double t1) {
  for (std::size_t i = 0; i < in.t_s.size(); ++i) {
    if (in.t_s[i] < t0 || in.t_s[i] > t1) continue;
    if (std::isnan(in.north_m[i]) || std::isnan(in.east_m[i])) continue;
    s.x.push_back(in.east_m[i]);
    s.y.push_back(in.north_m[i]);
  }
  return s;
}

}  // namespace

nlohmann::json to_json(const FourCornerReport& report) {
  const ident::FourCornerResult& r = report.result;
  nlohmann::json doc;
  doc["analysis"] = "four-corner";
  doc["log"] = report.log.string();
  doc["input"] = io::to_json(report.input);
  doc["segmentation"] = r.segmentation;
  doc["radius_m"] = report.radius_m;
  doc["arm_m"] = report.arm_m ? nlohmann::json::array({report.arm_m->x(), report.arm_m->y()})
                              : nlohmann::json(nullptr);
  doc["heading_tol_deg"] = report.heading_tol_deg;
  doc["thrusters"] = nlohmann::json::array();
  for (const auto& t : r.total.thrusters) doc["thrusters"].push_back(t.name);
  doc["legs"] = nlohmann::json::array();
  for (const auto& leg : r.legs) doc["legs"].push_back(leg_json(leg, true));
  doc["total"] = leg_json(r.total, false);
  return doc;
}

report::Table four_corner_table(const FourCornerReport& report) {
  std::vector<std::string> names;
  for (const auto& t : report.result.total.thrusters) names.push_back(t.name);
  names.emplace_back("total");
  report::Table t;
  t.header = {"leg", "start [s]", "end [s]", "duration [s]"};
  for (const auto& n : names) t.header.push_back("thrust " + n + " [kNs]");
  for (const auto& n : names) t.header.push_back("energy " + n + " [kJ]");
  for (const auto& leg : report.result.legs) t.rows.push_back(leg_row(leg, leg.name, names));
  t.rows.push_back(leg_row(report.result.total, "total", names));
  return t;
}

std::string to_text(const FourCornerReport& report) {
  return fmt::format("{}: DP 4-corner, {} legs from the {}\n{}", report.log.string(),
                     report.result.legs.size(), report.result.segmentation,
                     report::render_text(four_corner_table(report))) +
         io::to_text(report.input);
}

void write_plot(const FourCornerReport& report, const std::filesystem::path& svg,
                const std::string& title) {
  const ident::FourCornerInput& in = report.track;
  const ident::FourCornerResult& r = report.result;
  report::Panel p;
  p.title = "Track (" + r.segmentation + " segmentation)";
  p.x_axis = {"East", "m", {}, {}};
  p.y_axis = {"North", "m", {}, {}};
  const double inf = std::numeric_limits<double>::infinity();
  p.series.push_back(track_series(in, {"whole log", {}, {}, "#bbbbbb", 1.0, false}, -inf, inf));
  for (const auto& leg : r.legs) {
    p.series.push_back(
        track_series(in, {leg.name, {}, {}, "", 1.8, false}, leg.t_start_s, leg.t_end_s));
  }
  if (r.segmentation == "setpoints") {
    report::Series box{"setpoints", {}, {}, "#000000", 1.0, true};
    for (const auto& leg : r.legs) {
      if (leg.setpoint_north_m && leg.setpoint_east_m) {
        box.x.push_back(*leg.setpoint_east_m);
        box.y.push_back(*leg.setpoint_north_m);
      }
    }
    if (!box.x.empty()) p.series.push_back(std::move(box));
  }
  report::Figure f;
  f.title = title.empty() ? "DP 4-corner: " + report.log.string() : title;
  f.width_px = 700.0;
  f.panel_height_px = 600.0;
  f.panels.push_back(std::move(p));
  report::write_svg(svg, f);
}

Written write_outputs(const FourCornerReport& report, const Outputs& outputs) {
  Written written;
  if (!outputs.figures.empty()) {
    write_plot(report, outputs.figures);
    written.push_back(outputs.figures);
  }
  write_json_output(outputs, to_json(report), written);
  return written;
}

}  // namespace dynpos::analysis
