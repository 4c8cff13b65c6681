// dynpos identify agility: thrust agility (thesis section 3.5.1, figures 3.1-3.3): the time to
// 63.2 % of the response of every thruster (and of the vessel's speed) after a joystick thrust
// step in each direction, as a table, JSON and polar plots.

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "dynpos/analysis/data_dir.hpp"
#include "dynpos/core/circular_stats.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/ident/agility.hpp"
#include "dynpos/ident/derived_signals.hpp"
#include "dynpos/ident/thrust_map.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/report/polar_plot.hpp"
#include "dynpos/report/table.hpp"
#include "dynpos/scenario/vessel_config.hpp"
#include "log_input.hpp"

namespace dynpos::cli {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

struct AgilityCliOptions {
  LogInput input;
  std::string json;
  std::string plot;
  std::vector<std::string> windows;  ///< T_STEP,T_END,DIR_DEG[,THRUST_PCT[,YAW_PCT]]
  std::string current;               ///< SPEED_MPS,TO_DEG as observed
  bool use_rpm = false;
  double min_response_pct = 5.0;
  double min_demand_pct = 5.0;
};

bool wanted_role(const std::string& role) {
  for (const char* r : {"command.surge", "command.sway", "command.yaw", "u", "v", "wind_speed",
                        "wind_dir", "heading"}) {
    if (role == r) return true;
  }
  return role.rfind("thrust.", 0) == 0 || role.rfind("rpm.", 0) == 0;
}

std::vector<double> values_or_empty(const core::Log& log, const std::string& name) {
  return log.has(name) ? log.values(name) : std::vector<double>{};
}

std::vector<double> to_pct(std::vector<double> v) {
  for (double& x : v) x *= 100.0;  // the log holds fractions (SI); the demands are in %
  return v;
}

std::vector<double> parse_numbers(const std::string& text, const std::string& option) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    try {
      std::size_t used = 0;
      out.push_back(std::stod(item, &used));
      if (used != item.size() && item.find_first_not_of(' ', used) != std::string::npos) {
        throw std::invalid_argument(item);
      }
    } catch (const std::exception&) {
      throw core::InputError({"", {}, {}, option},
                             "'" + item + "' in '" + text + "' is not a number",
                             "give comma-separated numbers");
    }
  }
  return out;
}

std::vector<ident::AgilityWindow> parse_windows(const std::vector<std::string>& specs) {
  std::vector<ident::AgilityWindow> out;
  for (const std::string& s : specs) {
    const std::vector<double> v = parse_numbers(s, "--window");
    if (v.size() < 3 || v.size() > 5) {
      throw core::InputError({"", {}, {}, "--window"},
                             "'" + s + "' needs 3 to 5 numbers, has " + std::to_string(v.size()),
                             "--window T_STEP,T_END,DIR_DEG[,THRUST_PCT[,YAW_PCT]]");
    }
    ident::AgilityWindow w;
    w.t_step = v[0];
    w.t_end = v[1];
    w.direction_deg = v[2];
    w.magnitude_pct = v.size() > 3 ? v[3] : 100.0;
    if (v.size() > 4) w.yaw_pct = v[4];
    out.push_back(w);
  }
  return out;
}

struct Current {
  double speed_mps = 0.0;
  double to_deg = 0.0;
};

std::optional<Current> parse_current(const std::string& s) {
  if (s.empty()) return std::nullopt;
  const std::vector<double> v = parse_numbers(s, "--current");
  if (v.size() != 2 || !(v[0] >= 0.0)) {
    throw core::InputError({"", {}, {}, "--current"}, "'" + s + "' is not SPEED,TO_DEG",
                           "e.g. --current 0.2,318 (0.2 m/s towards 318°, as observed)");
  }
  return Current{v[0], v[1]};
}

