#include "dynpos/scenario/vessel_plant.hpp"

#include <fmt/format.h>

#include <cmath>

#include "dynpos/core/error.hpp"
#include "dynpos/model/model_unit_forces.hpp"
#include "dynpos/scenario/unit_failure.hpp"

namespace dynpos::scenario {

void check_simulated(const VesselConfig& vessel, const ScenarioSpec& spec, const char* key) {
  if (spec.failure) {
    try {
      (void)UnitFailure(*spec.failure, vessel);
    } catch (const core::InputError& e) {
      throw core::InputError({spec.source, {}, {}, "failure"}, e.problem(), e.hint());
    }
  }
  if (vessel.thrusters.empty() || spec.rudder.empty()) return;
  throw core::InputError::for_option(
      key,
      fmt::format("the scenario '{}' steps the model's two rudders by hand, and {} has a "
                  "[[thruster]] layout of {} units instead",
                  spec.name, vessel.source.empty() ? vessel.name : vessel.source,
                  vessel.thrusters.size()),
      "run a scenario without [[rudder]] steps (pure DP, the DP 4-corner, joystick steps), or "
      "a vessel file without [[thruster]] tables");
}

VesselPlant::VesselPlant(const VesselConfig& config)
    : hull_(config.hull),
      propeller_(config.propeller),
      rudder_(config.rudder),
      tunnel_(config.tunnel),
      layout_(config.layout),
      capacity_(config.thruster_capacity) {
  for (const model::ThrusterUnit& unit : config.thrusters) drives_.emplace_back(unit);
  if (capacity_.empty()) capacity_.assign(drives_.size(), 1.0);
}

Eigen::Vector3d VesselPlant::layout_tau_b(const sim::ConstVectorRef& x) const {
  Eigen::Vector3d tau_b = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < drives_.size(); ++k) {
    const Eigen::Index i = kUnits + 2 * static_cast<Eigen::Index>(k);
    tau_b += drives_[k].outputs(x[i], x[i + 1], capacity_[k]).tau_b;
  }
  return tau_b;
}

ActuatorState VesselPlant::actuators(const sim::ConstVectorRef& x,
                                     const Eigen::Vector2d& current_n) const {
  const double psi = x[kHull + model::Hull::kYaw];
  return actuators(x, current_n, std::cos(psi), std::sin(psi));
}

ActuatorState VesselPlant::actuators(const sim::ConstVectorRef& x, const Eigen::Vector2d& current_n,
                                     double c, double s) const {
  ActuatorState a;
  if (!drives_.empty()) {
    for (std::size_t k = 0; k < drives_.size(); ++k) {
      const Eigen::Index i = kUnits + 2 * static_cast<Eigen::Index>(k);
      a.units.push_back(drives_[k].outputs(x[i], x[i + 1], capacity_[k]));
      a.tau_b += a.units.back().tau_b;
    }
    return a;
  }
  // Velocity through the water in BODY, ν_r = ν − R(ψ)ᵀ v_c.
  const Eigen::Vector3d nu_r(
      x[kHull + model::Hull::kSurge] - (c * current_n.x() + s * current_n.y()),
      x[kHull + model::Hull::kSway] - (-s * current_n.x() + c * current_n.y()),
      x[kHull + model::Hull::kYawRate]);
  const model::Thruster::State port = x.segment<4>(kPort);
  const model::Thruster::State stb = x.segment<4>(kStb);
  a.port = propeller_.outputs(port, nu_r.x());
  a.stb = propeller_.outputs(stb, nu_r.x());
  a.tunnel = tunnel_.outputs(x[kTunnel], nu_r.x());
  const model::ModelUnitForces f = model::model_unit_forces(
      rudder_, layout_,
      {a.port.thrust, a.stb.thrust, x[kRudderPort], x[kRudderStb], a.tunnel.thrust}, nu_r);
  a.rudder_port = f.rudder_port;
  a.rudder_stb = f.rudder_stb;
  a.tau_b = f.tau_b;
  return a;
}

void VesselPlant::flow(double /*t*/, const sim::ConstVectorRef& x, const sim::ConstVectorRef& u,
                       sim::VectorRef dxdt) const {
  const Eigen::Vector2d current_n = u.segment<2>(kCurrentNed);
  const double psi = x[kHull + model::Hull::kYaw];
  const double c = std::cos(psi), s = std::sin(psi);
  const Eigen::Vector3d f_n = u.segment<3>(kForceNed);
  // NED force into BODY: R(ψ)ᵀ b, as in (2.21).
  const Eigen::Vector3d f_b(c * f_n.x() + s * f_n.y(), -s * f_n.x() + c * f_n.y(), f_n.z());
  const model::Hull::State hull_x = x.segment<10>(kHull);
  if (!drives_.empty()) {
    const Eigen::Vector3d tau_b = layout_tau_b(x) + u.segment<3>(kTauEnvBody) + f_b;
    dxdt.segment<10>(kHull) = hull_.derivatives(hull_x, tau_b, current_n);
    for (std::size_t k = 0; k < drives_.size(); ++k) {
      const Eigen::Index i = kUnits + 2 * static_cast<Eigen::Index>(k);
      const Eigen::Index j = kCmdUnits + 2 * static_cast<Eigen::Index>(k);
      dxdt[i] = drives_[k].shaft_acceleration(x[i], u[j]);
      dxdt[i + 1] = drives_[k].angle_rate(x[i + 1], u[j + 1]);
    }
    return;
  }
  const ActuatorState a = actuators(x, current_n, c, s);
  const Eigen::Vector3d tau_b = a.tau_b + u.segment<3>(kTauEnvBody) + f_b;
  dxdt.segment<10>(kHull) = hull_.derivatives(hull_x, tau_b, current_n);
  const double u_r = x[kHull + model::Hull::kSurge] - (c * current_n.x() + s * current_n.y());
  dxdt.segment<4>(kPort) = propeller_.derivatives(x.segment<4>(kPort), {u[kCmdPort], u_r});
  dxdt.segment<4>(kStb) = propeller_.derivatives(x.segment<4>(kStb), {u[kCmdStb], u_r});
  dxdt[kRudderPort] = rudder_.angle_rate(x[kRudderPort], u[kCmdRudderPort]);
  dxdt[kRudderStb] = rudder_.angle_rate(x[kRudderStb], u[kCmdRudderStb]);
  dxdt[kTunnel] = tunnel_.shaft_acceleration(x[kTunnel], u[kCmdTunnel]);
}

Eigen::VectorXd VesselPlant::initial_state(double heading_rad) const {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(state_size());
  x[kHull + model::Hull::kYaw] = heading_rad;
  if (!drives_.empty()) return x;  // shafts at rest, steering ahead
  x.segment<4>(kPort) = propeller_.steady_state(0.0);
  x.segment<4>(kStb) = propeller_.steady_state(0.0);
  return x;
}

}  // namespace dynpos::scenario
