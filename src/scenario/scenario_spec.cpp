#include "dynpos/scenario/scenario_spec.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "dynpos/core/error.hpp"
#include "dynpos/core/param_range.hpp"
#include "dynpos/io/nmea.hpp"
#include "dynpos/model/environment.hpp"
#include "dynpos/model/sea_state.hpp"
#include "dynpos/sim/sim_time.hpp"
#include "param_fields.hpp"
#include "toml_fields.hpp"

namespace dynpos::scenario {
namespace {

using detail::TomlTable;

core::InputLocation at(const ScenarioSpec& spec, std::string field) {
  return {spec.source, {}, {}, std::move(field)};
}

// The ranges of the scenario file's numbers that validate() checks again after the command
// line may have changed them (core/param_range.hpp).
const core::ParamRange kDuration{"duration_s", "s", 1e-6, 1e6};
const core::ParamRange kStep{"dt_s", "s", 1e-5, 1.0};
const core::ParamRange kLogRate{"log_rate_hz", "Hz", 1e-3, 1000.0};
const core::ParamRange kInitialSurge{"initial_surge_mps", "m/s", -4.0, 7.0};
const core::ParamRange kSettle{"settle_s", "s", 0.0, 3600.0};
const core::ParamRange kLeverPct{"pct", "%", -100.0, 100.0};
const core::ParamRange kRudderAngle{"angle_deg", "deg", -90.0, 90.0};

// `range` with another key (an entry of an array of tables).
core::ParamRange keyed(const core::ParamRange& range, std::string key) {
  core::ParamRange out = range;
  out.key = std::move(key);
  return out;
}

void check_range(const ScenarioSpec& spec, const std::string& field, double value,
                 const core::ParamRange& range) {
  if (!range.contains(value)) {
    throw core::InputError(at(spec, field), fmt::format("value {} is out of range", value),
                           "expected a number in " + range.interval());
  }
}

void check_range(const ScenarioSpec& spec, const std::string& field, double value, double lo,
                 double hi) {
  check_range(spec, field, value, core::ParamRange{field, "", lo, hi});
}

// A duration the simulator must step exactly: a whole number of dt_s (sim::TimeGrid's rule).
void check_whole_steps(const ScenarioSpec& spec, const std::string& field, double value_s) {
  const double steps = value_s / spec.dt_s;
  if (std::abs(steps - std::round(steps)) > sim::kTickTolerance * steps) {
    throw core::InputError(at(spec, field),
                           fmt::format("{} s is not a multiple of dt_s = {} s", value_s, spec.dt_s),
                           "give a whole number of dt_s steps (or a dt_s that divides it)");
  }
}

EnvironmentSpec read_environment(const TomlTable& t) {
  t.reject_unknown({"current_speed_mps", "current_to_deg", "wind_speed_mps", "wind_from_deg",
                    "hs_m", "tp_s", "wave_from_deg", "wave_components"});
  EnvironmentSpec env;
  env.current_speed_mps = t.number_or(env.current_speed_mps, model::kCurrentSpeedRange);
  env.current_to_deg = t.number_or("current_to_deg", env.current_to_deg, -360.0, 360.0);
  env.wind_speed_mps = t.number_or(env.wind_speed_mps, model::kWindSpeedRange);
  env.wind_from_deg = t.number_or("wind_from_deg", env.wind_from_deg, -360.0, 360.0);
  env.hs_m = t.number_or(env.hs_m, model::kSignificantWaveHeightRange);
  env.tp_s = t.number_or(env.tp_s, model::kPeakPeriodRange);
  env.wave_from_deg = t.number_or("wave_from_deg", env.wave_from_deg, -360.0, 360.0);
  env.wave_components =
      static_cast<int>(t.number_or(env.wave_components, model::kWaveComponentsRange));
  return env;
}

// Calls fn for each table of the array of tables [[key]], if present.
template <typename Fn>
void for_each_row(const toml::table& doc, const TomlTable& root, const char* key, Fn fn) {
  const toml::node* node = doc.get(key);
  if (node == nullptr) return;
  const toml::array* rows = node->as_array();
  if (rows == nullptr) {
    throw core::InputError(root.where(key), "expected an array of tables",
                           fmt::format("write each entry as [[{}]]", key));
  }
  for (std::size_t i = 0; i < rows->size(); ++i) {
    const toml::table* row = (*rows)[i].as_table();
    if (row == nullptr) {
      throw core::InputError(root.where(key), fmt::format("expected a table in [[{}]]", key));
    }
    fn(TomlTable(*row, root.file(), fmt::format("{}[{}]", key, i + 1)));
  }
}

// The rules of a DP scenario ([[setpoint]] entries): no joystick modes, increasing times.
void validate_dp_mode(const ScenarioSpec& spec) {
  if (spec.heading_hold) {
    throw core::InputError(at(spec, "heading_hold"), "heading_hold is a joystick mode",
                           "DP setpoints hold the heading already; remove heading_hold");
  }
  if (spec.settle_s > 0.0) {
    throw core::InputError(at(spec, "settle_s"), "settle_s is a joystick mode",
                           "DP starts at its first setpoint from rest; remove settle_s");
  }
  if (!spec.joystick.empty()) {
    throw core::InputError(at(spec, "setpoint"), "a scenario is either joystick or DP",
                           "remove the [[joystick]] entries or the [[setpoint]] entries");
  }
  if (spec.setpoints.front().t_s < 0.0) {
    throw core::InputError(at(spec, "setpoint[1].t_s"), "the first setpoint needs a time");
  }
  double last = -1.0;
  for (std::size_t i = 0; i < spec.setpoints.size(); ++i) {
    if (spec.setpoints[i].t_s < 0.0) continue;
    const std::string field = fmt::format("setpoint[{}].t_s", i + 1);
    check_range(spec, field, spec.setpoints[i].t_s, 0.0, spec.duration_s);
    if (spec.setpoints[i].t_s <= last) {
      throw core::InputError(at(spec, field), "setpoint times must increase");
    }
    last = spec.setpoints[i].t_s;
  }
}

// The observer, the failure and the dropouts.
void validate_events(const ScenarioSpec& spec) {
  if (spec.observer != control::ObserverKind::kIdeal && spec.setpoints.empty()) {
    throw core::InputError(at(spec, "observer"), "an observer runs in the DP loop",
                           "add [[setpoint]] entries or remove the observer");
  }
  if (spec.failure) {
    check_range(spec, "failure_at_s", spec.failure->t_s, 0.0, spec.duration_s);
    if (spec.failure->name.empty()) {
      throw core::InputError(at(spec, "failure"), "no unit named",
                             "name the unit, group:NAME or actuator that fails");
    }
  }
  double end = -1.0;
  for (std::size_t i = 0; i < spec.gnss_dropouts.size(); ++i) {
    const DropoutEvent& d = spec.gnss_dropouts[i];
    const std::string field = fmt::format("gnss_dropout[{}]", i + 1);
    check_range(spec, field + ".t_s", d.t_s, 0.0, spec.duration_s);
    check_range(spec, field + ".duration_s", d.duration_s, 1e-3, 86400.0);
    if (d.t_s < end) {
      throw core::InputError(at(spec, field + ".t_s"),
                             "dropouts must be in increasing time and not overlap");
    }
    end = d.t_s + d.duration_s;
  }
}

}  // namespace

bool any_covers(const std::vector<DropoutEvent>& dropouts, double t) noexcept {
  return std::any_of(dropouts.begin(), dropouts.end(),
                     [t](const DropoutEvent& d) { return d.covers(t); });
}

void ScenarioSpec::set_duration(double duration) {
  duration_s = duration;
  auto after_end = [&](const auto& c) { return c.t_s > duration; };
  joystick.erase(std::remove_if(joystick.begin(), joystick.end(), after_end), joystick.end());
  rudder.erase(std::remove_if(rudder.begin(), rudder.end(), after_end), rudder.end());
  setpoints.erase(std::remove_if(setpoints.begin(), setpoints.end(), after_end), setpoints.end());
  if (failure && failure->t_s > duration) failure.reset();
  gnss_dropouts.erase(std::remove_if(gnss_dropouts.begin(), gnss_dropouts.end(), after_end),
                      gnss_dropouts.end());
}

void ScenarioSpec::validate() const {
  if (name.empty()) throw core::InputError(at(*this, "name"), "scenario has no name");
  check_range(*this, "duration_s", duration_s, kDuration);
  check_range(*this, "dt_s", dt_s, kStep);
  check_whole_steps(*this, "duration_s", duration_s);
  check_range(*this, "log_rate_hz", log_rate_hz, kLogRate);
  const double ticks_per_log = 1.0 / (log_rate_hz * dt_s);
  if (std::abs(ticks_per_log - std::round(ticks_per_log)) > 1e-9 * ticks_per_log ||
      std::round(ticks_per_log) < 1.0) {
    throw core::InputError(
        at(*this, "log_rate_hz"),
        fmt::format("log period 1/{} s is not a multiple of dt_s = {} s", log_rate_hz, dt_s),
        "choose a log rate whose period is a whole number of steps");
  }
  if (device_files) {
    const double logs_per_feedback = log_rate_hz / device_files->feedback_rate_hz;
    if (std::abs(logs_per_feedback - std::round(logs_per_feedback)) > 1e-9 * logs_per_feedback ||
        std::round(logs_per_feedback) < 1.0) {
      throw core::InputError(at(*this, "device_files.feedback_rate_hz"),
                             fmt::format("{} Hz does not divide the log rate {} Hz",
                                         device_files->feedback_rate_hz, log_rate_hz),
                             "choose a rate whose period is a whole number of log periods");
    }
  }
  check_range(*this, "initial_surge_mps", initial_surge_mps, kInitialSurge);
  check_range(*this, "settle_s", settle_s, kSettle);
  if (settle_s != std::round(settle_s)) {
    throw core::InputError(at(*this, "settle_s"),
                           fmt::format("{} s is not a whole number of seconds", settle_s),
                           "give the settling time in whole seconds, so every task's grid keeps "
                           "its phase at t = 0");
  }
  check_whole_steps(*this, "settle_s", settle_s);
  {
    const auto bad_start = [&](const std::string& problem) {
      throw core::InputError(at(*this, "start_utc"), problem,
                             "write the UTC of t = 0 as \"YYYY-MM-DDTHH:MM:SS[.sss]Z\", e.g. "
                             "\"2014-08-27T10:00:00Z\"");
    };
    std::optional<io::UtcTimestamp> start;
    try {
      start = io::parse_utc_timestamp(start_utc);
    } catch (const core::InputError& e) {
      bad_start(e.problem());
    }
    if (!start->date) bad_start(fmt::format("'{}' has no date", start_utc));
  }
  double previous = -1.0;
  for (std::size_t i = 0; i < joystick.size(); ++i) {
    const JoystickCommand& c = joystick[i];
    const std::string field = fmt::format("joystick[{}]", i + 1);
    check_range(*this, field + ".t_s", c.t_s, 0.0, duration_s);
    if (c.t_s <= previous) {
      throw core::InputError(at(*this, field + ".t_s"),
                             fmt::format("time {} s is not after the previous command", c.t_s),
                             "list joystick commands in increasing time");
    }
    previous = c.t_s;
    check_range(*this, field + ".surge_pct", c.surge_pct, kLeverPct);
    check_range(*this, field + ".sway_pct", c.sway_pct, kLeverPct);
    check_range(*this, field + ".yaw_pct", c.yaw_pct, kLeverPct);
  }
  if (hybrid_integral && setpoints.empty()) {
    throw core::InputError(at(*this, "hybrid"), "hybrid integral action needs DP setpoints",
                           "add [[setpoint]] entries or remove the [hybrid] section");
  }
  if (!setpoints.empty()) validate_dp_mode(*this);
  validate_events(*this);
  previous = -1.0;
  for (std::size_t i = 0; i < rudder.size(); ++i) {
    const std::string field = fmt::format("rudder[{}]", i + 1);
    check_range(*this, field + ".t_s", rudder[i].t_s, 0.0, duration_s);
    if (rudder[i].t_s <= previous) {
      throw core::InputError(
          at(*this, field + ".t_s"),
          fmt::format("time {} s is not after the previous command", rudder[i].t_s),
          "list rudder commands in increasing time");
    }
    previous = rudder[i].t_s;
    if (!rudder[i].release) {
      check_range(*this, field + ".angle_deg", rudder[i].angle_deg, kRudderAngle);
    }
  }
  for (std::size_t i = 0; i < loads.size(); ++i) {
    if (!(loads[i].t_off_s > loads[i].t_on_s)) {
      throw core::InputError(at(*this, fmt::format("load[{}].t_off_s", i + 1)),
                             "a load must switch off after it switches on");
    }
  }
}

ScenarioSpec load_scenario(const std::filesystem::path& path) {
  const std::string file = path.string();
  const toml::table doc = TomlTable::parse_file(file);
  const TomlTable root(doc, file, "");
  root.reject_unknown({"name",
                       "description",
                       "duration_s",
                       "dt_s",
                       "log_rate_hz",
                       "initial_heading_deg",
                       "initial_surge_mps",
                       "heading_hold",
                       "settle_s",
                       "start_utc",
                       "environment",
                       "joystick",
                       "hybrid",
                       "rudder",
                       "setpoint",
                       "load",
                       "device_files",
                       "observer",
                       "observer_wind_feedforward",
                       "inertial_position_aid",
                       "failure_at_s",
                       "failure",
                       "gnss_dropout"});
  ScenarioSpec spec;
  spec.source = file;
  spec.name = root.string("name");
  spec.description = root.string_or("description", "");
  spec.duration_s = root.number(kDuration);
  spec.dt_s = root.number_or(spec.dt_s, kStep);
  spec.log_rate_hz = root.number_or(spec.log_rate_hz, kLogRate);
  spec.initial_heading_deg = root.number_or("initial_heading_deg", 0.0, -360.0, 360.0);
  spec.initial_surge_mps = root.number_or(0.0, kInitialSurge);
  spec.heading_hold = root.boolean_or("heading_hold", false);
  spec.settle_s = root.number_or(0.0, kSettle);
  spec.start_utc = root.string_or("start_utc", spec.start_utc);
  if (auto env = root.optional_table("environment")) spec.environment = read_environment(*env);

  for_each_row(doc, root, "joystick", [&](const TomlTable& t) {
    t.reject_unknown({"t_s", "surge_pct", "sway_pct", "yaw_pct"});
    JoystickCommand c;
    c.t_s = t.number("t_s", 0.0, 1e6);
    c.surge_pct = t.number_or(0.0, keyed(kLeverPct, "surge_pct"));
    c.sway_pct = t.number_or(0.0, keyed(kLeverPct, "sway_pct"));
    c.yaw_pct = t.number_or(0.0, keyed(kLeverPct, "yaw_pct"));
    spec.joystick.push_back(c);
  });
  for_each_row(doc, root, "rudder", [&](const TomlTable& t) {
    t.reject_unknown({"t_s", "angle_deg", "release"});
    RudderCommand c;
    c.t_s = t.number("t_s", 0.0, 1e6);
    c.release = t.boolean_or("release", false);
    if (!c.release) c.angle_deg = t.number(kRudderAngle);
    spec.rudder.push_back(c);
  });
  for_each_row(doc, root, "setpoint", [&](const TomlTable& t) {
    t.reject_unknown({"t_s", "north_m", "east_m", "heading_deg", "name"});
    SetpointCommand c;
    c.t_s = t.number_or("t_s", -1.0, -1.0, 1e6);
    c.north_m = t.number("north_m", -1e5, 1e5);
    c.east_m = t.number("east_m", -1e5, 1e5);
    c.heading_deg = t.number("heading_deg", -360.0, 360.0);
    c.name = t.string_or("name", "");
    spec.setpoints.push_back(c);
  });
  for_each_row(doc, root, "load", [&](const TomlTable& t) {
    t.reject_unknown({"t_on_s", "t_off_s", "north_N", "east_N", "yaw_Nm"});
    LoadEvent e;
    e.t_on_s = t.number_or("t_on_s", 0.0, 0.0, 1e6);
    e.t_off_s = t.number_or("t_off_s", e.t_off_s, 0.0, 1e300);
    e.north_N = t.number_or("north_N", 0.0, -1e8, 1e8);
    e.east_N = t.number_or("east_N", 0.0, -1e8, 1e8);
    e.yaw_Nm = t.number_or("yaw_Nm", 0.0, -1e10, 1e10);
    spec.loads.push_back(e);
  });
  if (root.has("observer")) {
    const std::string name = root.string("observer");
    const std::optional<control::ObserverKind> kind = control::parse_observer(name);
    if (!kind) {
      throw core::InputError(root.where("observer"), fmt::format("unknown observer '{}'", name),
                             "use ideal, passive, ekf or raw");
    }
    spec.observer = *kind;
  }
  spec.observer_wind_feedforward = root.boolean_or("observer_wind_feedforward", true);
  spec.inertial_position_aid = root.boolean_or("inertial_position_aid", true);
  if (root.has("failure") || root.has("failure_at_s")) {
    spec.failure = FailureEvent{root.number("failure_at_s", 0.0, 1e6), root.string("failure")};
  }
  for_each_row(doc, root, "gnss_dropout", [&](const TomlTable& t) {
    t.reject_unknown({"t_s", "duration_s"});
    spec.gnss_dropouts.push_back(
        {t.number("t_s", 0.0, 1e6), t.number("duration_s", 1e-3, 86400.0)});
  });
  if (auto h = root.optional_table("hybrid")) {
    hybrid::IntegralJumpParams p;
    detail::read_fields(*h, hybrid::param_fields(p), {"enabled"});
    if (h->boolean_or("enabled", true)) spec.hybrid_integral = p;
  }
  if (auto d = root.optional_table("device_files")) {
    d->reject_unknown({"enabled", "feedback_rate_hz", "order_wiggle_rpm", "order_wiggle_deg",
                       "order_wiggle_pct"});
    DeviceFilesSpec f;
    f.feedback_rate_hz = d->number_or("feedback_rate_hz", f.feedback_rate_hz, 0.01, 100.0);
    f.order_wiggle_rpm = d->number_or("order_wiggle_rpm", f.order_wiggle_rpm, 0.0, 50.0);
    f.order_wiggle_deg = d->number_or("order_wiggle_deg", f.order_wiggle_deg, 0.0, 10.0);
    f.order_wiggle_pct = d->number_or("order_wiggle_pct", f.order_wiggle_pct, 0.0, 10.0);
    if (d->boolean_or("enabled", true)) spec.device_files = f;
  }
  spec.validate();
  return spec;
}

std::vector<std::string> list_scenarios(const std::filesystem::path& scenario_dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(scenario_dir, ec)) {
    if (entry.path().extension() == ".toml") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::filesystem::path resolve_scenario(const std::string& name_or_path,
                                       const std::filesystem::path& scenario_dir) {
  const std::filesystem::path as_path(name_or_path);
  if (as_path.extension() == ".toml") {
    if (std::filesystem::is_regular_file(as_path)) return as_path;
    throw core::InputError({name_or_path, {}, {}, {}}, "scenario file not found");
  }
  const std::filesystem::path builtin = scenario_dir / (name_or_path + ".toml");
  if (std::filesystem::is_regular_file(builtin)) return builtin;
  std::string list;
  for (const std::string& n : list_scenarios(scenario_dir)) list += (list.empty() ? "" : ", ") + n;
  throw core::InputError(
      {}, fmt::format("unknown scenario '{}'", name_or_path),
      "available: " +
          (list.empty() ? std::string("none found in ") + scenario_dir.string() : list));
}

}  // namespace dynpos::scenario