nlohmann::json num(const std::optional<double>& v) {
  return v && std::isfinite(*v) ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

double wrap360(double d) {
  d = std::fmod(d, 360.0);
  return d < 0.0 ? d + 360.0 : d;
}

// Mean wind over the steps of a case: speed [m/s] and the direction it comes from (true, and
// relative to the bow using the mean heading) [deg].
struct Wind {
  double speed_mps = 0.0;
  double from_deg = 0.0;
  std::optional<double> heading_deg;
};

std::optional<Wind> mean_wind(const core::Log& log,
                              const std::vector<const ident::AgilityStep*>& s) {
  if (!log.has("wind_speed") || !log.has("wind_dir")) return std::nullopt;
  const std::vector<double>& t = log.time();
  const std::vector<double>& ws = log.values("wind_speed");
  const std::vector<double>& wd = log.values("wind_dir");
  const std::vector<double> hd = values_or_empty(log, "heading");
  double sum = 0.0;
  std::size_t n = 0;
  std::vector<double> dirs, heads;
  for (const ident::AgilityStep* step : s) {
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (t[i] < step->t_step || t[i] > step->t_end) continue;
      if (std::isfinite(ws[i])) {
        sum += ws[i];
        ++n;
      }
      if (std::isfinite(wd[i])) dirs.push_back(wd[i]);
      if (!hd.empty() && std::isfinite(hd[i])) heads.push_back(hd[i]);
    }
  }
  const std::optional<double> dir = core::circular_mean(dirs);
  if (n == 0 || !dir) return std::nullopt;
  Wind w{sum / static_cast<double>(n), wrap360(*dir * kDeg), std::nullopt};
  if (const auto h = core::circular_mean(heads)) w.heading_deg = wrap360(*h * kDeg);
  return w;
}

struct CaseGroup {
  std::string label;
  std::vector<const ident::AgilityStep*> steps;
  std::optional<Wind> wind;
};

std::vector<CaseGroup> group_cases(const ident::AgilityResult& r, const core::Log& log,
                                   double min_demand_pct) {
  std::vector<CaseGroup> cases;
  for (const ident::AgilityStep& s : r.steps) {
    const std::string label = ident::agility_case_label(s, min_demand_pct);
    auto it = std::find_if(cases.begin(), cases.end(),
                           [&](const CaseGroup& c) { return c.label == label; });
    if (it == cases.end()) {
      cases.push_back({label, {}, std::nullopt});
      it = cases.end() - 1;
    }
    it->steps.push_back(&s);
  }
  for (CaseGroup& c : cases) c.wind = mean_wind(log, c.steps);
  return cases;
}

struct AgilityRun {
  ident::AgilityResult result;
  std::vector<std::string> thrusters;
  std::string channel;  // "thrust" or "rpm"
  bool has_speed = false;
  std::vector<CaseGroup> cases;
  std::optional<Current> current;
  nlohmann::json doc;
};

// Envelope of the thrust response: the slowest thruster of a step (the time until every
// thruster has covered 63.2 % of its response); absent when none responded.
std::optional<double> envelope(const ident::AgilityStep& s) {
  std::optional<double> e;
  for (const auto& r : s.thrusters) {
    if (r.response_s) e = std::max(e.value_or(0.0), *r.response_s);
  }
  return e;
}

ident::AgilityResult run_analysis(const AgilityCliOptions& o, const core::Log& log,
                                  const std::vector<ident::AgilityChannel>& channels,
                                  const std::vector<double>& speed,
                                  const ident::AgilityOptions& ao) {
  const std::vector<double>& t = log.time();
  if (!o.windows.empty()) {
    const std::vector<ident::AgilityWindow> w = parse_windows(o.windows);
    return ident::analyse_agility(t, w, channels, speed, ao);
  }
  if (!log.has("command.surge") || !log.has("command.sway")) {
    throw core::InputError({o.input.log.string(), {}, {}, "command.surge, command.sway"},
                           "no joystick demand in the log and no --window",
                           "map the demands (--col command.surge=COL --col command.sway=COL, "
                           "in %) or give each step as --window T_STEP,T_END,DIR_DEG");
  }
  const std::vector<double> surge = to_pct(log.values("command.surge"));
  const std::vector<double> sway = to_pct(log.values("command.sway"));
  const std::vector<double> yaw = to_pct(values_or_empty(log, "command.yaw"));
  return ident::analyse_agility(t, {surge, sway, yaw}, channels, speed, ao);
}

