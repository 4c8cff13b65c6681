#include "dynpos/scenario/load_response.hpp"

#include <cmath>
#include <stdexcept>

#include "dynpos/core/error.hpp"

namespace dynpos::scenario {

LoadResponse evaluate_load_response(const core::Log& log, double t_load_s, double within_m) {
  if (!(within_m > 0.0)) throw std::invalid_argument("evaluate_load_response: within_m > 0");
  for (const char* name : {"north", "east", "setpoint.north", "setpoint.east", "power.port",
                           "power.stb", "power.tunnel"}) {
    if (!log.has(name)) {
      throw std::invalid_argument(std::string("evaluate_load_response: no channel ") + name);
    }
  }
  const auto& t = log.time();
  if (t.empty() || !(t_load_s >= t.front() && t_load_s < t.back())) {
    throw std::invalid_argument("evaluate_load_response: the load time is outside the log");
  }
  const auto& n = log.values("north");
  const auto& e = log.values("east");
  const auto& sn = log.values("setpoint.north");
  const auto& se = log.values("setpoint.east");
  const auto& pp = log.values("power.port");
  const auto& ps = log.values("power.stb");
  const auto& pt = log.values("power.tunnel");
  LoadResponse r;
  r.t_load_s = t_load_s;
  r.within_m = within_m;
  r.duration_s = t.back() - t_load_s;
  std::optional<double> last_outside;
  double prev_t = 0.0, prev_d = 0.0, prev_p = 0.0;
  bool first = true;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] < t_load_s) continue;
    const double d = std::hypot(n[i] - sn[i], e[i] - se[i]);  // NaN outside DP: skipped below
    const double p = pp[i] + ps[i] + pt[i];
    if (std::isnan(d)) continue;
    r.peak_offset_m = std::max(r.peak_offset_m, d);
    if (d > within_m) last_outside = t[i];
    if (!first) {
      const double dt = t[i] - prev_t;  // trapezoids over the samples
      r.iae_m_s += 0.5 * dt * (d + prev_d);
      r.energy_kJ += 0.5 * dt * (p + prev_p) / 1e3;
    }
    prev_t = t[i];
    prev_d = d;
    prev_p = p;
    first = false;
  }
  if (!last_outside) {
    r.back_within_s = 0.0;
  } else if (*last_outside < t.back()) {
    r.back_within_s = *last_outside - t_load_s;
  }
  return r;
}

double first_load_change_s(const ScenarioSpec& spec) {
  if (spec.loads.empty()) {
    throw core::InputError({spec.source, {}, {}, "load"}, "the scenario has no [[load]]",
                           "a sudden-load comparison needs a load that sets in or is released");
  }
  const LoadEvent& e = spec.loads.front();
  return e.t_on_s > 0.0 ? e.t_on_s : e.t_off_s;
}

HybridComparison compare_integral_action(const ScenarioSpec& spec, const VesselConfig& vessel,
                                         std::uint64_t seed, double within_m) {
  HybridComparison c;
  c.t_load_s = first_load_change_s(spec);
  ScenarioSpec conventional = spec;
  conventional.hybrid_integral.reset();
  ScenarioSpec with_jumps = spec;
  if (!with_jumps.hybrid_integral) with_jumps.hybrid_integral = hybrid::IntegralJumpParams{};
  const auto run = [&](const ScenarioSpec& s) {
    DesignRun d{run_scenario(s, vessel, seed), {}, 0};
    d.response = evaluate_load_response(d.run.truth_log, c.t_load_s, within_m);
    if (d.run.truth.hybrid) d.jumps = d.run.truth.hybrid->jump_times_s.size();
    return d;
  };
  c.conventional = run(conventional);
  c.hybrid = run(with_jumps);
  return c;
}

}  // namespace dynpos::scenario
