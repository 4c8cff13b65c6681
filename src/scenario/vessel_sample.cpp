#include "dynpos/scenario/vessel_sample.hpp"

#include <cmath>

#include "dynpos/core/angle.hpp"
#include "vessel_motion.hpp"

namespace dynpos::scenario {

VesselSampler::VesselSampler(const VesselPlant& plant, const TrialEnvironment& environment)
    : plant_(plant), environment_(environment), dxdt_(plant.state_size()) {}

const VesselSample& VesselSampler::sample(double t, const sim::ConstVectorRef& x,
                                          const sim::ConstVectorRef& u) {
  using Plant = VesselPlant;
  using model::Hull;
  VesselSample& s = sample_;
  s.current_n = u.segment<2>(Plant::kCurrentNed);
  const ActuatorState a = plant_.actuators(x, s.current_n);
  plant_.flow(t, x, u, dxdt_);
  const model::WaveMotion6 wf =
      environment_.waves().motion(x[Plant::kHull + Hull::kYaw], dxdt_[Plant::kHull + Hull::kYaw],
                                  dxdt_[Plant::kHull + Hull::kYawRate]);
  s.motion =
      detail::compose_motion(x.segment<10>(Plant::kHull), dxdt_.segment<10>(Plant::kHull), wf);
  s.eta_lf_n = x.segment<3>(Plant::kHull + Hull::kNorth);
  s.shaft_speed_rps = {a.port.shaft_speed, a.stb.shaft_speed, a.tunnel.shaft_speed};
  s.thrust_N = {a.port.thrust, a.stb.thrust, a.tunnel.thrust};
  s.power_W = {a.port.power, a.stb.power, a.tunnel.power};
  s.units = a.units;
  if (!s.units.empty()) {
    s.rudder_rad = {0.0, 0.0};
  } else {
    s.rudder_rad = {x[Plant::kRudderPort], x[Plant::kRudderStb]};
  }
  s.wind_speed_mps = environment_.wind().speed_mps();
  s.wind_from_rad = core::wrap_2pi(environment_.wind().from_rad());
  s.load_n = environment_.load_n(t);
  const double psi = x[Plant::kHull + Hull::kYaw];
  const double c = std::cos(psi), sn = std::sin(psi);
  const Eigen::Vector3d current_b(c * s.current_n.x() + sn * s.current_n.y(),
                                  -sn * s.current_n.x() + c * s.current_n.y(), 0.0);
  const Eigen::Vector3d env_b =
      u.segment<3>(Plant::kTauEnvBody) +
      plant_.hull().hydrodynamic_forces(Eigen::Vector3d::Zero(), -current_b);
  s.env_load_n =
      u.segment<3>(Plant::kForceNed) +
      Eigen::Vector3d(c * env_b.x() - sn * env_b.y(), sn * env_b.x() + c * env_b.y(), env_b.z());
  return s;
}

}  // namespace dynpos::scenario
