// dynpos identify thrust-map: back-calculate the thrust map T = c·n|n| (3.17) of every thruster
// with logged thrust and shaft speed, or apply a map to a log with shaft speed only (3.18).

#include <fmt/core.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "dynpos/analysis/data_dir.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/ident/thrust_map.hpp"
#include "dynpos/io/csv_writer.hpp"
#include "dynpos/io/json_writer.hpp"
#include "dynpos/scenario/vessel_config.hpp"
#include "log_input.hpp"

namespace dynpos::cli {
namespace {

struct ThrustMapOptions {
  LogInput input;
  std::string json;
  double min_speed_rpm = 3.0;
  bool apply = false;
  bool abs_speed = false;
  std::filesystem::path vessel;
  std::filesystem::path out;
};

nlohmann::json opt(const std::optional<double>& v) {
  return v && std::isfinite(*v) ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

std::string kn(const std::optional<ident::Estimate>& e) {
  if (!e) return "—";
  return e->sigma ? fmt::format("{:.3f} ± {:.3f}", e->value / 1000.0, *e->sigma / 1000.0)
                  : fmt::format("{:.3f}", e->value / 1000.0);
}

bool is_rpm_or_thrust(const std::string& role) {
  return role.rfind("rpm.", 0) == 0 || role.rfind("thrust.", 0) == 0;
}

// The thrust maps of the vessel file: c = ρK_T D⁴ for each sign (3.17), tables 3.1/3.2.
std::map<std::string, ident::ThrustMap> vessel_maps(const scenario::VesselConfig& v) {
  const auto& p = v.propeller;
  const double d4 = std::pow(p.diameter, 4);
  const ident::ThrustMap propeller{p.rho * p.kt_forward * d4, -p.rho * p.kt_reverse * d4};
  const auto& t = v.tunnel;
  const double t4 = std::pow(t.diameter, 4);
  const ident::ThrustMap tunnel{t.rho * t.kt_starboard * t4, -t.rho * t.kt_port * t4};
  return {{"port", propeller}, {"stb", propeller}, {"tunnel", tunnel}};
}

void run_fit(const ThrustMapOptions& o) {
  check_json_target(o.json);
  const core::Log log = o.input.read(is_rpm_or_thrust);
  const std::vector<std::string> rpm = thruster_names(log, "rpm");
  nlohmann::json doc;
  doc["analysis"] = "thrust-map";
  doc["log"] = o.input.log.string();
  doc["unit"] = "N/rps^2";
  doc["thrusters"] = nlohmann::json::array();
  std::string table = fmt::format("{:<10} {:>20} {:>20} {:>9} {:>8} {:>8} {:>7}\n", "thruster",
                                  "c+ [kN/rps²]", "c- [kN/rps²]", "c̄", "n+", "n-", "R²");
  int fitted = 0;
  for (const std::string& name : rpm) {
    if (!log.has("thrust." + name)) continue;
    ident::ThrustMapFitOptions f;
    f.min_abs_shaft_speed_rps = o.min_speed_rpm / 60.0;
    f.shaft_speed_name = "rpm." + name;
    f.thrust_name = "thrust." + name;
    const ident::ThrustMapFitResult r =
        ident::fit_thrust_map(log.values("rpm." + name), log.values("thrust." + name), f);
    std::optional<double> c_mean;
    if (r.c_forward && r.c_reverse) {
      c_mean = ident::ThrustMap{r.c_forward->value, r.c_reverse->value}.mean_coefficient();
    }
    const auto sig = [](const std::optional<ident::Estimate>& e) {
      return e ? opt(e->sigma) : nlohmann::json(nullptr);
    };
    doc["thrusters"].push_back(
        {{"name", name},
         {"c_pos", r.c_forward ? opt(r.c_forward->value) : nlohmann::json(nullptr)},
         {"c_neg", r.c_reverse ? opt(r.c_reverse->value) : nlohmann::json(nullptr)},
         {"sigma", {{"c_pos", sig(r.c_forward)}, {"c_neg", sig(r.c_reverse)}}},
         {"c_mean", opt(c_mean)},
         {"n_samples", {{"pos", r.samples_forward}, {"neg", r.samples_reverse}}},
         {"r_squared", opt(r.r_squared)},
         {"status", std::string(ident::fit_status_name(r.status))},
         {"message", r.message}});
    table += fmt::format("{:<10} {:>20} {:>20} {:>9} {:>8} {:>8} {:>7}\n", name, kn(r.c_forward),
                         kn(r.c_reverse), c_mean ? fmt::format("{:.3f}", *c_mean / 1000.0) : "—",
                         r.samples_forward, r.samples_reverse,
                         r.r_squared ? fmt::format("{:.4f}", *r.r_squared) : "—");
    ++fitted;
  }
  if (fitted == 0) {
    throw core::InputError({o.input.log.string(), {}, {}, "thrust.NAME"},
                           "no thruster with both shaft speed and thrust in the log",
                           "map them per thruster, e.g. --col rpm.port=RPM_P --col "
                           "thrust.port=THRUST_P (a dynpos log names them so already)");
  }
  if (!o.json.empty()) io::write_json(o.json, doc);
  std::FILE* out = o.json == "-" ? stderr : stdout;
  fmt::print(out, "{}: thrust map T = c·n|n| (3.17), |n| ≥ {} rpm, ±1σ\n{}", o.input.log.string(),
             o.min_speed_rpm, table);
  if (!o.json.empty() && o.json != "-") fmt::print(out, "wrote {}\n", o.json);
}

void run_apply(const ThrustMapOptions& o) {
  if (o.out.empty()) {
    throw core::InputError({{}, {}, {}, "--out"}, "--apply needs --out FILE.csv",
                           "name the CSV to write the computed thrust into");
  }
  const scenario::VesselConfig vessel = scenario::load_vessel_config(
      o.vessel.empty() ? analysis::find_data_dir() / "vessels" / "gunnerus.toml" : o.vessel);
  const auto maps = vessel_maps(vessel);
  const core::Log log =
      o.input.read([](const std::string& role) { return role.rfind("rpm.", 0) == 0; });
  core::Log result(log.time());
  int applied = 0;
  for (const std::string& name : thruster_names(log, "rpm")) {
    const auto it = maps.find(name);
    if (it == maps.end()) {
      throw core::InputError({o.input.log.string(), {}, {}, "rpm." + name},
                             "no thrust map for thruster '" + name + "' in the vessel file",
                             "the vessel file has port, stb (main propellers) and tunnel");
    }
    const std::vector<double>& n = log.values("rpm." + name);
    std::vector<double> thrust_kN =
        o.abs_speed ? ident::thrust_from_abs_speed(it->second.mean_coefficient(), n)
                    : it->second.thrust(n);
    for (double& t : thrust_kN) t /= 1000.0;
    std::vector<double> rpm(n.size());
    for (std::size_t i = 0; i < n.size(); ++i) rpm[i] = n[i] * 60.0;
    result.add_channel("rpm." + name, "rpm", std::move(rpm));
    result.add_channel("thrust." + name, "kN", std::move(thrust_kN));
    ++applied;
  }
  if (applied == 0) {
    throw core::InputError({o.input.log.string(), {}, {}, "rpm.NAME"},
                           "no shaft speed column in the log",
                           "map one per thruster, e.g. --col rpm.port=RPM_P");
  }
  io::write_csv(o.out, result);
  fmt::print("{}: thrust of {} thruster(s) from {} ({}) into {}\n", o.input.log.string(), applied,
             vessel.source.empty() ? std::string("the built-in vessel") : vessel.source,
             o.abs_speed ? "|n| only: mean coefficient (3.18)" : "signed n: c+ / c- (3.17)",
             o.out.string());
}

}  // namespace

void add_identify_thrust_map(CLI::App& identify) {
  auto o = std::make_shared<ThrustMapOptions>();
  CLI::App* sub = identify.add_subcommand(
      "thrust-map", "Thrust map: back-calculate c+ and c- of T = c n|n| (3.17), or apply a map");
  o->input.add_options(*sub, "time, rpm.NAME (shaft speed), thrust.NAME, per thruster NAME");
  sub->add_option("--min-speed", o->min_speed_rpm,
                  "Leave out samples with |n| below this [rpm]: near zero the thrust is noise")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--json", o->json, "Write the coefficients as JSON to FILE, or '-' for stdout");
  sub->add_flag("--apply", o->apply,
                "Apply the vessel file's maps to a log with shaft speed only; writes --out");
  sub->add_flag("--abs-speed", o->abs_speed,
                "With --apply: the log has |n| only, so use the mean coefficient (3.18)");
  sub->add_option("--vessel", o->vessel, "With --apply: vessel file (default: built-in Gunnerus)")
      ->check(CLI::ExistingFile);
  sub->add_option("--out", o->out, "With --apply: CSV to write (time, rpm.NAME, thrust.NAME)");
  sub->footer(
      "Back-calculation: for each sign of n, c = Σ T n² / Σ n⁴ (least squares through the "
      "origin), with 1σ from the residuals. Values in N/rps² in JSON (c_pos, c_neg, c_mean), "
      "kN/rps² in the table (thesis table 3.2: 8.13 / -5.8). Example: dynpos identify "
      "thrust-map DIR/log.csv --json map.json");
  sub->callback([o] { o->apply ? run_apply(*o) : run_fit(*o); });
}

}  // namespace dynpos::cli
