#include "dynpos/analysis/four_corner.hpp"

#include <map>
#include <numbers>

#include "dynpos/analysis/options.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/ident/local_position.hpp"

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

// The position [m]: north/east as logged, or lat/lon made local.
void read_position(const FourCornerRequest& request, const core::Log& log,
                   ident::FourCornerInput& in) {
  std::optional<ident::LocalPositions> p = local_position(log);
  if (!p) {
    throw request.source.error("north/east", "no position in the log",
                               "map north and east in metres (any offset, e.g. UTM: --col "
                               "north=gnss1.north --col east=gnss1.east) or lat and lon");
  }
  in.north_m = std::move(p->north_m);
  in.east_m = std::move(p->east_m);
}

ident::FourCornerInput make_input(const FourCornerRequest& request, const core::Log& log) {
  ident::FourCornerInput in;
  in.t_s = log.time();
  read_position(request, log, in);
  if (!log.has("heading")) {
    throw request.source.error("heading", "no heading in the log",
                               "map heading (--col heading=COLUMN)");
  }
  in.heading_rad = log.values("heading");
  if (request.arm_m) {
    in.arm_x_m = request.arm_m->x();
    in.arm_y_m = request.arm_m->y();
  }
  in.setpoint_north_m = values_or_empty(log, "setpoint.north");
  in.setpoint_east_m = values_or_empty(log, "setpoint.east");
  in.setpoint_heading_rad = values_or_empty(log, "setpoint.heading");
  in.thrusters = thrust_power_channels(log);
  return in;
}

}  // namespace

std::string to_string(ident::LegSegmentation segmentation) {
  switch (segmentation) {
    case ident::LegSegmentation::kSetpoints:
      return "setpoints";
    case ident::LegSegmentation::kTrack:
      return "track";
    case ident::LegSegmentation::kAuto:
      break;
  }
  return "auto";
}

const std::map<std::string, ident::LegSegmentation>& leg_segmentation_names() {
  static const std::map<std::string, ident::LegSegmentation> names = [] {
    std::map<std::string, ident::LegSegmentation> m;
    for (auto s : {ident::LegSegmentation::kAuto, ident::LegSegmentation::kSetpoints,
                   ident::LegSegmentation::kTrack}) {
      m.emplace(to_string(s), s);
    }
    return m;
  }();
  return names;
}

ident::LegSegmentation parse_leg_segmentation(const std::string& name) {
  const auto& names = leg_segmentation_names();
  if (const auto it = names.find(name); it != names.end()) return it->second;
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

void FourCornerRequest::validate() const {
  options();
  if (arm_m && !arm_m->allFinite()) {
    throw option_error("arm", "the antenna lever arm is not finite", "give X,Y in metres");
  }
}

FourCornerReport run_four_corner(const FourCornerRequest& request) {
  request.validate();
  const ident::FourCornerOptions options = request.options();
  // Only the rows of the window are read (memory and time follow the window, not the file).
  LogSource source = request.source;
  source.window_from_s = request.t_from_s;
  source.window_to_s = request.t_to_s;
  LoadedLog loaded = source.load(wanted_role);
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
    throw request.source.in_log(e);
  }
  return report;
}

}  // namespace dynpos::analysis
