// The order steps of a unit in the logs of identify vessel (vessel_unit_steps.hpp).

#include "vessel_unit_steps.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "dynpos/core/error.hpp"
#include "dynpos/ident/fopdt_fit.hpp"
#include "dynpos/ident/thrust_map.hpp"

namespace dynpos::analysis::vessel_units {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
// Shaft speeds below this are left out of a thrust map (identify thrust-map's default, 3 rpm).
constexpr double kMinMapSpeedRps = 3.0 / 60.0;

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

// The order steps of one unit in one log.
std::vector<ident::Step> order_steps(const std::vector<double>& t, const UnitColumns& u) {
  if (u.order_rps.empty() || u.shaft_speed_rps.empty()) return {};
  std::size_t valid = 0;
  for (double v : u.order_rps) valid += core::is_missing(v) ? 0 : 1;
  if (valid < 3) return {};
  ident::StepDetectorOptions o;
  o.input_name = "command.rpm." + u.unit;
  o.jobs = 1;
  try {
    return ident::detect_steps(t, u.order_rps, o).steps;
  } catch (const core::InputError&) {
    return {};  // an order without enough samples: no step
  }
}

}  // namespace

std::vector<LoggedStep> logged_steps(const std::vector<LogUnits>& logs, const std::string& unit) {
  std::vector<LoggedStep> out;
  for (const LogUnits& log : logs) {
    for (const UnitColumns& u : log.units) {
      if (u.unit != unit) continue;
      for (const ident::Step& s : order_steps(log.time_s, u)) {
        if (!s.u_before || !s.u_after) continue;
        const std::optional<ident::FopdtFitResult> f = fopdt(log.time_s, u.shaft_speed_rps, s);
        if (!f) continue;
        out.push_back({&log, &u, s, f->time_constant->value, *f->time_constant->sigma,
                       f->dead_time->value, *f->dead_time->sigma});
      }
    }
  }
  return out;
}

ModelSamples ideal_step(ModelResponse response) {
  return [response = std::move(response)](const LoggedStep& s) {
    const std::vector<double>& t = s.log->time_s;
    const std::vector<double>& n = s.unit->shaft_speed_rps;
    const model::StepResponse r = response(*s.step.u_before, *s.step.u_after);
    std::vector<double> y(t.size(), kNan);
    const auto first =
        static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), s.step.t_begin) - t.begin());
    for (std::size_t i = first; i < t.size() && t[i] <= s.step.t_end; ++i) {
      if (!core::is_missing(n[i])) y[i] = r.at(t[i] - s.step.t_step);
    }
    return y;
  };
}

std::vector<StepFit> with_model(const std::vector<LoggedStep>& steps, const ModelSamples& model) {
  std::vector<StepFit> out;
  for (const LoggedStep& s : steps) {
    const std::optional<ident::FopdtFitResult> f = fopdt(s.log->time_s, model(s), s.step);
    if (f) out.push_back({&s, {f->time_constant->value, f->dead_time->value}});
  }
  return out;
}

MapEstimates thrust_maps(const std::vector<LogUnits>& logs, const std::string& unit) {
  MapEstimates out;
  for (const LogUnits& log : logs) {
    for (const UnitColumns& u : log.units) {
      if (u.unit != unit || u.shaft_speed_rps.empty() || u.thrust_N.empty()) continue;
      ident::ThrustMapFitOptions o;
      o.min_abs_shaft_speed_rps = kMinMapSpeedRps;
      o.shaft_speed_name = "rpm." + u.unit;
      o.thrust_name = "thrust." + u.unit;
      const ident::ThrustMapFitResult m = ident::fit_thrust_map(u.shaft_speed_rps, u.thrust_N, o);
      if (m.status == ident::FitStatus::kFailed) continue;
      // A thrust the DP system computes from the logged shaft speed by its own map is that map
      // to rounding: σ may come out 0, which would be no weight. It is taken as at least 10⁻¹²
      // of c.
      auto add = [&](const std::optional<ident::Estimate>& c, std::vector<Estimate>& to) {
        if (c && c->sigma)
          to.push_back({c->value, std::max(*c->sigma, 1e-12 * std::abs(c->value)), log.name});
      };
      add(m.c_forward, out.c_forward);
      add(m.c_reverse, out.c_reverse);
    }
  }
  return out;
}

UnitIdentification dynamics(const std::string& unit, const std::vector<StepFit>& fits,
                            const MapEstimates& maps) {
  UnitIdentification u;
  u.unit = unit;
  u.steps = fits.size();
  u.slew_rate_deg_per_s = u.slew_rate_sigma_deg_per_s = kNan;
  std::vector<Estimate> t, dt, tm, dm;
  for (const StepFit& f : fits) {
    const LoggedStep& s = *f.logged;
    t.push_back({s.time_constant_s, s.time_constant_sigma_s, s.log->name});
    dt.push_back({s.dead_time_s, s.dead_time_sigma_s, s.log->name});
    // The model's values are exact; weighted like the logged ones, for the same mean.
    tm.push_back({f.model.time_constant_s, s.time_constant_sigma_s, s.log->name});
    dm.push_back({f.model.dead_time_s, s.dead_time_sigma_s, s.log->name});
  }
  double ignored = 0.0;
  set(combine(t), u.time_constant_s, u.time_constant_sigma_s);
  set(combine(dt), u.dead_time_s, u.dead_time_sigma_s);
  set(combine(tm), u.model_time_constant_s, ignored);
  set(combine(dm), u.model_dead_time_s, ignored);
  set(combine(maps.c_forward), u.c_forward, u.c_forward_sigma);
  set(combine(maps.c_reverse), u.c_reverse, u.c_reverse_sigma);
  return u;
}

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

void set(const std::optional<Combined>& c, double& value, double& sigma) {
  value = c ? c->value : kNan;
  sigma = c ? c->sigma : kNan;
}

}  // namespace dynpos::analysis::vessel_units
