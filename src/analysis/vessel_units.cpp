// The units of identify vessel: thrust maps and order → shaft speed dynamics from the logs
// (vessel_units.hpp; docs/theory.md, "Vessel identification", "The units").

#include "vessel_units.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>

#include "dynpos/core/error.hpp"
#include "dynpos/ident/fopdt_fit.hpp"
#include "dynpos/ident/step_detector.hpp"
#include "dynpos/ident/thrust_map.hpp"
#include "dynpos/model/thruster.hpp"
#include "dynpos/model/tunnel_thruster.hpp"
#include "vessel_fit.hpp"
#include "vessel_layout_units.hpp"
#include "vessel_unit_steps.hpp"

namespace dynpos::analysis::vessel_units {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

std::vector<double> column(const core::Log& log, const std::string& role) {
  return log.has(role) ? log.values(role) : std::vector<double>{};
}

// Estimates scaled by k (a thrust coefficient [N/rps²] to K_T = c/(ρD⁴)).
std::vector<Estimate> scaled(std::vector<Estimate> e, double k) {
  for (Estimate& x : e) {
    x.value *= k;
    x.sigma *= std::abs(k);
  }
  return e;
}

constexpr const char* kStepsHow = "order steps (FOPDT fits of command.rpm → rpm)";
constexpr const char* kMapHow = "thrust maps (3.17) of logged rpm and thrust";

// The K_T of a unit's two directions (keys TABLE.kt_FORWARD and TABLE.kt_REVERSE) from the
// thrust coefficients of its maps, c = ρD⁴K_T; `logged` names what the logs must hold for each.
void add_thrust_map(UnitResult& out, const std::string& table, double rho_kg_m3, double diameter_m,
                    const MapEstimates& maps,
                    const std::array<std::pair<const char*, double>, 2>& kt,
                    const std::array<const char*, 2>& logged, double max_rel) {
  const double to_kt = 1.0 / (rho_kg_m3 * std::pow(diameter_m, 4));
  out.parameters.push_back(parameter(table + ".kt_" + kt[0].first, "1", kt[0].second,
                                     scaled(maps.c_forward, to_kt), kMapHow, logged[0], max_rel));
  out.parameters.push_back(parameter(table + ".kt_" + kt[1].first, "1", kt[1].second,
                                     scaled(maps.c_reverse, -to_kt), kMapHow, logged[1], max_rel));
}

// The [propeller] values from the port and stb units.
void propellers(const scenario::VesselConfig& start, const std::vector<LogUnits>& logs,
                double max_rel, UnitResult& out) {
  const model::ThrusterParams& p = start.propeller;
  const model::Thruster thruster(p);
  const ModelResponse response = [&](double from, double to) {
    return model::thruster_step_response(thruster, from, to).shaft_speed;
  };
  std::vector<LoggedStep> logged[2];
  std::vector<StepFit> both;
  MapEstimates maps;
  const char* names[2] = {"port", "stb"};
  for (std::size_t k = 0; k < 2; ++k) {
    logged[k] = logged_steps(logs, names[k]);
    const std::vector<StepFit> fits = with_model(logged[k], ideal_step(response));
    const MapEstimates m = thrust_maps(logs, names[k]);
    out.units.push_back(dynamics(names[k], fits, m));
    both.insert(both.end(), fits.begin(), fits.end());
    maps.c_forward.insert(maps.c_forward.end(), m.c_forward.begin(), m.c_forward.end());
    maps.c_reverse.insert(maps.c_reverse.end(), m.c_reverse.begin(), m.c_reverse.end());
  }
  // The dead time shifts the response alone: the file's plus what its model lacks of the delay.
  std::vector<Estimate> dead;
  for (const StepFit& f : both) {
    dead.push_back({p.dead_time + f.logged->dead_time_s - f.model.dead_time_s,
                    f.logged->dead_time_sigma_s, f.logged->log->name});
  }
  out.parameters.push_back(parameter(
      "propeller.dead_time_s", "s", p.dead_time, dead, kStepsHow,
      "steps of the main propellers' shaft speed order (surge steps) with rpm logged at 10 Hz "
      "or more",
      max_rel));
  add_thrust_map(out, "propeller", p.rho, p.diameter, maps,
                 {{{"forward", p.kt_forward}, {"reverse", p.kt_reverse}}},
                 {"rpm.port/stb and thrust.port/stb logged running ahead",
                  "rpm.port/stb and thrust.port/stb logged running astern"},
                 max_rel);
  const char* chain =
      "one order step gives one time constant for the chain of reference rate limit, reference "
      "filter, speed loop and motor (its T is reported against the file's model's); to "
      "determine it: the shaft's reference and motor torque logged through steps of several "
      "sizes";
  const std::pair<const char*, double> kept[] = {
      {"propeller.ref_rate_limit_rps_per_s", p.ref_rate_limit},
      {"propeller.ref_time_constant_s", p.ref_time_constant},
      {"propeller.motor_time_constant_s", p.motor_time_constant}};
  const char* units[] = {"rps/s", "s", "s"};
  for (std::size_t k = 0; k < 3; ++k) {
    out.parameters.push_back(
        {kept[k].first, units[k], kept[k].second, kept[k].second, kNan, false, false, chain});
  }
}

// The [tunnel] values from the tunnel unit.
void tunnel(const scenario::VesselConfig& start, const std::vector<LogUnits>& logs, double max_rel,
            UnitResult& out) {
  const model::TunnelThrusterParams& p = start.tunnel;
  const model::TunnelThruster thruster(p);
  const ModelResponse response = [&](double from, double to) {
    return model::tunnel_step_response(thruster, from, to);
  };
  const std::vector<LoggedStep> logged = logged_steps(logs, "tunnel");
  const std::vector<StepFit> fits = with_model(logged, ideal_step(response));
  const MapEstimates maps = thrust_maps(logs, "tunnel");
  out.units.push_back(dynamics("tunnel", fits, maps));
  std::vector<Estimate> dead, time_constant;
  for (const StepFit& f : fits) {
    const LoggedStep& s = *f.logged;
    dead.push_back(
        {p.dead_time + s.dead_time_s - f.model.dead_time_s, s.dead_time_sigma_s, s.log->name});
    // ṅ = sat_r((n_c − n)/T_n): a first-order step below the rate limit, whose T is T_n.
    if (std::abs(s.delta_n_rps()) <= p.rate_limit * p.time_constant) {
      time_constant.push_back({p.time_constant + s.time_constant_s - f.model.time_constant_s,
                               s.time_constant_sigma_s, s.log->name});
    }
  }
  const char* excitation =
      "steps of the tunnel's order (sway steps) with its rpm logged at 10 Hz or more";
  out.parameters.push_back(
      parameter("tunnel.dead_time_s", "s", p.dead_time, dead, kStepsHow, excitation, max_rel));
  out.parameters.push_back(
      parameter("tunnel.time_constant_s", "s", p.time_constant, time_constant,
                "order steps under the rate limit (FOPDT fits of command.rpm → rpm)",
                fmt::format("{}, each under {:.0f} rpm (the rate limit over T_n)", excitation,
                            60.0 * p.rate_limit * p.time_constant),
                max_rel));
  add_thrust_map(out, "tunnel", p.rho, p.diameter, maps,
                 {{{"starboard", p.kt_starboard}, {"port", p.kt_port}}},
                 {"rpm.tunnel and thrust.tunnel logged pushing to starboard",
                  "rpm.tunnel and thrust.tunnel logged pushing to port"},
                 max_rel);
  out.parameters.push_back(
      {"tunnel.rate_limit_rps_per_s", "rps/s", p.rate_limit, p.rate_limit, kNan, false, false,
       fmt::format("not fitted; to determine it: tunnel order steps over {:.0f} rpm with its rpm "
                   "logged at 10 Hz or more",
                   60.0 * p.rate_limit * p.time_constant)});
}

}  // namespace

