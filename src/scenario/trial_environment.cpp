#include "dynpos/scenario/trial_environment.hpp"

#include <cmath>

#include "dynpos/core/angle.hpp"
#include "dynpos/scenario/vessel_plant.hpp"

namespace dynpos::scenario {
namespace {

model::CurrentParams current_params(const EnvironmentSpec& env, const VesselConfig& vessel) {
  model::CurrentParams p = vessel.current;
  p.speed_mps = env.current_speed_mps;
  p.to_rad = core::deg_to_rad(env.current_to_deg);
  return p;
}

model::WindParams wind_params(const EnvironmentSpec& env, const VesselConfig& vessel) {
  model::WindParams p = vessel.wind;
  p.speed_mps = env.wind_speed_mps;
  p.from_rad = core::deg_to_rad(env.wind_from_deg);
  return p;
}

std::vector<model::StepLoad> step_loads(const std::vector<LoadEvent>& events) {
  std::vector<model::StepLoad> loads;
  for (const LoadEvent& e : events) {
    loads.push_back({e.t_on_s, e.t_off_s, Eigen::Vector3d(e.north_N, e.east_N, e.yaw_Nm)});
  }
  return loads;
}

}  // namespace

model::SeaStateParams sea_state(const EnvironmentSpec& env) {
  model::SeaStateParams sea;
  sea.hs_m = env.hs_m;
  sea.tp_s = env.tp_s;
  sea.from_rad = core::deg_to_rad(env.wave_from_deg);
  sea.components = env.wave_components;
  return sea;
}

TrialEnvironment::TrialEnvironment(const ScenarioSpec& spec, const VesselConfig& vessel,
                                   std::uint64_t seed, const TrialClock& clock)
    : clock_(clock),
      current_(current_params(spec.environment, vessel), seed, spec.dt_s),
      wind_(wind_params(spec.environment, vessel), seed, spec.dt_s),
      bias_(model::bias_for_sea_state(vessel.bias, spec.environment.hs_m), seed, spec.dt_s),
      waves_(sea_state(spec.environment), vessel.waves, seed, clock.log_period_s()),
      loads_(step_loads(spec.loads)) {}

void TrialEnvironment::step(sim::Tick k, const sim::ConstVectorRef& x, sim::VectorRef u) {
  using Plant = VesselPlant;
  using model::Hull;
  current_.step();
  wind_.step();
  bias_.step();
  if (clock_.logs_at(k)) {
    if (waves_sampled_) waves_.advance();  // the generator starts at the first logged sample
    waves_sampled_ = true;
  }
  const double psi = x[Plant::kHull + Hull::kYaw];
  const double cs = std::cos(psi), sn = std::sin(psi);
  const double uu = x[Plant::kHull + Hull::kSurge], vv = x[Plant::kHull + Hull::kSway];
  const Eigen::Vector2d velocity_n(cs * uu - sn * vv, sn * uu + cs * vv);
  u.segment<3>(Plant::kTauEnvBody) = wind_.force_b(psi, velocity_n) + waves_.drift_force_b(psi);
  u.segment<3>(Plant::kForceNed) = bias_.value_n() + load_n(clock_.time(k));
  u.segment<2>(Plant::kCurrentNed) = current_.velocity_n();
}

}  // namespace dynpos::scenario
