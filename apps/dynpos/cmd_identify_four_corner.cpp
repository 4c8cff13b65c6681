// dynpos identify four-corner: the DP 4-corner maneuver cut into legs, with duration,
// accumulated thrust and energy per thruster per leg and in total (thesis table 3.6), and the
// NE plot of the track (figure 3.5).

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/ident/four_corner.hpp"
#include "dynpos/ident/local_position.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/report/svg_plot.hpp"
#include "dynpos/report/table.hpp"
#include "log_input.hpp"

namespace dynpos::cli {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

struct FourCornerCliOptions {
  LogInput input;
  double radius_m = 2.0;
  double heading_tol_deg = 2.0;
  std::string segment = "auto";
  std::vector<double> arm_m;  ///< horizontal lever arm of the position's antenna (x, y) [m]
  std::optional<double> t_from, t_to;
  std::string json;
  std::string plot;
};

bool wanted_role(const std::string& role) {
  for (const char* r : {"north", "east", "lat", "lon", "heading", "setpoint.north", "setpoint.east",
                        "setpoint.heading"}) {
    if (role == r) return true;
  }
  return role.rfind("thrust.", 0) == 0 || role.rfind("power.", 0) == 0;
}

std::vector<double> values_or_empty(const core::Log& log, const std::string& name) {
  return log.has(name) ? log.values(name) : std::vector<double>{};
}

// The log's rows with time in [from, to] (all rows when neither is given).
std::vector<double> slice(const std::vector<double>& x, std::size_t a, std::size_t b) {
  if (x.empty()) return x;
  return {x.begin() + static_cast<std::ptrdiff_t>(a), x.begin() + static_cast<std::ptrdiff_t>(b)};
}

ident::FourCornerInput make_input(const FourCornerCliOptions& o, const core::Log& log) {
  ident::FourCornerInput in;
  in.t_s = log.time();
  if (log.has("north") && log.has("east")) {
    in.north_m = log.values("north");
    in.east_m = log.values("east");
  } else if (log.has("lat") && log.has("lon")) {
    const ident::LocalPositions p = ident::local_north_east(log.values("lat"), log.values("lon"));
    in.north_m = p.north_m;
    in.east_m = p.east_m;
  } else {
    throw core::InputError({o.input.log.string(), {}, {}, "north/east"}, "no position in the log",
                           "map north and east in metres (any offset, e.g. UTM: --col "
                           "north=gnss1.north --col east=gnss1.east) or lat and lon");
  }
  if (!log.has("heading")) {
    throw core::InputError({o.input.log.string(), {}, {}, "heading"}, "no heading in the log",
                           "map heading (--col heading=COLUMN)");
  }
  in.heading_rad = log.values("heading");
  if (!o.arm_m.empty()) {
    in.arm_x_m = o.arm_m[0];
    in.arm_y_m = o.arm_m[1];
  }
  in.setpoint_north_m = values_or_empty(log, "setpoint.north");
  in.setpoint_east_m = values_or_empty(log, "setpoint.east");
  in.setpoint_heading_rad = values_or_empty(log, "setpoint.heading");
  std::vector<std::string> names = thruster_names(log, "thrust");
  for (const std::string& n : thruster_names(log, "power")) {
    if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  }
  for (const std::string& n : names) {
    in.thrusters.push_back(
        {n, values_or_empty(log, "thrust." + n), values_or_empty(log, "power." + n)});
  }
  if (o.t_from || o.t_to) {
    const double from = o.t_from.value_or(in.t_s.front());
    const double to = o.t_to.value_or(in.t_s.back());
    if (!(to > from) || from > in.t_s.back() || to < in.t_s.front()) {
      throw core::InputError({o.input.log.string(), {}, {}, "--from/--to"},
                             fmt::format("the window {:g} … {:g} s is empty or outside the log "
                                         "({:g} … {:g} s)",
                                         from, to, in.t_s.front(), in.t_s.back()),
                             "choose --from < --to inside the log");
    }
    const auto a = static_cast<std::size_t>(std::lower_bound(in.t_s.begin(), in.t_s.end(), from) -
                                            in.t_s.begin());
    const auto b = static_cast<std::size_t>(std::upper_bound(in.t_s.begin(), in.t_s.end(), to) -
                                            in.t_s.begin());
    for (auto* x : {&in.t_s, &in.north_m, &in.east_m, &in.heading_rad, &in.setpoint_north_m,
                    &in.setpoint_east_m, &in.setpoint_heading_rad}) {
      *x = slice(*x, a, b);
    }
    for (auto& t : in.thrusters) {
      t.thrust_N = slice(t.thrust_N, a, b);
      t.power_W = slice(t.power_W, a, b);
    }
  }
  return in;
}

ident::FourCornerOptions analysis_options(const FourCornerCliOptions& o) {
  ident::FourCornerOptions a;
  a.radius_m = o.radius_m;
  a.heading_tol_rad = o.heading_tol_deg / kDeg;
  if (o.segment == "auto") {
    a.segmentation = ident::LegSegmentation::kAuto;
  } else if (o.segment == "setpoints") {
    a.segmentation = ident::LegSegmentation::kSetpoints;
  } else if (o.segment == "track") {
    a.segmentation = ident::LegSegmentation::kTrack;
  } else {
    throw core::InputError({{}, {}, {}, "--segment"}, "unknown segmentation '" + o.segment + "'",
                           "use auto, setpoints or track");
  }
  try {
    a.validate();
  } catch (const core::InputError& e) {
    throw core::InputError({{}, {}, {}, "--radius/--heading-tol"}, e.problem(), e.hint());
  }
  return a;
}

nlohmann::json num(const std::optional<double>& v, double scale = 1.0) {
  return v && std::isfinite(*v) ? nlohmann::json(*v * scale) : nlohmann::json(nullptr);
}

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
      j["setpoint"] = {{"north_m", num(leg.setpoint_north_m)},
                       {"east_m", num(leg.setpoint_east_m)},
                       {"heading_deg", num(leg.setpoint_heading_rad, kDeg)}};
    } else {
      j["setpoint"] = nullptr;
    }
  }
  nlohmann::json thrust = nlohmann::json::object(), energy = nlohmann::json::object();
  for (const auto& t : leg.thrusters) {
    thrust[t.name] = num(t.accumulated_thrust_Ns, 1e-3);
    energy[t.name] = num(t.energy_J, 1e-3);
  }
  thrust["total"] = num(leg.total_accumulated_thrust_Ns, 1e-3);
  energy["total"] = num(leg.total_energy_J, 1e-3);
  j["thrust_kNs"] = thrust;
  j["energy_kJ"] = energy;
  return j;
}

