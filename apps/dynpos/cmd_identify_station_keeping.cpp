// dynpos identify station-keeping: pure-DP statistics over a window or per setpoint hold
// (thesis tables 3.11-3.22).

#include <fmt/core.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/ident/local_position.hpp"
#include "dynpos/ident/station_keeping.hpp"
#include "dynpos/io/atomic_file.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/report/table.hpp"
#include "log_input.hpp"

namespace dynpos::cli {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

struct StationKeepingOptions {
  LogInput input;
  std::optional<double> t_from, t_to;
  double duration_s = 300.0;
  bool per_setpoint = false;
  std::string waves, current;
  std::string json;
};

bool wanted_role(const std::string& role) {
  for (const char* r : {"north", "east", "lat", "lon", "heading", "wind_speed", "wind_dir",
                        "setpoint.north", "setpoint.east", "setpoint.heading"}) {
    if (role == r) return true;
  }
  return role.rfind("thrust.", 0) == 0 || role.rfind("power.", 0) == 0;
}

std::vector<double> values_or_empty(const core::Log& log, const std::string& name) {
  return log.has(name) ? log.values(name) : std::vector<double>{};
}

ident::StationKeepingInput make_input(const core::Log& log) {
  ident::StationKeepingInput in;
  in.t_s = log.time();
  if (log.has("north") && log.has("east")) {
    in.north_m = log.values("north");
    in.east_m = log.values("east");
  } else if (log.has("lat") && log.has("lon")) {
    const ident::LocalPositions p = ident::local_north_east(log.values("lat"), log.values("lon"));
    in.north_m = p.north_m;
    in.east_m = p.east_m;
  }
  in.heading_rad = values_or_empty(log, "heading");
  in.wind_speed_mps = values_or_empty(log, "wind_speed");
  in.wind_dir_rad = values_or_empty(log, "wind_dir");
  std::vector<std::string> names = thruster_names(log, "thrust");
  for (const std::string& n : thruster_names(log, "power")) {
    if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  }
  for (const std::string& n : names) {
    in.thrusters.push_back(
        {n, values_or_empty(log, "thrust." + n), values_or_empty(log, "power." + n)});
  }
  return in;
}

nlohmann::json num(const std::optional<double>& v, double scale = 1.0) {
  return v && std::isfinite(*v) ? nlohmann::json(*v * scale) : nlohmann::json(nullptr);
}

nlohmann::json deg360(const std::optional<double>& rad) {
  if (!rad || !std::isfinite(*rad)) return nullptr;
  double d = std::fmod(*rad * kDeg, 360.0);
  if (d < 0.0) d += 360.0;
  return d;
}

nlohmann::json window_json(const ident::StationKeepingResult& r) {
  nlohmann::json j;
  j["name"] = r.window.name;
  j["t_from"] = r.window.t_from_s;
  j["t_to"] = r.window.t_to_s;
  j["position_samples"] = r.position_samples;
  j["position_std_m"] = {{"north", num(r.position_std_north_m)},
                         {"east", num(r.position_std_east_m)}};
  j["heading_deg"] = {{"mean", deg360(r.heading_rad.mean)}, {"std", num(r.heading_rad.std, kDeg)}};
  j["wind_speed_mps"] = {{"mean", num(r.wind_speed_mps.mean)}, {"std", num(r.wind_speed_mps.std)}};
  j["wind_dir_deg"] = {{"mean", deg360(r.wind_dir_rad.mean)},
                       {"std", num(r.wind_dir_rad.std, kDeg)}};
  nlohmann::json thrust = nlohmann::json::object(), energy = nlohmann::json::object(),
                 accumulated = nlohmann::json::object();
  for (const auto& t : r.thrusters) {
    thrust[t.name] = num(t.mean_abs_thrust_N, 1e-3);
    energy[t.name] = num(t.energy_J, 1e-3);
    accumulated[t.name] = num(t.accumulated_thrust_Ns, 1e-3);
  }
  thrust["total"] = num(r.total_mean_abs_thrust_N, 1e-3);
  energy["total"] = num(r.total_energy_J, 1e-3);
  accumulated["total"] = num(r.total_accumulated_thrust_Ns, 1e-3);
  j["thrusters"] = nlohmann::json::array();
  for (const auto& t : r.thrusters) j["thrusters"].push_back(t.name);
  j["thrust_kN"] = thrust;
  j["energy_kJ"] = energy;
  j["accumulated_thrust_kNs"] = accumulated;
  return j;
}

std::string cell(const nlohmann::json& v, const char* spec) {
  return v.is_number() ? fmt::format(fmt::runtime(spec), v.get<double>()) : std::string("—");
}

// A direction in [0, 360) to whole degrees: 359.7 reads 0, not 360.
std::string direction_cell(const nlohmann::json& v) {
  if (!v.is_number()) return "—";
  const long d = std::lround(v.get<double>()) % 360;
  return fmt::format("{}", d);
}

// Rows of thesis tables 3.14-3.22, one column per window.
report::Table station_keeping_table(const std::vector<nlohmann::json>& windows) {
  report::Table t;
  t.header = {"quantity"};
  for (const auto& w : windows) t.header.push_back(w.at("name").get<std::string>());
  auto row = [&](const std::string& label, auto get, const char* spec) {
    std::vector<std::string> r = {label};
    for (const auto& w : windows) r.push_back(cell(get(w), spec));
    t.rows.push_back(std::move(r));
  };
  row(
      "wind speed mean [m/s]", [](const auto& w) { return w["wind_speed_mps"]["mean"]; }, "{:.1f}");
  row(
      "wind speed std [m/s]", [](const auto& w) { return w["wind_speed_mps"]["std"]; }, "{:.1f}");
  t.rows.push_back({"wind from, mean [deg]"});
  for (const auto& w : windows) t.rows.back().push_back(direction_cell(w["wind_dir_deg"]["mean"]));
  row(
      "wind from, std [deg]", [](const auto& w) { return w["wind_dir_deg"]["std"]; }, "{:.1f}");
  row(
      "position std north [m]", [](const auto& w) { return w["position_std_m"]["north"]; },
      "{:.2f}");
  row(
      "position std east [m]", [](const auto& w) { return w["position_std_m"]["east"]; }, "{:.2f}");
  row(
      "heading mean [deg]", [](const auto& w) { return w["heading_deg"]["mean"]; }, "{:.1f}");
  row(
      "heading std [deg]", [](const auto& w) { return w["heading_deg"]["std"]; }, "{:.2f}");
  if (!windows.empty()) {
    // Thrusters in the log's order, the total last.
    std::vector<std::string> names;
    for (const auto& t : windows.front()["thrusters"]) names.push_back(t.get<std::string>());
    names.emplace_back("total");
    for (const std::string& name : names) {
      row(
          "mean thrust " + name + " [kN]", [name](const auto& w) { return w["thrust_kN"][name]; },
          "{:.1f}");
    }
    for (const std::string& name : names) {
      row(
          "energy " + name + " [kJ]", [name](const auto& w) { return w["energy_kJ"][name]; },
          "{:.0f}");
    }
  }
  return t;
}

struct StationKeepingRun {
  nlohmann::json doc;
  std::vector<nlohmann::json> windows;
};

StationKeepingRun analyse(const StationKeepingOptions& o, const core::Log& log) {
  const ident::StationKeepingInput in = make_input(log);
  std::vector<ident::TimeWindow> windows;
  if (o.t_from || o.t_to) {
    windows.push_back({"window", o.t_from.value_or(o.t_to ? *o.t_to - o.duration_s : 0.0),
                       o.t_to.value_or(o.t_from ? *o.t_from + o.duration_s : 0.0)});
  } else if (o.per_setpoint) {
    if (!log.has("setpoint.heading") && !log.has("setpoint.north")) {
      throw core::InputError({o.input.log.string(), {}, {}, "setpoint.heading"},
                             "--per-setpoint needs the DP setpoints in the log",
                             "map setpoint.north, setpoint.east, setpoint.heading, or give "
                             "--from/--to");
    }
    windows = ident::setpoint_windows(in.t_s, values_or_empty(log, "setpoint.north"),
                                      values_or_empty(log, "setpoint.east"),
                                      values_or_empty(log, "setpoint.heading"), o.duration_s);
  } else {
    windows.push_back({"last " + fmt::format("{:g}", o.duration_s) + " s",
                       std::max(in.t_s.front(), in.t_s.back() - o.duration_s), in.t_s.back()});
  }
  StationKeepingRun run;
  for (const auto& w : windows) {
    run.windows.push_back(window_json(ident::analyse_station_keeping(in, w)));
  }
  nlohmann::json& doc = run.doc;
  doc["analysis"] = "station-keeping";
  doc["log"] = o.input.log.string();
  doc["observed"] = {
      {"waves", o.waves.empty() ? nlohmann::json(nullptr) : nlohmann::json(o.waves)},
      {"current", o.current.empty() ? nlohmann::json(nullptr) : nlohmann::json(o.current)}};
  if (run.windows.size() == 1 && !o.per_setpoint) {
    doc.update(run.windows.front());
  } else {
    doc["windows"] = run.windows;
  }
  return run;
}

void run_station_keeping(const StationKeepingOptions& o) {
  check_json_target(o.json);
  if (!(o.duration_s > 0.0)) {
    throw core::InputError({{}, {}, {}, "--duration"}, "the window duration must be > 0 s");
  }
  const core::Log log = o.input.read(wanted_role);
  if (!(log.has("north") && log.has("east")) && !(log.has("lat") && log.has("lon"))) {
    throw core::InputError({o.input.log.string(), {}, {}, "north/east"}, "no position in the log",
                           "map north and east in metres (any offset, e.g. UTM: --col "
                           "north=gnss1.north --col east=gnss1.east) or lat and lon");
  }
  const StationKeepingRun run = analyse(o, log);
  if (!o.json.empty()) io::write_json(o.json, run.doc);
  std::FILE* out = o.json == "-" ? stderr : stdout;
  fmt::print(out, "{}: stationkeeping, {} window(s)\n", o.input.log.string(), run.windows.size());
  for (const auto& w : run.windows) {
    fmt::print(out, "  {}: {:.1f} … {:.1f} s\n", w["name"].get<std::string>(),
               w["t_from"].get<double>(), w["t_to"].get<double>());
  }
  if (!o.waves.empty()) fmt::print(out, "waves (observed): {}\n", o.waves);
  if (!o.current.empty()) fmt::print(out, "current (observed): {}\n", o.current);
  fmt::print(out, "{}", report::render_text(station_keeping_table(run.windows)));
  if (!o.json.empty() && o.json != "-") fmt::print(out, "wrote {}\n", o.json);
}

}  // namespace

