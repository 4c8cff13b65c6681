#include "dynpos/analysis/agility.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "dynpos/analysis/options.hpp"
#include "dynpos/core/circular_stats.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/ident/derived_signals.hpp"

namespace dynpos::analysis {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

bool wanted_role(const std::string& role) {
  for (const char* r : {"command.surge", "command.sway", "command.yaw", "u", "v", "wind_speed",
                        "wind_dir", "heading"}) {
    if (role == r) return true;
  }
  return role.rfind("thrust.", 0) == 0 || role.rfind("rpm.", 0) == 0;
}

std::vector<double> to_pct(std::vector<double> v) {
  for (double& x : v) x *= 100.0;  // the log holds fractions (SI); the demands are in %
  return v;
}

double wrap360(double d) {
  d = std::fmod(d, 360.0);
  return d < 0.0 ? d + 360.0 : d;
}

// Mean wind over the steps of a case: speed [m/s] and the direction it comes from (true, and
// relative to the bow using the mean heading) [deg].
std::optional<AgilityWind> mean_wind(const core::Log& log, const ident::AgilityResult& result,
                                     const std::vector<std::size_t>& steps) {
  if (!log.has("wind_speed") || !log.has("wind_dir")) return std::nullopt;
  const std::vector<double>& t = log.time();
  const std::vector<double>& ws = log.values("wind_speed");
  const std::vector<double>& wd = log.values("wind_dir");
  const std::vector<double> hd = values_or_empty(log, "heading");
  double sum = 0.0;
  std::size_t n = 0;
  std::vector<double> dirs, heads;
  for (const std::size_t k : steps) {
    const ident::AgilityStep& step = result.steps[k];
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (t[i] < step.t_step || t[i] > step.t_end) continue;
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
  AgilityWind w{sum / static_cast<double>(n), wrap360(*dir * kDeg), std::nullopt};
  if (const auto h = core::circular_mean(heads)) w.heading_deg = wrap360(*h * kDeg);
  return w;
}

std::vector<AgilityCase> group_cases(const ident::AgilityResult& result, const core::Log& log,
                                     double min_demand_pct) {
  std::vector<AgilityCase> cases;
  for (std::size_t k = 0; k < result.steps.size(); ++k) {
    const std::string label = ident::agility_case_label(result.steps[k], min_demand_pct);
    auto it = std::find_if(cases.begin(), cases.end(),
                           [&](const AgilityCase& c) { return c.label == label; });
    if (it == cases.end()) {
      cases.push_back({label, {}, std::nullopt});
      it = cases.end() - 1;
    }
    it->steps.push_back(k);
  }
  for (AgilityCase& c : cases) c.wind = mean_wind(log, result, c.steps);
  return cases;
}

// The steps from the windows, or else from the joystick demands.
ident::AgilityResult analyse_steps(const AgilityRequest& request, const core::Log& log,
                                   const std::vector<ident::AgilityChannel>& channels,
                                   const std::vector<double>& speed,
                                   const ident::AgilityOptions& options) {
  const std::vector<double>& t = log.time();
  if (!request.windows.empty()) {
    return ident::analyse_agility(t, request.windows, channels, speed, options);
  }
  if (!log.has("command.surge") || !log.has("command.sway")) {
    throw request.source.error("command.surge, command.sway",
                               "no joystick demand in the log and no --window",
                               "map the demands (--col command.surge=COL --col command.sway=COL, "
                               "in %) or give each step as --window T_STEP,T_END,DIR_DEG");
  }
  const std::vector<double> surge = to_pct(log.values("command.surge"));
  const std::vector<double> sway = to_pct(log.values("command.sway"));
  const std::vector<double> yaw = to_pct(values_or_empty(log, "command.yaw"));
  return ident::analyse_agility(t, {surge, sway, yaw}, channels, speed, options);
}

// The total speed √(u²+v²) (3.19), u alone, or empty when neither is logged.
std::vector<double> vessel_speed(const core::Log& log) {
  if (log.has("u") && log.has("v")) return ident::total_speed(log.values("u"), log.values("v"));
  if (log.has("u")) return log.values("u");
  return {};
}

}  // namespace

void AgilityRequest::validate() const {
  if (!(min_response_pct >= 0.0 && min_response_pct <= 99.0)) {
    throw option_error("min_response", fmt::format("{:g} % is not in [0, 99]", min_response_pct),
                       "give the share of the channel's range in %");
  }
  if (!(min_demand_pct >= 0.0)) {
    throw option_error("min_demand", fmt::format("{:g} % is not ≥ 0", min_demand_pct),
                       "give a demand ≥ 0 %");
  }
  if (current && !(current->speed_mps >= 0.0 && std::isfinite(current->speed_mps) &&
                   std::isfinite(current->to_deg))) {
    throw option_error("current",
                       fmt::format("the speed {:g} m/s towards {:g}° is not a current",
                                   current->speed_mps, current->to_deg),
                       "give the speed ≥ 0 and the direction it flows towards");
  }
}

std::optional<double> thrust_envelope_s(const ident::AgilityStep& step) {
  std::optional<double> e;
  for (const auto& r : step.thrusters) {
    if (r.response_s) e = std::max(e.value_or(0.0), *r.response_s);
  }
  return e;
}

AgilityReport run_agility(const AgilityRequest& request) {
  request.validate();
  LoadedLog loaded = request.source.load(wanted_role);
  const core::Log& log = loaded.log;
  AgilityReport report;
  report.log = request.source.log;
  report.input = std::move(loaded.input);
  report.current = request.current;
  report.min_demand_pct = request.min_demand_pct;
  const std::vector<std::string> thrust = thruster_names(log, "thrust");
  const std::vector<std::string> rpm = thruster_names(log, "rpm");
  report.channel = (!request.use_rpm && !thrust.empty()) ? "thrust" : "rpm";
  report.thrusters = report.channel == "thrust" ? thrust : rpm;
  if (report.thrusters.empty()) {
    throw request.source.error("thrust.NAME",
                               request.use_rpm
                                   ? "no shaft speed channel (rpm.NAME) in the log"
                                   : "no thruster channel (thrust.NAME or rpm.NAME) in the log",
                               "map one per thruster, e.g. --col thrust.port=THRUST_P");
  }
  std::vector<ident::AgilityChannel> channels;
  for (const std::string& n : report.thrusters) {
    channels.push_back({n, log.values(report.channel + "." + n), std::nullopt});
  }
  const std::vector<double> speed = vessel_speed(log);
  report.has_speed = !speed.empty();
  ident::AgilityOptions options;
  options.min_response_fraction = request.min_response_pct / 100.0;
  options.min_demand_pct = request.min_demand_pct;
  report.min_response_fraction = options.min_response_fraction;
  try {
    report.result = analyse_steps(request, log, channels, speed, options);
  } catch (const core::InputError& e) {
    // Name the log, and the thruster channel by its role, in the library's message.
    const core::InputError named = request.source.in_log(e);
    if (!named.option().empty()) throw named;
    core::InputLocation where = named.where();
    for (const std::string& n : report.thrusters) {
      if (where.column_name == n) where.column_name = report.channel + "." + n;
    }
    throw core::InputError(where, named.problem(), named.hint());
  }
  report.cases = group_cases(report.result, log, request.min_demand_pct);
  return report;
}

}  // namespace dynpos::analysis