AgilityRun analyse(const AgilityCliOptions& o, const core::Log& log) {
  AgilityRun run;
  run.current = parse_current(o.current);
  const std::vector<std::string> thrust = thruster_names(log, "thrust");
  const std::vector<std::string> rpm = thruster_names(log, "rpm");
  run.channel = (!o.use_rpm && !thrust.empty()) ? "thrust" : "rpm";
  run.thrusters = run.channel == "thrust" ? thrust : rpm;
  if (run.thrusters.empty()) {
    throw core::InputError({o.input.log.string(), {}, {}, "thrust.NAME"},
                           o.use_rpm ? "no shaft speed channel (rpm.NAME) in the log"
                                     : "no thruster channel (thrust.NAME or rpm.NAME) in the log",
                           "map one per thruster, e.g. --col thrust.port=THRUST_P");
  }
  std::vector<ident::AgilityChannel> channels;
  for (const std::string& n : run.thrusters) {
    channels.push_back({n, log.values(run.channel + "." + n), std::nullopt});
  }
  std::vector<double> speed;
  if (log.has("u") && log.has("v")) {
    speed = ident::total_speed(log.values("u"), log.values("v"));  // (3.19)
  } else if (log.has("u")) {
    speed = log.values("u");
  }
  run.has_speed = !speed.empty();
  ident::AgilityOptions ao;
  ao.min_response_fraction = o.min_response_pct / 100.0;
  ao.min_demand_pct = o.min_demand_pct;
  try {
    run.result = run_analysis(o, log, channels, speed, ao);
  } catch (const core::InputError& e) {
    // Name the log, and the thruster channel by its role, in the library's message.
    core::InputLocation where = e.where();
    if (where.file.empty()) where.file = o.input.log.string();
    for (const std::string& n : run.thrusters) {
      if (where.column_name == n) where.column_name = run.channel + "." + n;
    }
    throw core::InputError(where, e.problem(), e.hint());
  }
  run.cases = group_cases(run.result, log, o.min_demand_pct);

  nlohmann::json& doc = run.doc;
  doc["analysis"] = "agility";
  doc["log"] = o.input.log.string();
  doc["definition"] =
      "time from the step to 63.2 % of the response, dead time included (thesis 3.5.1)";
  doc["channel"] = run.channel;
  doc["thrusters"] = run.thrusters;
  doc["min_response_fraction"] = ao.min_response_fraction;
  doc["status"] = std::string(ident::fit_status_name(run.result.status));
  doc["message"] = run.result.message;
  doc["current"] = run.current ? nlohmann::json{{"speed_mps", run.current->speed_mps},
                                                {"to_deg", run.current->to_deg}}
                               : nlohmann::json(nullptr);
  doc["cases"] = nlohmann::json::array();
  for (const CaseGroup& c : run.cases) {
    nlohmann::json j{{"label", c.label}, {"steps", c.steps.size()}};
    j["wind"] = c.wind ? nlohmann::json{{"speed_mps", c.wind->speed_mps},
                                        {"from_deg", c.wind->from_deg},
                                        {"heading_deg", num(c.wind->heading_deg)}}
                       : nlohmann::json(nullptr);
    doc["cases"].push_back(j);
  }
  doc["directions"] = nlohmann::json::array();
  for (const ident::AgilityStep& s : run.result.steps) {
    nlohmann::json j;
    j["direction_deg"] = s.direction_deg;
    j["magnitude_pct"] = s.magnitude_pct;
    j["yaw_pct"] = num(s.yaw_pct);
    j["case"] = ident::agility_case_label(s, o.min_demand_pct);
    j["t_step"] = s.t_step;
    j["t_end"] = s.t_end;
    nlohmann::json resp = nlohmann::json::object();
    nlohmann::json notes = nlohmann::json::object();
    for (const auto& r : s.thrusters) {
      resp[r.name] = num(r.response_s);
      if (!r.notes.empty()) notes[r.name] = r.notes;
    }
    j["response_s"] = resp;
    j["thrust_envelope_s"] = num(envelope(s));
    j["speed_response_s"] = s.speed ? num(s.speed->response_s) : nlohmann::json(nullptr);
    if (s.speed && !s.speed->notes.empty()) notes["speed"] = s.speed->notes;
    j["notes"] = notes;
    doc["directions"].push_back(j);
  }
  return run;
}

