#include "dynpos/analysis/four_corner.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <numbers>

#include "dynpos/analysis/options.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/ident/local_position.hpp"
#include "dynpos/io/csv_reader.hpp"

namespace dynpos::analysis {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

bool wanted_role(const std::string& role) {
  for (const char* r : {"north", "east", "lat", "lon", "heading", "setpoint.north", "setpoint.east",
                        "setpoint.heading"}) {
    if (role == r) return true;
  }
  return role.rfind("thrust.", 0) == 0 || role.rfind("power.", 0) == 0;
}

// Rows [a, b) of a channel; a channel that is not logged stays empty.
std::vector<double> slice(const std::vector<double>& x, std::size_t a, std::size_t b) {
  if (x.empty()) return x;
  return {x.begin() + static_cast<std::ptrdiff_t>(a), x.begin() + static_cast<std::ptrdiff_t>(b)};
}

// The position [m]: north/east as logged, or lat/lon made local.
void read_position(const FourCornerRequest& request, const core::Log& log,
                   ident::FourCornerInput& in) {
  std::optional<ident::LocalPositions> p = local_position(log);
  if (p) {
    in.north_m = std::move(p->north_m);
    in.east_m = std::move(p->east_m);
  } else {
    throw core::InputError({request.source.log.string(), {}, {}, "north/east"},
                           "no position in the log",
                           "map north and east in metres (any offset, e.g. UTM: --col "
                           "north=gnss1.north --col east=gnss1.east) or lat and lon");
  }
}

// Keeps the rows with time in [from, to] of the request (all rows when neither is given).
void cut_window(const FourCornerRequest& request, ident::FourCornerInput& in) {
  if (!request.t_from_s && !request.t_to_s) return;
  const double from = request.t_from_s.value_or(in.t_s.front());
  const double to = request.t_to_s.value_or(in.t_s.back());
  if (!(to > from) || from > in.t_s.back() || to < in.t_s.front()) {
    throw option_error_in_file(request.source.log, "from/to",
                               fmt::format("the window {:g} … {:g} s is empty or outside the log "
                                           "({:g} … {:g} s)",
                                           from, to, in.t_s.front(), in.t_s.back()),
                               "choose --from < --to inside the log");
  }
  const auto a = static_cast<std::size_t>(std::lower_bound(in.t_s.begin(), in.t_s.end(), from) -
                                          in.t_s.begin());
  const auto b =
      static_cast<std::size_t>(std::upper_bound(in.t_s.begin(), in.t_s.end(), to) - in.t_s.begin());
  for (auto* x : {&in.t_s, &in.north_m, &in.east_m, &in.heading_rad, &in.setpoint_north_m,
                  &in.setpoint_east_m, &in.setpoint_heading_rad}) {
    *x = slice(*x, a, b);
  }
  for (auto& t : in.thrusters) {
    t.thrust_N = slice(t.thrust_N, a, b);
    t.power_W = slice(t.power_W, a, b);
  }
}

ident::FourCornerInput make_input(const FourCornerRequest& request, const core::Log& log) {
  ident::FourCornerInput in;
  in.t_s = log.time();
  read_position(request, log, in);
  if (!log.has("heading")) {
    throw core::InputError({request.source.log.string(), {}, {}, "heading"},
                           "no heading in the log", "map heading (--col heading=COLUMN)");
  }
  in.heading_rad = log.values("heading");
  if (request.arm_m) {
    in.arm_x_m = (*request.arm_m)[0];
    in.arm_y_m = (*request.arm_m)[1];
  }
  in.setpoint_north_m = values_or_empty(log, "setpoint.north");
  in.setpoint_east_m = values_or_empty(log, "setpoint.east");
  in.setpoint_heading_rad = values_or_empty(log, "setpoint.heading");
  in.thrusters = thrust_power_channels(log);
  cut_window(request, in);
  return in;
}

}  // namespace

ident::LegSegmentation parse_leg_segmentation(const std::string& name) {
  if (name == "auto") return ident::LegSegmentation::kAuto;
  if (name == "setpoints") return ident::LegSegmentation::kSetpoints;
  if (name == "track") return ident::LegSegmentation::kTrack;
  throw option_error("segment", "unknown segmentation '" + name + "'",
                     "use auto, setpoints or track");
}

ident::FourCornerOptions FourCornerRequest::options() const {
  ident::FourCornerOptions a;
  a.radius_m = radius_m;
  a.heading_tol_rad = heading_tol_deg / kDeg;
  a.segmentation = segmentation;
  try {
    a.validate();
  } catch (const core::InputError& e) {
    throw option_error("radius/heading_tol", e.problem(), e.hint());
  }
  return a;
}

void FourCornerRequest::validate() const { options(); }

// The log, of which only the rows in --from/--to are read when they are given (memory and time
// follow the window, not the file); a window without rows is an error of --from/--to.
LoadedLog load_window(const FourCornerRequest& request) {
  LogSource source = request.source;
  source.window_from_s = request.t_from_s;
  source.window_to_s = request.t_to_s;
  const auto outside = [&](double log_from, double log_to) {
    return option_error_in_file(
        request.source.log, "from/to",
        fmt::format("the window {:g} … {:g} s is empty or outside the log ({:g} … {:g} s)",
                    request.t_from_s.value_or(log_from), request.t_to_s.value_or(log_to), log_from,
                    log_to),
        "choose --from < --to inside the log");
  };
  if (request.t_from_s && request.t_to_s && !(*request.t_to_s > *request.t_from_s)) {
    throw outside(*request.t_from_s, *request.t_to_s);
  }
  try {
    return source.load(wanted_role);
  } catch (const io::EmptyWindowError& e) {
    throw outside(e.first_row_s, e.last_row_read_s);
  }
}

FourCornerReport run_four_corner(const FourCornerRequest& request) {
  const ident::FourCornerOptions options = request.options();
  LoadedLog loaded = load_window(request);
  const core::Log& log = loaded.log;
  FourCornerReport report;
  report.log = request.source.log;
  report.input = std::move(loaded.input);
  report.radius_m = request.radius_m;
  report.heading_tol_deg = request.heading_tol_deg;
  report.arm_m = request.arm_m;
  report.track = make_input(request, log);
  try {
    report.result = ident::analyse_four_corner(report.track, options);
  } catch (const core::InputError& e) {
    throw core::InputError({request.source.log.string(), {}, {}, e.where().column_name},
                           e.problem(), e.hint());
  }
  return report;
}

}  // namespace dynpos::analysis