void add_identify_station_keeping(CLI::App& identify) {
  auto o = std::make_shared<StationKeepingOptions>();
  CLI::App* sub = identify.add_subcommand("station-keeping",
                                          "Pure DP: position, heading, wind and thrust statistics");
  o->input.add_options(*sub,
                       "time, north, east (m, any offset) or lat, lon; heading, wind_speed, "
                       "wind_dir; thrust.NAME, power.NAME; setpoint.north/east/heading");
  sub->add_option("--from", o->t_from, "Window start [s]");
  sub->add_option("--to", o->t_to, "Window end [s]");
  sub->add_option("--duration", o->duration_s,
                  "Window length [s] when --from or --to is not given (default: the last 5 min "
                  "of the log, or of each setpoint hold)")
      ->capture_default_str();
  sub->add_flag("--per-setpoint", o->per_setpoint,
                "One window per DP setpoint hold: its last --duration seconds");
  sub->add_option("--waves", o->waves, "Waves as observed, printed and kept in the JSON");
  sub->add_option("--current", o->current, "Current as observed, printed and kept in the JSON");
  sub->add_option("--json", o->json, "Write the results as JSON to FILE, or '-' for stdout");
  sub->footer(
      "Position std about the window's mean [m]; heading and wind direction by circular "
      "statistics [deg]; mean |thrust| [kN] and energy ∫P dt [kJ] per thruster and total. A "
      "channel that is not logged is '—' / null. Example on a virtual trial log: dynpos identify "
      "station-keeping DIR/log.csv --col north=gnss1.north --col east=gnss1.east --per-setpoint");
  sub->callback([o] { run_station_keeping(*o); });
}