LogUnits log_units(const std::string& name, const core::Log& log,
                   const std::vector<std::string>& units) {
  LogUnits out{name, log.time(), {}};
  for (const std::string& u : units) {
    out.units.push_back({u, column(log, "rpm." + u), column(log, "command.rpm." + u),
                         column(log, "thrust." + u), column(log, "azimuth." + u),
                         column(log, "command.azimuth." + u)});
  }
  return out;
}

std::optional<Combined> combine(const std::vector<Estimate>& estimates) {
  double sw = 0.0, swx = 0.0;
  Combined c;
  for (const Estimate& e : estimates) {
    if (!(e.sigma > 0.0) || !std::isfinite(e.sigma) || !std::isfinite(e.value)) continue;
    const double w = 1.0 / (e.sigma * e.sigma);
    sw += w;
    swx += w * e.value;
    ++c.count;
    if (std::find(c.sources.begin(), c.sources.end(), e.source) == c.sources.end()) {
      c.sources.push_back(e.source);
    }
  }
  if (c.count == 0) return std::nullopt;
  c.value = swx / sw;
  c.sigma = 1.0 / std::sqrt(sw);
  if (c.count > 1) {
    double chi2 = 0.0;
    for (const Estimate& e : estimates) {
      if (!(e.sigma > 0.0) || !std::isfinite(e.sigma) || !std::isfinite(e.value)) continue;
      chi2 += std::pow((e.value - c.value) / e.sigma, 2);
    }
    c.sigma *= std::max(1.0, std::sqrt(chi2 / static_cast<double>(c.count - 1)));
  }
  return c;
}

UnitResult identify_units(const scenario::VesselConfig& start, const std::vector<LogUnits>& logs,
                          double max_rel_sigma, unsigned jobs) {
  UnitResult out;
  if (!start.thrusters.empty()) {
    layout_units(start, logs, max_rel_sigma, jobs, out);
    return out;
  }
  propellers(start, logs, max_rel_sigma, out);
  tunnel(start, logs, max_rel_sigma, out);
  return out;
}

void apply(scenario::VesselConfig& config, const std::vector<VesselParameter>& parameters) {
  for (const VesselParameter& p : parameters) {
    if (!p.determined) continue;
    if (double* f = vessel_fit::field(config, p.key)) *f = p.value;  // the units' keys are SI
    apply_layout(config, p);
  }
}

}  // namespace dynpos::analysis::vessel_units