nlohmann::json result_json(const FourCornerCliOptions& o, const ident::FourCornerResult& r) {
  nlohmann::json doc;
  doc["analysis"] = "four-corner";
  doc["log"] = o.input.log.string();
  doc["segmentation"] = r.segmentation;
  doc["radius_m"] = o.radius_m;
  doc["arm_m"] = o.arm_m.empty() ? nlohmann::json(nullptr) : nlohmann::json(o.arm_m);
  doc["heading_tol_deg"] = o.heading_tol_deg;
  doc["thrusters"] = nlohmann::json::array();
  for (const auto& t : r.total.thrusters) doc["thrusters"].push_back(t.name);
  doc["legs"] = nlohmann::json::array();
  for (const auto& leg : r.legs) doc["legs"].push_back(leg_json(leg, true));
  doc["total"] = leg_json(r.total, false);
  return doc;
}

std::string cell(const nlohmann::json& v, const char* spec) {
  return v.is_number() ? fmt::format(fmt::runtime(spec), v.get<double>()) : std::string("—");
}

// Thesis table 3.6: one row per leg and the total; duration, accumulated thrust per thruster
// and total, energy per thruster and total.
report::Table four_corner_table(const nlohmann::json& doc) {
  std::vector<std::string> names;
  for (const auto& t : doc["thrusters"]) names.push_back(t.get<std::string>());
  names.emplace_back("total");
  report::Table t;
  t.header = {"leg", "start [s]", "end [s]", "duration [s]"};
  for (const auto& n : names) t.header.push_back("thrust " + n + " [kNs]");
  for (const auto& n : names) t.header.push_back("energy " + n + " [kJ]");
  auto row = [&](const nlohmann::json& leg) {
    std::string name = leg["name"].get<std::string>();
    if (!leg["reached"].get<bool>()) name += " (not reached)";
    std::vector<std::string> r = {name, cell(leg["t_start"], "{:.1f}"),
                                  cell(leg["t_end"], "{:.1f}"), cell(leg["duration_s"], "{:.0f}")};
    for (const auto& n : names) r.push_back(cell(leg["thrust_kNs"][n], "{:.0f}"));
    for (const auto& n : names) r.push_back(cell(leg["energy_kJ"][n], "{:.0f}"));
    t.rows.push_back(std::move(r));
  };
  for (const auto& leg : doc["legs"]) row(leg);
  nlohmann::json total = doc["total"];
  total["name"] = "total";
  row(total);
  return t;
}

