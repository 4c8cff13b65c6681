#include "dynpos/analysis/failure_test.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "dynpos/analysis/control_origin_track.hpp"
#include "dynpos/analysis/options.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/core/samples.hpp"

namespace dynpos::analysis {
namespace {

bool wanted_role(const std::string& role) {
  for (const char* r : {"north", "east", "lat", "lon", "heading", "roll", "pitch"}) {
    if (role == r) return true;
  }
  return role.rfind("thrust.", 0) == 0 || role.rfind("rpm.", 0) == 0 ||
         role.rfind("command.thrust.", 0) == 0 || role.rfind("command.rpm.", 0) == 0;
}

// Each unit's feedback: its thrust when logged with a valid sample (unless use_rpm), else its
// shaft speed; a channel without a valid sample is left out, with a note.
void read_units(const FailureTestRequest& request, const core::Log& log, FailureTestReport& report,
                ident::FailureTestInput& in) {
  std::vector<std::string> names;
  if (!request.use_rpm) names = thruster_names(log, "thrust");
  for (const std::string& n : thruster_names(log, "rpm")) {
    if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  }
  for (const std::string& name : names) {
    for (const char* kind : {"thrust", "rpm"}) {
      const std::string channel = std::string(kind) + "." + name;
      if ((request.use_rpm && channel.rfind("thrust.", 0) == 0) || !log.has(channel)) continue;
      if (!core::has_valid_sample(log.values(channel))) {
        report.notes.push_back(channel + " has no valid sample: left out");
        continue;
      }
      const bool thrust = channel.rfind("thrust.", 0) == 0;
      report.units.push_back({name, channel, thrust ? "kN" : "rpm", thrust ? 1e-3 : 60.0});
      // The unit's order of the same kind, when logged: a stop it was ordered is not a trip.
      const std::string order = "command." + channel;
      in.units.push_back({name, log.values(channel),
                          log.has(order) ? log.values(order) : std::vector<double>{},
                          thrust ? 2.0 : 1.0});  // thrust ∝ n|n|
      break;
    }
  }
  if (in.units.empty()) {
    throw request.source.error(
        request.use_rpm ? "rpm.NAME" : "thrust.NAME/rpm.NAME",
        request.use_rpm ? "no shaft speed channel (rpm.NAME) with a valid sample in the log"
                        : "no unit feedback channel (thrust.NAME or rpm.NAME) with a valid "
                          "sample in the log",
        "map one per unit, e.g. --col thrust.port=PORT_THRUST or --col rpm.port=PORT_RPM");
  }
}

// The position [m] of the control origin: north/east or lat/lon as logged, moved by the arm.
void read_position(const FailureTestRequest& request, const core::Log& log,
                   FailureTestReport& report, ident::FailureTestInput& in) {
  ControlOriginTrack track = control_origin_track(request.source, log, request.arm_m);
  report.position = track.position;
  report.has_heading = track.has_heading;
  report.attitude = track.attitude;
  in.north_m = std::move(track.north_m);
  in.east_m = std::move(track.east_m);
  in.heading_rad = std::move(track.heading_rad);
}

}  // namespace

ident::FailureTestOptions FailureTestRequest::options() const {
  ident::FailureTestOptions o;
  o.pre_window_s = pre_window_s;
  o.redistribution_window_s = redistribution_window_s;
  o.hold_s = hold_s;
  o.response_window_s = response_window_s;
  o.max_fall_s = max_fall_s;
  o.min_off_s = min_off_s;
  o.validate();  // names the request key
  return o;
}

void FailureTestRequest::validate() const {
  options();
  if (arm_m && !arm_m->allFinite()) {
    throw option_error("arm", "the antenna lever arm is not finite", "give X,Y[,Z] in metres");
  }
}

FailureTestReport run_failure_test(const FailureTestRequest& request) {
  request.validate();
  // Only the rows of the window are read (memory and time follow the window, not the file).
  LogSource source = request.source;
  source.window_from_s = request.t_from_s;
  source.window_to_s = request.t_to_s;
  LoadedLog loaded = source.load(wanted_role);
  const core::Log& log = loaded.log;
  FailureTestReport report;
  report.log = request.source.log;
  report.input = std::move(loaded.input);
  report.arm_m = request.arm_m;
  report.options = request.options();
  ident::FailureTestInput in;
  in.t_s = log.time();
  read_units(request, log, report, in);
  read_position(request, log, report, in);
  try {
    report.result = ident::analyse_failure_test(in, report.options);
  } catch (const core::InputError& e) {
    throw request.source.in_log(e);
  }
  return report;
}

}  // namespace dynpos::analysis
