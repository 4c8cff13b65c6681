// The units of identify vessel: thrust maps and order → shaft speed dynamics from the logs
// (vessel_units.hpp; docs/theory.md, "Vessel identification", "The units").

#include "vessel_units.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "dynpos/core/error.hpp"
#include "dynpos/ident/fopdt_fit.hpp"
#include "dynpos/ident/step_detector.hpp"
#include "dynpos/ident/thrust_map.hpp"
#include "dynpos/model/thruster.hpp"
#include "dynpos/model/tunnel_thruster.hpp"
#include "vessel_fit.hpp"

namespace dynpos::analysis::vessel_units {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
// Shaft speeds below this are left out of a thrust map (identify thrust-map's default, 3 rpm).
constexpr double kMinMapSpeedRps = 3.0 / 60.0;

std::vector<double> column(const core::Log& log, const std::string& role) {
  return log.has(role) ? log.values(role) : std::vector<double>{};
}

// One order step of a unit fitted (FOPDT (3.7), least squares) on the log and on the file's
// model's response to the same step at the log's samples.
struct StepFit {
  double time_constant = 0.0, time_constant_sigma = 0.0;
  double dead_time = 0.0, dead_time_sigma = 0.0;
  double model_time_constant = 0.0, model_dead_time = 0.0;
  double delta_n = 0.0;  // the order's step [rps]
};

using ModelResponse = std::function<model::StepResponse(double from, double to)>;

// The FOPDT fit of y over the step, or nullopt when it is no estimate (failed, no σ, δ at a
// bound).
std::optional<ident::FopdtFitResult> fopdt(const std::vector<double>& t,
                                           const std::vector<double>& y, const ident::Step& step) {
  try {
    ident::FopdtFitResult f = ident::fit_fopdt(t, y, step);
    if (f.status == ident::FitStatus::kFailed || !f.time_constant || !f.dead_time ||
        !f.time_constant->sigma || !f.dead_time->sigma ||
        ident::has_warning(f.warnings, ident::WarningCode::kDeadTimeAtBound)) {
      return std::nullopt;
    }
    return f;
  } catch (const core::InputError&) {
    return std::nullopt;  // a step too short or without samples: not an estimate
  }
}

std::optional<StepFit> fit_step(const std::vector<double>& t, const std::vector<double>& n,
                                const ident::Step& step, const ModelResponse& model_response) {
  if (!step.u_before || !step.u_after) return std::nullopt;
  const std::optional<ident::FopdtFitResult> logged = fopdt(t, n, step);
  if (!logged) return std::nullopt;
  // The file's model at the same samples: its fit sees the same window, sampling and shape, so
  // what the model lacks of the logged delay is the difference of the two fits.
  const model::StepResponse r = model_response(*step.u_before, *step.u_after);
  std::vector<double> y(t.size(), kNan);
  const auto first =
      static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), step.t_begin) - t.begin());
  for (std::size_t i = first; i < t.size() && t[i] <= step.t_end; ++i) {
    if (!core::is_missing(n[i])) y[i] = r.at(t[i] - step.t_step);
  }
  const std::optional<ident::FopdtFitResult> model = fopdt(t, y, step);
  if (!model) return std::nullopt;
  return StepFit{logged->time_constant->value,  *logged->time_constant->sigma,
                 logged->dead_time->value,      *logged->dead_time->sigma,
                 model->time_constant->value,   model->dead_time->value,
                 *step.u_after - *step.u_before};
}

// Every order step of one unit in one log.
std::vector<StepFit> step_fits(const std::vector<double>& t, const UnitColumns& u,
                               const ModelResponse& model_response) {
  std::vector<StepFit> out;
  if (u.order_rps.empty() || u.shaft_speed_rps.empty()) return out;
  std::size_t valid = 0;
  for (double v : u.order_rps) valid += core::is_missing(v) ? 0 : 1;
  if (valid < 3) return out;
  ident::StepDetectorOptions o;
  o.input_name = "command.rpm." + u.unit;
  o.jobs = 1;
  ident::StepDetection d;
  try {
    d = ident::detect_steps(t, u.order_rps, o);
  } catch (const core::InputError&) {
    return out;  // an order without enough samples: no step
  }
  for (const ident::Step& s : d.steps) {
    if (auto f = fit_step(t, u.shaft_speed_rps, s, model_response)) out.push_back(*f);
  }
  return out;
}