// NE plot (figure 3.5): the whole track in grey, each leg in its own colour, the setpoint box.
report::Figure ne_plot(const ident::FourCornerInput& in, const ident::FourCornerResult& r,
                       const std::string& title) {
  report::Panel p;
  p.title = "Track (" + r.segmentation + " segmentation)";
  p.x_axis = {"East", "m", {}, {}};
  p.y_axis = {"North", "m", {}, {}};
  report::Series all{"whole log", {}, {}, "#bbbbbb", 1.0, false};
  for (std::size_t i = 0; i < in.t_s.size(); ++i) {
    if (std::isnan(in.north_m[i]) || std::isnan(in.east_m[i])) continue;
    all.x.push_back(in.east_m[i]);
    all.y.push_back(in.north_m[i]);
  }
  p.series.push_back(std::move(all));
  for (const auto& leg : r.legs) {
    report::Series s{leg.name, {}, {}, "", 1.8, false};
    for (std::size_t i = 0; i < in.t_s.size(); ++i) {
      if (in.t_s[i] < leg.t_start_s || in.t_s[i] > leg.t_end_s) continue;
      if (std::isnan(in.north_m[i]) || std::isnan(in.east_m[i])) continue;
      s.x.push_back(in.east_m[i]);
      s.y.push_back(in.north_m[i]);
    }
    p.series.push_back(std::move(s));
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
  f.title = title;
  f.width_px = 700.0;
  f.panel_height_px = 600.0;
  f.panels.push_back(std::move(p));
  return f;
}

struct FourCornerRun {
  ident::FourCornerInput input;
  ident::FourCornerResult result;
  nlohmann::json doc;
};

FourCornerRun analyse(const FourCornerCliOptions& o) {
  const ident::FourCornerOptions a = analysis_options(o);
  const core::Log log = o.input.read(wanted_role);
  FourCornerRun run;
  run.input = make_input(o, log);
  try {
    run.result = ident::analyse_four_corner(run.input, a);
  } catch (const core::InputError& e) {
    throw core::InputError({o.input.log.string(), {}, {}, e.where().column_name}, e.problem(),
                           e.hint());
  }
  run.doc = result_json(o, run.result);
  return run;
}

void run_four_corner(const FourCornerCliOptions& o) {
  check_json_target(o.json);
  check_json_target(o.plot);
  FourCornerRun run = analyse(o);
  if (!o.plot.empty()) {
    report::write_svg(o.plot,
                      ne_plot(run.input, run.result, "DP 4-corner: " + o.input.log.string()));
  }
  if (!o.json.empty()) io::write_json(o.json, run.doc);
  std::FILE* out = o.json == "-" ? stderr : stdout;
  fmt::print(out, "{}: DP 4-corner, {} legs from the {}\n", o.input.log.string(),
             run.result.legs.size(), run.result.segmentation);
  fmt::print(out, "{}", report::render_text(four_corner_table(run.doc)));
  if (!o.plot.empty()) fmt::print(out, "wrote {}\n", o.plot);
  if (!o.json.empty() && o.json != "-") fmt::print(out, "wrote {}\n", o.json);
}

}  // namespace

void add_identify_four_corner(CLI::App& identify) {
  auto o = std::make_shared<FourCornerCliOptions>();
  CLI::App* sub = identify.add_subcommand(
      "four-corner", "DP 4-corner: legs, durations, accumulated thrust and energy");
  o->input.add_options(*sub,
                       "time, north, east (m, any offset) or lat, lon; heading; "
                       "setpoint.north/east/heading; thrust.NAME, power.NAME");
  sub->add_option("--radius", o->radius_m, "Operating circle radius [m]")->capture_default_str();
  sub->add_option("--heading-tol", o->heading_tol_deg, "Operating circle heading tolerance [deg]")
      ->capture_default_str();
  sub->add_option("--segment", o->segment, "Leg segmentation: auto, setpoints or track")
      ->capture_default_str();
  sub->add_option("--arm", o->arm_m,
                  "Horizontal lever arm X,Y [m] (BODY: forward, starboard) of the antenna whose "
                  "position is logged; the position is moved to the control origin")
      ->expected(2)
      ->delimiter(',');
  sub->add_option("--from", o->t_from, "Analyse from this time [s]");
  sub->add_option("--to", o->t_to, "Analyse up to this time [s]");
  sub->add_option("--json", o->json, "Write the results as JSON to FILE, or '-' for stdout");
  sub->add_option("--plot", o->plot, "Write the NE plot of the track to FILE.svg");
  sub->footer(
      "Legs start at each setpoint change and end when the position is within --radius and "
      "the heading within --heading-tol of the setpoint (auto, when setpoints are logged), or "
      "are the stretches of motion of the track (track). Accumulated thrust ∫|T|dt [kNs] and "
      "energy ∫P dt [kJ] per thruster; a channel that is not logged is '—' / null. Example on "
      "a virtual trial log: dynpos identify four-corner DIR/log.csv --col north=gnss1.north "
      "--col east=gnss1.east --plot ne.svg");
  sub->callback([o] { run_four_corner(*o); });
}