scenario::ReportSection station_keeping_demo_section(const std::filesystem::path& campaign_dir) {
  const std::filesystem::path log = campaign_dir / "pure-dp" / "log.csv";
  if (!std::filesystem::exists(log)) return {};
  StationKeepingOptions o;
  o.input.log = log;
  o.input.columns = {"north=gnss1.north", "east=gnss1.east"};
  o.per_setpoint = true;
  o.waves = "Hs 2.0 m, Tp 7 s, from 0° (simulated)";
  o.current = "0.2 m/s towards 180° (simulated)";
  StationKeepingRun run = analyse(o, o.input.read(wanted_role));
  run.doc["log"] = "pure-dp/log.csv";  // relative to the report, so the report is relocatable
  const std::filesystem::path dir = campaign_dir / "analysis" / "station-keeping";
  std::filesystem::create_directories(dir);
  io::write_json((dir / "pure-dp.json").string(), run.doc);
  const report::Table table = station_keeping_table(run.windows);
  const std::string intro =
      "Pure DP (`pure-dp`): the last 5 min of each heading hold, relative to the weather "
      "(waves " +
      o.waves + ", current " + o.current +
      "; wind from the log). Thesis tables 3.14–3.22 in Hs 1.7–2.3 m: position std 0.3–0.9 m, "
      "heading std 0.4–0.9° (2.8° once), mean total thrust 1–45 kN. Position from GNSS antenna "
      "1; JSON: analysis/station-keeping/pure-dp.json.";
  scenario::ReportSection s;
  s.title = "Stationkeeping (pure DP)";
  s.markdown = intro + "\n\n" + report::render_markdown(table);
  s.html = "<p>" + intro + "</p>\n" + report::render_html(table);
  return s;
}

}  // namespace dynpos::cli