// What one unit's logs give: the step fits and the thrust maps, per log.
struct UnitData {
  std::vector<std::pair<std::string, StepFit>> steps;  // (log, fit)
  std::vector<Estimate> c_forward, c_reverse;          // [N/rps²]
};

void add_thrust_map(UnitData& data, const std::string& log, const UnitColumns& u) {
  if (u.shaft_speed_rps.empty() || u.thrust_N.empty()) return;
  ident::ThrustMapFitOptions o;
  o.min_abs_shaft_speed_rps = kMinMapSpeedRps;
  o.shaft_speed_name = "rpm." + u.unit;
  o.thrust_name = "thrust." + u.unit;
  const ident::ThrustMapFitResult m = ident::fit_thrust_map(u.shaft_speed_rps, u.thrust_N, o);
  if (m.status == ident::FitStatus::kFailed) return;
  // A thrust the DP system computes from the logged shaft speed by its own map is that map to
  // rounding: σ may come out 0, which would be no weight. It is taken as at least 10⁻¹² of c.
  auto add = [&](const std::optional<ident::Estimate>& c, std::vector<Estimate>& to) {
    if (c && c->sigma)
      to.push_back({c->value, std::max(*c->sigma, 1e-12 * std::abs(c->value)), log});
  };
  add(m.c_forward, data.c_forward);
  add(m.c_reverse, data.c_reverse);
}

UnitData unit_data(const std::vector<LogUnits>& logs, const std::string& unit,
                   const ModelResponse& model_response) {
  UnitData data;
  for (const LogUnits& log : logs) {
    for (const UnitColumns& u : log.units) {
      if (u.unit != unit) continue;
      for (const StepFit& f : step_fits(log.time_s, u, model_response)) {
        data.steps.emplace_back(log.name, f);
      }
      add_thrust_map(data, log.name, u);
    }
  }
  return data;
}

// A value of the file from estimates: determined when σ/|value| ≤ max_rel.
VesselParameter parameter(const std::string& key, const std::string& unit, double start,
                          const std::vector<Estimate>& estimates, const std::string& how,
                          const std::string& excitation, double max_rel) {
  VesselParameter p{key, unit, start, start, kNan, false, false, {}};
  const std::optional<Combined> c = combine(estimates);
  if (!c) {
    p.note = "the logs hold no " + how + "; to determine it: " + excitation;
    return p;
  }
  const double rel = c->sigma / std::abs(c->value);
  if (!(rel <= max_rel)) {
    p.note = fmt::format(
        "{:.3g} ± {:.2g} from {} {} is not determined (σ/|value| {:.1f} %, over {:.1f} %); "
        "to determine it: {}",
        c->value, c->sigma, c->count, how, 100.0 * rel, 100.0 * max_rel, excitation);
    return p;
  }
  p.value = c->value;
  p.sigma = c->sigma;
  p.determined = p.fitted = true;
  p.note = fmt::format("{}: {}, in {}", how, c->count, fmt::join(c->sources, ", "));
  return p;
}

// Estimates scaled by k (a thrust coefficient [N/rps²] to K_T = c/(ρD⁴)).
std::vector<Estimate> scaled(std::vector<Estimate> e, double k) {
  for (Estimate& x : e) {
    x.value *= k;
    x.sigma *= std::abs(k);
  }
  return e;
}

// Into value and σ (NaN, NaN without estimates).
void set(const std::optional<Combined>& c, double& value, double& sigma) {
  value = c ? c->value : kNan;
  sigma = c ? c->sigma : kNan;
}

UnitIdentification dynamics(const std::string& unit, const UnitData& d) {
  UnitIdentification u;
  u.unit = unit;
  u.steps = d.steps.size();
  std::vector<Estimate> t, dt, tm, dm;
  for (const auto& [log, f] : d.steps) {
    t.push_back({f.time_constant, f.time_constant_sigma, log});
    dt.push_back({f.dead_time, f.dead_time_sigma, log});
    // The model's values are exact; weighted like the logged ones, for the same mean.
    tm.push_back({f.model_time_constant, f.time_constant_sigma, log});
    dm.push_back({f.model_dead_time, f.dead_time_sigma, log});
  }
  double ignored = 0.0;
  set(combine(t), u.time_constant_s, u.time_constant_sigma_s);
  set(combine(dt), u.dead_time_s, u.dead_time_sigma_s);
  set(combine(tm), u.model_time_constant_s, ignored);
  set(combine(dm), u.model_dead_time_s, ignored);
  set(combine(d.c_forward), u.c_forward, u.c_forward_sigma);
  set(combine(d.c_reverse), u.c_reverse, u.c_reverse_sigma);
  return u;
}