scenario::ReportSection four_corner_demo_section(const std::filesystem::path& campaign_dir) {
  const std::filesystem::path log = campaign_dir / "four-corner" / "log.csv";
  if (!std::filesystem::exists(log)) return {};
  FourCornerCliOptions o;
  o.input.log = log;
  o.input.columns = {"north=gnss1.north", "east=gnss1.east"};
  // The antenna's surveyed lever arm (the vessel file's, which truth.json repeats), so the
  // circle is tested at the control origin as the DP system does.
  std::ifstream truth_file(campaign_dir / "four-corner" / "truth.json");
  const nlohmann::json t = nlohmann::json::parse(truth_file, nullptr, false);
  if (!t.is_discarded() && t.contains("lever_arms") && t["lever_arms"].contains("gnss1")) {
    o.arm_m = {t["lever_arms"]["gnss1"][0].get<double>(),
               t["lever_arms"]["gnss1"][1].get<double>()};
  }
  FourCornerRun run = analyse(o);
  run.doc["log"] = "four-corner/log.csv";  // relative to the report, so it is relocatable
  const std::filesystem::path dir = campaign_dir / "analysis" / "four-corner";
  std::filesystem::create_directories(dir);
  io::write_json((dir / "four-corner.json").string(), run.doc);
  report::write_svg(dir / "four-corner_ne.svg",
                    ne_plot(run.input, run.result, "DP 4-corner on the virtual Gunnerus"));
  // The simulator's own reach times (truth.json) beside the identified legs.
  report::Table truth;
  truth.header = {"leg", "duration [s], identified", "duration [s], simulator", "difference [s]"};
  if (!t.is_discarded() && t.contains("setpoints")) {
    std::vector<double> durations;
    for (const auto& s : t["setpoints"]) {
      if (s.contains("t_reached_s") && s["name"] != "hold") {
        durations.push_back(s["t_reached_s"].get<double>() - s["t_start_s"].get<double>());
      }
    }
    for (std::size_t k = 0; k < run.result.legs.size(); ++k) {
      const auto& leg = run.result.legs[k];
      const bool known = k < durations.size();
      truth.rows.push_back({leg.name, fmt::format("{:.1f}", leg.duration_s),
                            known ? fmt::format("{:.1f}", durations[k]) : "—",
                            known ? fmt::format("{:+.1f}", leg.duration_s - durations[k]) : "—"});
    }
  }
  const report::Table table = four_corner_table(run.doc);
  const std::string intro =
      "DP 4-corner (`four-corner`, 50 m legs): legs from the logged setpoints, each ending when "
      "the control origin (GNSS antenna 1 moved by its lever arm) is within 2 m and the heading "
      "within 2° of the setpoint, both averaged over 10 s as a DP wave filter does. Thesis "
      "tables 3.6–3.10: 85–214 s per leg, 545–624 s in total. JSON: analysis/four-corner/"
      "four-corner.json.";
  scenario::ReportSection s;
  s.title = "DP 4-corner";
  s.markdown = intro + "\n\n" + report::render_markdown(table) + "\n" +
               report::render_markdown(truth) +
               "\n![NE plot](analysis/four-corner/four-corner_ne.svg)\n";
  s.html = "<p>" + intro + "</p>\n" + report::render_html(table) + report::render_html(truth) +
           "<p><img src=\"analysis/four-corner/four-corner_ne.svg\" alt=\"NE plot\"></p>\n";
  return s;
}

}  // namespace dynpos::cli
