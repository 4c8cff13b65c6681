// The adapters of the stationkeeping report: JSON, the thesis-style table and the printed text.

#include <fmt/core.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "dynpos/analysis/json_fields.hpp"
#include "dynpos/analysis/station_keeping.hpp"

namespace dynpos::analysis {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

// A direction [rad] in [0, 360) deg; missing when absent or not finite.
std::optional<double> direction_deg(const std::optional<double>& rad) {
  if (!rad || !std::isfinite(*rad)) return std::nullopt;
  double d = std::fmod(*rad * kDeg, 360.0);
  if (d < 0.0) d += 360.0;
  return d;
}

nlohmann::json direction_json(const std::optional<double>& rad) {
  const std::optional<double> d = direction_deg(rad);
  return d ? nlohmann::json(*d) : nlohmann::json(nullptr);
}

// The value times `scale` with the fmt spec, or "—" when absent (number_cell: an overflow shows
// as "inf", never as missing).
std::string scaled_cell(const std::optional<double>& v, double scale, const char* spec) {
  return number_cell(v ? std::optional<double>(*v * scale) : std::nullopt, spec);
}

// A direction to whole degrees: 359.7 reads 0, not 360.
std::string direction_cell(const std::optional<double>& rad) {
  const std::optional<double> d = direction_deg(rad);
  if (!d) return "—";
  return fmt::format("{}", std::lround(*d) % 360);
}

const ident::ThrusterSummary* find_thruster(const ident::StationKeepingResult& w,
                                            const std::string& name) {
  for (const ident::ThrusterSummary& t : w.thrusters) {
    if (t.name == name) return &t;
  }
  return nullptr;
}

nlohmann::json window_json(const ident::StationKeepingResult& r) {
  nlohmann::json j;
  j["name"] = r.window.name;
  j["t_from"] = r.window.t_from_s;
  j["t_to"] = r.window.t_to_s;
  j["position_samples"] = r.position_samples;
  j["position_std_m"] = {{"north", number_json(r.position_std_north_m)},
                         {"east", number_json(r.position_std_east_m)}};
  j["heading_deg"] = {{"mean", direction_json(r.heading_rad.mean)},
                      {"std", number_json(r.heading_rad.std, kDeg)}};
  j["wind_speed_mps"] = {{"mean", number_json(r.wind_speed_mps.mean)},
                         {"std", number_json(r.wind_speed_mps.std)}};
  j["wind_dir_deg"] = {{"mean", direction_json(r.wind_dir_rad.mean)},
                       {"std", number_json(r.wind_dir_rad.std, kDeg)}};
  nlohmann::json thrust = nlohmann::json::object(), energy = nlohmann::json::object(),
                 accumulated = nlohmann::json::object();
  for (const ident::ThrusterSummary& t : r.thrusters) {
    thrust[t.name] = number_json(t.mean_abs_thrust_N, 1e-3);
    energy[t.name] = number_json(t.energy_J, 1e-3);
    accumulated[t.name] = number_json(t.accumulated_thrust_Ns, 1e-3);
  }
  thrust["total"] = number_json(r.total_mean_abs_thrust_N, 1e-3);
  energy["total"] = number_json(r.total_energy_J, 1e-3);
  accumulated["total"] = number_json(r.total_accumulated_thrust_Ns, 1e-3);
  j["thrusters"] = nlohmann::json::array();
  for (const ident::ThrusterSummary& t : r.thrusters) j["thrusters"].push_back(t.name);
  j["thrust_kN"] = thrust;
  j["energy_kJ"] = energy;
  j["accumulated_thrust_kNs"] = accumulated;
  return j;
}

}  // namespace

nlohmann::json to_json(const StationKeepingReport& report) {
  nlohmann::json doc;
  doc["analysis"] = "station-keeping";
  doc["log"] = report.log.string();
  doc["input"] = io::to_json(report.input);
  doc["observed"] = {
      {"waves", report.waves.empty() ? nlohmann::json(nullptr) : nlohmann::json(report.waves)},
      {"current",
       report.current.empty() ? nlohmann::json(nullptr) : nlohmann::json(report.current)}};
  if (report.windows.size() == 1 && !report.per_setpoint) {
    doc.update(window_json(report.windows.front()));
  } else {
    doc["windows"] = nlohmann::json::array();
    for (const ident::StationKeepingResult& w : report.windows) {
      doc["windows"].push_back(window_json(w));
    }
  }
  return doc;
}

