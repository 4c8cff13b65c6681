#include "dynpos/scenario/control_task.hpp"

#include <cmath>
#include <tuple>

#include "dynpos/core/angle.hpp"
#include "dynpos/core/log.hpp"
#include "dynpos/model/thruster.hpp"
#include "dynpos/scenario/joystick_lever.hpp"

namespace dynpos::scenario {
namespace {

using Plant = VesselPlant;
using model::Hull;

// Auto heading holding ψ(0), gains from the joystick's ω and ζ and the hull's yaw inertia.
control::HeadingHoldParams heading_hold_params(const ScenarioSpec& spec,
                                               const VesselConfig& vessel) {
  const JoystickParams& js = vessel.joystick;
  control::HeadingHoldParams p;
  p.inertia_kgm2 = vessel.hull.iz_kgm2 + vessel.hull.n_rdot_kgm2;
  p.yaw_damping_Nms = vessel.hull.n_r_Nms;
  p.omega_rad_s = js.heading_hold_omega_rad_s;
  p.zeta = js.heading_hold_zeta;
  p.max_yaw_Nm = js.max_yaw_Nm;
  p.rate_hz = js.control_rate_hz;
  p.heading_rad = core::deg_to_rad(spec.initial_heading_deg);
  return p;
}

const Eigen::Vector3d kNoSetpoint = Eigen::Vector3d::Constant(core::kMissing);
const Eigen::Vector3d kNoBias = Eigen::Vector3d::Zero();

}  // namespace

InitialTrim initial_trim(const ScenarioSpec& spec, const VesselConfig& vessel,
                         const VesselPlant& plant) {
  InitialTrim trim;
  trim.x0 = plant.initial_state(core::deg_to_rad(spec.initial_heading_deg));
  if (spec.initial_surge_mps == 0.0) return trim;
  const JoystickParams& js = vessel.joystick;
  const double u0 = spec.initial_surge_mps;
  trim.x0[Plant::kHull + Hull::kSurge] = u0;
  const double x_needed = -plant.hull().hydrodynamic_forces({u0, 0, 0}, {u0, 0, 0}).x();
  trim.demand_pct.x() = 100.0 * x_needed / js.max_surge_N;
  trim.lever_pct.x() = lever_pct_for_fraction(x_needed / js.max_surge_N, js.lever_exponent);
  const double n = plant.propeller().shaft_speed_for_thrust(0.5 * x_needed);
  trim.x0.segment<4>(Plant::kPort) = plant.propeller().steady_state(n, u0);
  trim.x0.segment<4>(Plant::kStb) = plant.propeller().steady_state(n, u0);
  trim.commands.n_port_rps = trim.commands.n_stb_rps = n;
  return trim;
}

ControlTask::ControlTask(const ScenarioSpec& spec, const VesselConfig& vessel,
                         const VesselPlant& plant, const InitialTrim& trim)
    : joystick_params_(vessel.joystick),
      period_s_(1.0 / vessel.joystick.control_rate_hz),
      dt_s_(spec.dt_s),
      propeller_(plant.propeller()),
      allocator_(plant.propeller(), plant.rudder(), plant.tunnel(), plant.layout(),
                 vessel.allocation),
      joystick_(spec.joystick, trim.lever_pct),
      rudder_(spec.rudder, plant.rudder(), plant.hull(), vessel.layout.p_port_rudder_b.x(),
              spec.dt_s),
      demand_pct_(trim.demand_pct),
      commands_(trim.commands) {
  if (spec.heading_hold) heading_hold_.emplace(heading_hold_params(spec, vessel));
  if (!spec.setpoints.empty()) {
    dp_.emplace(spec, vessel, plant.hull(), trim.x0.segment<3>(Plant::kHull + Hull::kNorth),
                period_s_);
  }
}

const Eigen::Vector3d& ControlTask::setpoint_n() const noexcept {
  return dp_ ? dp_->setpoint_n() : kNoSetpoint;
}

const Eigen::Vector3d& ControlTask::bias_hat_n() const noexcept {
  return dp_ ? dp_->bias_hat_n() : kNoBias;
}

void ControlTask::step(double t, const sim::ConstVectorRef& x) {
  const JoystickParams& js = joystick_params_;
  const bool changed = joystick_.advance(t);
  demand_pct_ = 100.0 * lever_to_demand_fraction(joystick_.lever_pct(), js.lever_exponent);
  if (heading_hold_) {
    // Auto heading on the low-frequency heading, added to the operator's yaw demand.
    demand_pct_.z() =
        100.0 * heading_hold_->update(demand_pct_.z() / 100.0, x[Plant::kHull + Hull::kYaw],
                                      x[Plant::kHull + Hull::kYawRate]);
  }
  model::ThrustAllocationInput in;
  const Eigen::Vector3d joystick_tau_b =
      (demand_pct_ / 100.0)
          .cwiseProduct(Eigen::Vector3d(js.max_surge_N, js.max_sway_N, js.max_yaw_Nm));
  in.tau_d_b = joystick_tau_b;
  if (dp_) {
    const Eigen::Vector3d eta_n = x.segment<3>(Plant::kHull + Hull::kNorth);
    const Eigen::Vector3d nu_b = x.segment<3>(Plant::kHull + Hull::kSurge);
    if (const std::optional<DpDemand> demand = dp_->control(t, eta_n, nu_b)) {
      in.tau_d_b = demand->tau_b;
      if (demand->hold_split) in.hold_forces = forces_N_;
    }
  }
  in.surge_speed = x[Plant::kHull + Hull::kSurge];
  const model::ThrustAllocationResult a = allocator_.allocate(in);
  if (dp_) {
    dp_->integrate_bias(x[Plant::kHull + Hull::kYaw], a.status == model::AllocationStatus::kOk);
  }
  const ActuatorCommands before = commands_;
  commands_ = {a.n_port, a.n_stb, a.rudder_port, a.rudder_stb, a.n_tunnel};
  forces_N_ = a.forces;
  const std::optional<double>& rudder_rad =
      rudder_.advance(t, before.rudder_stb_rad, x[Plant::kHull + Hull::kSurge]);
  if (rudder_rad) commands_.rudder_port_rad = commands_.rudder_stb_rad = *rudder_rad;
  unmet_max_ = unmet_max_.cwiseMax(a.tau_unmet_b.cwiseAbs());
  if (changed) record_command(t, before, joystick_tau_b, a.tau_unmet_b);
}

void ControlTask::record_command(double t, const ActuatorCommands& before,
                                 const Eigen::Vector3d& demand_b,
                                 const Eigen::Vector3d& tau_unmet_b) {
  const Eigen::Vector3d& lever = joystick_.lever_pct();
  CommandTruth c;
  c.t_s = t;
  c.surge_pct = lever.x();
  c.sway_pct = lever.y();
  c.yaw_pct = lever.z();
  c.demand_surge_N = demand_b.x();
  c.demand_sway_N = demand_b.y();
  c.demand_yaw_Nm = demand_b.z();
  c.n_port_rps = commands_.n_port_rps;
  c.n_stb_rps = commands_.n_stb_rps;
  c.rudder_port_deg = core::rad_to_deg(commands_.rudder_port_rad);
  c.rudder_stb_deg = core::rad_to_deg(commands_.rudder_stb_rad);
  c.n_tunnel_rps = commands_.n_tunnel_rps;
  c.tau_unmet = tau_unmet_b;
  command_truth_.push_back(c);
  // Both main propellers (one model): the sway tables 3.27 and 3.29 use the starboard and the
  // port propeller respectively.
  for (const auto& [name, n_from, n_to] :
       {std::tuple{"port", before.n_port_rps, commands_.n_port_rps},
        std::tuple{"stb", before.n_stb_rps, commands_.n_stb_rps}}) {
    if (std::abs(n_to - n_from) <= 1e-3) continue;
    const model::ThrusterStepTruth step =
        model::thruster_step_truth(propeller_, n_from, n_to, dt_s_);
    propeller_steps_.push_back({t, name, n_from, n_to, step.shaft_speed, step.thrust});
  }
}

void ControlTask::write_truth(TrialTruth& truth) const {
  truth.commands = command_truth_;
  truth.propeller_steps = propeller_steps_;
  truth.rudder_steps = rudder_.steps();
  truth.setpoints = dp_ ? dp_->setpoints().legs() : std::vector<SetpointTruth>{};
  truth.hybrid.reset();
  if (dp_ && dp_->jumps())
    truth.hybrid = HybridTruth{dp_->jumps()->params(), dp_->jumps()->jump_times()};
  truth.allocation_unmet_max = unmet_max_;
}

}  // namespace dynpos::scenario