std::string cell(const std::optional<double>& v) {
  return v ? fmt::format("{:.1f}", *v) : std::string("—");
}

report::Table agility_table(const AgilityRun& run) {
  report::Table t;
  t.header = {"case", "direction [°]", "t_step [s]"};
  for (const std::string& n : run.thrusters) t.header.push_back(n + " [s]");
  t.header.push_back("thrust envelope [s]");
  t.header.push_back("speed [s]");
  t.first_numeric_column = 1;
  for (const ident::AgilityStep& s : run.result.steps) {
    std::vector<std::string> row = {ident::agility_case_label(s),
                                    fmt::format("{:.0f}", s.direction_deg),
                                    fmt::format("{:.1f}", s.t_step)};
    for (const auto& r : s.thrusters) row.push_back(cell(r.response_s));
    row.push_back(cell(envelope(s)));
    row.push_back(s.speed ? cell(s.speed->response_s) : std::string("—"));
    t.rows.push_back(std::move(row));
  }
  return t;
}

// One polar panel per case: a series per thruster, the thrust envelope, the speed response,
// and the wind and current arrows relative to the bow (pointing where they go).
report::PolarFigure agility_figure(const AgilityRun& run, const std::string& title) {
  report::PolarFigure f;
  f.title = title;
  f.panel_size_px = 380.0;
  for (const CaseGroup& c : run.cases) {
    std::vector<const ident::AgilityStep*> steps = c.steps;
    std::stable_sort(steps.begin(), steps.end(), [](const auto* a, const auto* b) {
      return wrap360(a->direction_deg) < wrap360(b->direction_deg);
    });
    report::PolarPanel p;
    p.title = c.label;
    p.radial_label = "Time to 63.2 %";
    p.radial_unit = "s";
    const auto add = [&](const std::string& label, const auto& get, bool dashed, bool markers,
                         const std::string& color, double width) {
      report::PolarSeries s;
      s.label = label;
      s.dashed = dashed;
      s.markers = markers;
      s.color = color;
      s.width_px = width;
      for (const ident::AgilityStep* st : steps) {
        s.angle_deg.push_back(st->direction_deg);
        const std::optional<double> v = get(*st);
        s.radius.push_back(v ? *v : std::nan(""));
      }
      p.series.push_back(std::move(s));
    };
    for (std::size_t k = 0; k < run.thrusters.size(); ++k) {
      add(
          run.thrusters[k], [k](const ident::AgilityStep& s) { return s.thrusters[k].response_s; },
          false, true, "", 1.5);
    }
    add(
        "thrust envelope", [](const ident::AgilityStep& s) { return envelope(s); }, true, false,
        "#000000", 2.0);
    if (run.has_speed) {
      add(
          "speed response",
          [](const ident::AgilityStep& s) {
            return s.speed ? s.speed->response_s : std::optional<double>{};
          },
          true, true, "#1f9e89", 2.0);
    }
    const double heading = c.wind && c.wind->heading_deg ? *c.wind->heading_deg : 0.0;
    if (c.wind) {
      p.arrows.push_back({fmt::format("wind {:.1f} m/s", c.wind->speed_mps),
                          c.wind->from_deg + 180.0 - heading, 0.75, "#2ca02c"});
    }
    if (run.current) {
      p.arrows.push_back({fmt::format("current {:.1f} m/s", run.current->speed_mps),
                          run.current->to_deg - heading, 0.5, "#9467bd"});
    }
    f.panels.push_back(std::move(p));
  }
  return f;
}