report::Table station_keeping_table(const StationKeepingReport& report) {
  using Window = ident::StationKeepingResult;
  const std::vector<Window>& windows = report.windows;
  report::Table t;
  t.header = {"quantity"};
  for (const Window& w : windows) t.header.push_back(w.window.name);
  using Figure = std::function<std::optional<double>(const Window&)>;
  auto row = [&](const std::string& label, const Figure& get, double scale, const char* spec) {
    std::vector<std::string> r = {label};
    for (const Window& w : windows) r.push_back(scaled_cell(get(w), scale, spec));
    t.rows.push_back(std::move(r));
  };
  row(
      "wind speed mean [m/s]", [](const Window& w) { return w.wind_speed_mps.mean; }, 1.0,
      "{:.1f}");
  row(
      "wind speed std [m/s]", [](const Window& w) { return w.wind_speed_mps.std; }, 1.0, "{:.1f}");
  t.rows.push_back({"wind from, mean [deg]"});
  for (const Window& w : windows) t.rows.back().push_back(direction_cell(w.wind_dir_rad.mean));
  row(
      "wind from, std [deg]", [](const Window& w) { return w.wind_dir_rad.std; }, kDeg, "{:.1f}");
  row(
      "position std north [m]", [](const Window& w) { return w.position_std_north_m; }, 1.0,
      "{:.2f}");
  row(
      "position std east [m]", [](const Window& w) { return w.position_std_east_m; }, 1.0,
      "{:.2f}");
  row(
      "heading mean [deg]", [](const Window& w) { return direction_deg(w.heading_rad.mean); }, 1.0,
      "{:.1f}");
  row(
      "heading std [deg]", [](const Window& w) { return w.heading_rad.std; }, kDeg, "{:.2f}");
  if (windows.empty()) return t;
  // Thrusters in the log's order, the total last.
  std::vector<std::string> names;
  for (const ident::ThrusterSummary& s : windows.front().thrusters) names.push_back(s.name);
  names.emplace_back("total");
  auto thruster_figure = [](const std::string& name, auto member, auto total) -> Figure {
    return [name, member, total](const Window& w) -> std::optional<double> {
      if (name == "total") return w.*total;
      const ident::ThrusterSummary* s = find_thruster(w, name);
      return s ? s->*member : std::nullopt;
    };
  };
  for (const std::string& name : names) {
    row("mean thrust " + name + " [kN]",
        thruster_figure(name, &ident::ThrusterSummary::mean_abs_thrust_N,
                        &Window::total_mean_abs_thrust_N),
        1e-3, "{:.1f}");
  }
  for (const std::string& name : names) {
    row("energy " + name + " [kJ]",
        thruster_figure(name, &ident::ThrusterSummary::energy_J, &Window::total_energy_J), 1e-3,
        "{:.0f}");
  }
  return t;
}

std::string to_text(const StationKeepingReport& report) {
  std::string out =
      fmt::format("{}: stationkeeping, {} window(s)\n", report.log.string(), report.windows.size());
  for (const ident::StationKeepingResult& w : report.windows) {
    out +=
        fmt::format("  {}: {:.1f} … {:.1f} s\n", w.window.name, w.window.t_from_s, w.window.t_to_s);
  }
  if (!report.waves.empty()) out += fmt::format("waves (observed): {}\n", report.waves);
  if (!report.current.empty()) out += fmt::format("current (observed): {}\n", report.current);
  return out + report::render_text(station_keeping_table(report)) + io::to_text(report.input);
}

Written write_outputs(const StationKeepingReport& report, const Outputs& outputs) {
  Written written;
  write_json_output(outputs, to_json(report), written);
  return written;
}

}  // namespace dynpos::analysis
