#include "dynpos/analysis/station_keeping.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <string>
#include <vector>

#include "dynpos/analysis/options.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/ident/local_position.hpp"

namespace dynpos::analysis {
namespace {

bool wanted_role(const std::string& role) {
  for (const char* r : {"north", "east", "lat", "lon", "heading", "wind_speed", "wind_dir",
                        "setpoint.north", "setpoint.east", "setpoint.heading"}) {
    if (role == r) return true;
  }
  return role.rfind("thrust.", 0) == 0 || role.rfind("power.", 0) == 0;
}

// A channel's values moved out of `log` (empty if it has none): the input takes the log's
// columns instead of copies of them (a day-long log would be held twice). The channel is left
// without values; make_input() is the last to use it.
std::vector<double> take_values(core::Log& log, const std::string& name) {
  return log.has(name) ? std::move(log.channel(name).values) : std::vector<double>{};
}

// The position in metres: north/east as logged (any offset), else lat/lon about their first fix.
// The time axis is copied (a Log keeps its own); every other column is moved out of `log`.
ident::StationKeepingInput make_input(core::Log& log) {
  ident::StationKeepingInput in;
  in.t_s = log.time();
  if (log.has("north") && log.has("east")) {
    in.north_m = take_values(log, "north");
    in.east_m = take_values(log, "east");
  } else if (std::optional<ident::LocalPositions> p = local_position(log)) {
    in.north_m = std::move(p->north_m);
    in.east_m = std::move(p->east_m);
    take_values(log, "lat");  // done with: freed
    take_values(log, "lon");
  }
  in.heading_rad = take_values(log, "heading");
  in.wind_speed_mps = take_values(log, "wind_speed");
  in.wind_dir_rad = take_values(log, "wind_dir");
  for (const std::string& n : thrust_power_names(log)) {
    in.thrusters.push_back({n, take_values(log, "thrust." + n), take_values(log, "power." + n)});
  }
  return in;
}

// The window from/to give; a missing end is duration_s from the other (the rule of this
// analysis: LogSource takes the window it makes).
ident::TimeWindow given_window(const StationKeepingRequest& request) {
  const std::optional<double>& from = request.t_from_s;
  const std::optional<double>& to = request.t_to_s;
  const double duration = request.duration_s;
  return {"window", from.value_or(to ? *to - duration : 0.0),
          to.value_or(from ? *from + duration : 0.0)};
}

// The given window (a missing end is duration_s from the other), else one per setpoint hold,
// else the last duration_s of the log.
std::vector<ident::TimeWindow> windows_of(const StationKeepingRequest& request,
                                          const core::Log& log,
                                          const ident::StationKeepingInput& in) {
  if (request.t_from_s || request.t_to_s) return {given_window(request)};
  const double duration = request.duration_s;
  if (request.per_setpoint) {
    if (!log.has("setpoint.heading") && !log.has("setpoint.north")) {
      throw request.source.error("setpoint.heading",
                                 "--per-setpoint needs the DP setpoints in the log",
                                 "map setpoint.north, setpoint.east, setpoint.heading, or give "
                                 "--from/--to");
    }
    auto holds = ident::setpoint_windows(in.t_s, values_or_empty(log, "setpoint.north"),
                                         values_or_empty(log, "setpoint.east"),
                                         values_or_empty(log, "setpoint.heading"), duration);
    if (holds.empty()) {  // an empty table would read as "nothing to report"
      throw option_error_in_file(
          request.source.log, "per_setpoint",
          fmt::format("no setpoint is held for {:g} s or more (half of --duration {:g})",
                      0.5 * duration, duration),
          "give a shorter --duration, or a window with --from/--to");
    }
    return holds;
  }
  return {{"last " + fmt::format("{:g}", duration) + " s",
           std::max(in.t_s.front(), in.t_s.back() - duration), in.t_s.back()}};
}

}  // namespace

void StationKeepingRequest::validate() const {
  if (!(duration_s > 0.0)) throw option_error("duration", "the window duration must be > 0 s");
}

StationKeepingReport run_station_keeping(const StationKeepingRequest& request) {
  request.validate();
  // A window given with from/to is all that is read of the main log (memory and time follow
  // the window, not the file); LogSource::load judges it.
  LogSource source = request.source;
  if (request.t_from_s || request.t_to_s) {
    const ident::TimeWindow w = given_window(request);
    source.window_from_s = w.t_from_s;
    source.window_to_s = w.t_to_s;
  }
  LoadedLog loaded = source.load(wanted_role);
  core::Log& log = loaded.log;
  if (!(log.has("north") && log.has("east")) && !(log.has("lat") && log.has("lon"))) {
    throw request.source.error("north/east", "no position in the log",
                               "map north and east in metres (any offset, e.g. UTM: --col "
                               "north=gnss1.north --col east=gnss1.east) or lat and lon");
  }
  ident::StationKeepingInput in = make_input(log);
  in.log_start_s = loaded.log_start_s;
  in.log_end_s = loaded.log_end_s;
  StationKeepingReport report;
  report.log = request.source.log;
  report.input = std::move(loaded.input);
  report.waves = request.waves;
  report.current = request.current;
  report.per_setpoint = request.per_setpoint;
  for (const ident::TimeWindow& w : windows_of(request, log, in)) {
    try {
      report.windows.push_back(ident::analyse_station_keeping(in, w));
    } catch (const core::InputError& e) {
      // A window's problem is one of from/to only when they gave it; else of the window made.
      if (e.option() != "from/to" || source.has_window()) throw request.source.in_log(e);
      throw request.source.error(w.name, e.problem(), e.hint());
    }
  }
  return report;
}

}  // namespace dynpos::analysis