constexpr const char* kStepsHow = "order steps (FOPDT fits of command.rpm → rpm)";
constexpr const char* kMapHow = "thrust maps (3.17) of logged rpm and thrust";

// The [propeller] values from the port and stb units.
void propellers(const scenario::VesselConfig& start, const std::vector<LogUnits>& logs,
                double max_rel, UnitResult& out) {
  const model::ThrusterParams& p = start.propeller;
  const model::Thruster thruster(p);
  const ModelResponse response = [&](double from, double to) {
    return model::thruster_step_response(thruster, from, to).shaft_speed;
  };
  UnitData both;
  for (const char* unit : {"port", "stb"}) {
    UnitData d = unit_data(logs, unit, response);
    out.units.push_back(dynamics(unit, d));
    both.steps.insert(both.steps.end(), d.steps.begin(), d.steps.end());
    both.c_forward.insert(both.c_forward.end(), d.c_forward.begin(), d.c_forward.end());
    both.c_reverse.insert(both.c_reverse.end(), d.c_reverse.begin(), d.c_reverse.end());
  }
  // The dead time shifts the response alone: the file's plus what its model lacks of the delay.
  std::vector<Estimate> dead;
  for (const auto& [log, f] : both.steps) {
    dead.push_back({p.dead_time + f.dead_time - f.model_dead_time, f.dead_time_sigma, log});
  }
  out.parameters.push_back(parameter(
      "propeller.dead_time_s", "s", p.dead_time, dead, kStepsHow,
      "steps of the main propellers' shaft speed order (surge steps) with rpm logged at 10 Hz "
      "or more",
      max_rel));
  const double to_kt = 1.0 / (p.rho * std::pow(p.diameter, 4));
  out.parameters.push_back(
      parameter("propeller.kt_forward", "1", p.kt_forward, scaled(both.c_forward, to_kt), kMapHow,
                "rpm.port/stb and thrust.port/stb logged running ahead", max_rel));
  out.parameters.push_back(
      parameter("propeller.kt_reverse", "1", p.kt_reverse, scaled(both.c_reverse, -to_kt), kMapHow,
                "rpm.port/stb and thrust.port/stb logged running astern", max_rel));
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
  const UnitData d = unit_data(logs, "tunnel", response);
  out.units.push_back(dynamics("tunnel", d));
  std::vector<Estimate> dead, time_constant;
  for (const auto& [log, f] : d.steps) {
    dead.push_back({p.dead_time + f.dead_time - f.model_dead_time, f.dead_time_sigma, log});
    // ṅ = sat_r((n_c − n)/T_n): a first-order step below the rate limit, whose T is T_n.
    if (std::abs(f.delta_n) <= p.rate_limit * p.time_constant) {
      time_constant.push_back(
          {p.time_constant + f.time_constant - f.model_time_constant, f.time_constant_sigma, log});
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
  const double to_kt = 1.0 / (p.rho * std::pow(p.diameter, 4));
  out.parameters.push_back(
      parameter("tunnel.kt_starboard", "1", p.kt_starboard, scaled(d.c_forward, to_kt), kMapHow,
                "rpm.tunnel and thrust.tunnel logged pushing to starboard", max_rel));
  out.parameters.push_back(parameter("tunnel.kt_port", "1", p.kt_port, scaled(d.c_reverse, -to_kt),
                                     kMapHow, "rpm.tunnel and thrust.tunnel logged pushing to port",
                                     max_rel));
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
    out.units.push_back(
        {u, column(log, "rpm." + u), column(log, "command.rpm." + u), column(log, "thrust." + u)});
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
                          double max_rel_sigma) {
  UnitResult out;
  if (!start.thrusters.empty()) return out;
  propellers(start, logs, max_rel_sigma, out);
  tunnel(start, logs, max_rel_sigma, out);
  return out;
}

void apply(scenario::VesselConfig& config, const std::vector<VesselParameter>& parameters) {
  for (const VesselParameter& p : parameters) {
    if (!p.determined) continue;
    if (double* f = vessel_fit::field(config, p.key)) *f = p.value;  // the units' keys are SI
  }
}

}  // namespace dynpos::analysis::vessel_units