void run_cli(const AgilityCliOptions& o) {
  check_json_target(o.json);
  const AgilityRun run = analyse(o, o.input.read(wanted_role));
  if (!o.plot.empty()) {
    report::write_polar_svg(
        o.plot, agility_figure(run, "Thrust agility: " + o.input.log.filename().string()));
  }
  if (!o.json.empty()) io::write_json(o.json, run.doc);
  std::FILE* out = o.json == "-" ? stderr : stdout;
  fmt::print(out,
             "{}: thrust agility, time from the step to 63.2 % of the response ({} of each "
             "thruster{}), dead time included; — = no response\n{}",
             o.input.log.string(), run.channel, run.has_speed ? "; speed √(u²+v²)" : "",
             report::render_text(agility_table(run)));
  for (const CaseGroup& c : run.cases) {
    if (c.wind) {
      fmt::print(out, "{}: wind {:.1f} m/s from {:.0f}°\n", c.label, c.wind->speed_mps,
                 c.wind->from_deg);
    }
  }
  if (run.result.status == ident::FitStatus::kFailed) {
    fmt::print(out, "warning: {}\n", run.result.message);
  }
  if (!o.plot.empty()) fmt::print(out, "wrote {}\n", o.plot);
  if (!o.json.empty() && o.json != "-") fmt::print(out, "wrote {}\n", o.json);
}

// Thrust map (3.17) back-calculated from a log with thrust and shaft speed, against the vessel
// file's c± and the thesis' table 3.2.
// One table over the logs given as (name, log): a row per log and main propeller.
report::Table thrust_map_table(const std::vector<std::pair<std::string, core::Log>>& logs,
                               const scenario::VesselConfig& vessel) {
  const auto& pr = vessel.propeller;
  const double d4 = std::pow(pr.diameter, 4);
  const double true_pos = pr.rho * pr.kt_forward * d4;
  const double true_neg = -pr.rho * pr.kt_reverse * d4;
  report::Table t;
  t.header = {"log", "thruster", "c+ [kN/rps²]",        "c- [kN/rps²]",  "n+",
              "n-",  "R²",       "vessel file c+ / c-", "thesis c+ / c-"};
  t.first_numeric_column = 2;
  const auto kn = [](const std::optional<ident::Estimate>& e) {
    return e ? fmt::format("{:.3f}", e->value / 1000.0) : std::string("—");
  };
  for (const auto& [log_name, log] : logs) {
    for (const std::string& name : thruster_names(log, "rpm")) {
      if (name == "tunnel" || !log.has("thrust." + name)) continue;
      ident::ThrustMapFitOptions f;
      f.shaft_speed_name = "rpm." + name;
      f.thrust_name = "thrust." + name;
      const auto r =
          ident::fit_thrust_map(log.values("rpm." + name), log.values("thrust." + name), f);
      t.rows.push_back({log_name, name, kn(r.c_forward), kn(r.c_reverse),
                        std::to_string(r.samples_forward), std::to_string(r.samples_reverse),
                        r.r_squared ? fmt::format("{:.4f}", *r.r_squared) : "—",
                        fmt::format("{:.2f} / {:.2f}", true_pos / 1000.0, true_neg / 1000.0),
                        "8.13 / -5.8"});
    }
  }
  return t;
}

}  // namespace

void add_identify_agility(CLI::App& identify) {
  auto o = std::make_shared<AgilityCliOptions>();
  CLI::App* sub = identify.add_subcommand(
      "agility", "Thrust agility: time to 63.2 % per direction and thruster, polar plot");
  o->input.add_options(*sub,
                       "time, command.surge, command.sway, command.yaw [%], thrust.NAME or "
                       "rpm.NAME per thruster, u, v (speed), wind_speed, wind_dir, heading");
  sub->add_option("--json", o->json, "Write the response times as JSON to FILE, or '-'");
  sub->add_option("--plot", o->plot, "Write the polar plot (SVG), one polar per case");
  sub->add_option("--window", o->windows,
                  "A step given explicitly (repeatable): T_STEP,T_END,DIR_DEG[,THRUST_PCT"
                  "[,YAW_PCT]]; replaces the joystick demands");
  sub->add_option("--current", o->current,
                  "Current as observed (e.g. on the DP display): SPEED_MPS,TO_DEG, drawn as an "
                  "arrow");
  sub->add_flag("--rpm", o->use_rpm, "Time the shaft speed (rpm.NAME) even when thrust is logged");
  sub->add_option("--min-response", o->min_response_pct,
                  "A thruster whose change is below this % of its range has no response (null)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 99.0));
  sub->add_option("--min-demand", o->min_demand_pct,
                  "Thrust demands below this [%] count as no thrust (no direction)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  sub->footer(
      "Steps: every level of the joystick demands with √(surge²+sway²) ≥ --min-demand, in "
      "direction atan2(sway, surge) (0 = ahead, 90 = starboard), until the next change. "
      "Response time: from the step to the crossing of y0 + 0.632·(y_end − y0), y0 the mean of "
      "the 5 s before, y_end the mean of the last 20 % of the step. Cases (thrust %, yaw %) get "
      "one polar each. Example: dynpos identify agility DIR/log.csv --plot agility.svg --json "
      "agility.json --current 0.2,318");
  sub->callback([o] { run_cli(*o); });
}

scenario::ReportSection agility_demo_section(const std::filesystem::path& campaign_dir) {
  const std::filesystem::path log = campaign_dir / "agility" / "log.csv";
  if (!std::filesystem::exists(log)) return {};
  AgilityCliOptions o;
  o.input.log = log;
  o.current = "0.2,318";  // the scenario's current, as an operator would read it off
  AgilityRun run = analyse(o, o.input.read(wanted_role));
  run.doc["log"] = "agility/log.csv";  // relative, so the report is relocatable
  const std::filesystem::path dir = campaign_dir / "analysis" / "agility";
  std::filesystem::create_directories(dir);
  io::write_json((dir / "agility.json").string(), run.doc);
  report::write_polar_svg(dir / "agility.svg", agility_figure(run, "Thrust agility (simulated)"));
  const report::Table table = agility_table(run);
  const std::string intro =
      "Thrust agility (`agility`): a joystick thrust step in each of 8 directions, at 50 % and "
      "100 % thrust, and at 100 % with 100 % yaw moment. Time from the step to 63.2 % of each "
      "thruster's thrust response (dead time included), the slowest of them (thrust envelope) "
      "and the speed response √(u²+v²) over the 40 s step; — = no response (e.g. the tunnel "
      "ahead and astern). Thesis figures 3.1–3.3 give 3–10 s for the main propellers. Plot: "
      "analysis/agility/agility.svg; JSON: analysis/agility/agility.json.";
  scenario::ReportSection s;
  s.title = "Thrust agility";
  s.markdown = intro + "\n\n" + report::render_markdown(table) +
               "\n\n![Thrust agility](analysis/agility/agility.svg)\n";
  s.html = "<p>" + intro + "</p>\n" + report::render_html(table) +
           "<p><img src=\"analysis/agility/agility.svg\" alt=\"Thrust agility polar plots\"></p>\n";

  std::vector<std::pair<std::string, core::Log>> logs;
  for (const char* name : {"surge-steps-forward", "surge-steps-backward"}) {
    const std::filesystem::path steps = campaign_dir / name / "log.csv";
    if (!std::filesystem::exists(steps)) continue;
    LogInput in;
    in.log = steps;
    logs.emplace_back(name, in.read([](const std::string& role) {
      return role.rfind("rpm.", 0) == 0 || role.rfind("thrust.", 0) == 0;
    }));
  }
  if (!logs.empty()) {
    const scenario::VesselConfig vessel =
        scenario::load_vessel_config(analysis::find_data_dir() / "vessels" / "gunnerus.toml");
    const report::Table map = thrust_map_table(logs, vessel);
    const std::string text =
        "Thrust map T = c·n|n| (3.17) back-calculated from the surge step logs (logged thrust "
        "and shaft speed, |n| ≥ 0.05 rps; c+ from the forward steps, c- from the backward ones), "
        "against the vessel file (c = ρK_T·D⁴) and the thesis' table 3.2 (kN/rps²).";
    s.markdown += "\n" + text + "\n\n" + report::render_markdown(map);
    s.html += "<p>" + text + "</p>\n" + report::render_html(map);
  }
  return s;
}

}  // namespace dynpos::cli
