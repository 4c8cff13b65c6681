#include "dynpos/scenario/control_task.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

#include "dynpos/core/angle.hpp"
#include "dynpos/core/log.hpp"
#include "dynpos/model/azimuth_region.hpp"
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

// An azimuth below this fraction of its rating keeps its direction (the file comment).
constexpr double kIdleThrustFraction = 0.01;

// The direction an azimuth rests in: ahead, or the middle of its first allowed arc when ahead
// is forbidden.
double rest_angle_rad(const model::ThrusterUnit& unit) {
  if (unit.type != model::UnitType::kAzimuth ||
      !model::in_forbidden_sector(0.0, unit.forbidden_deg))
    return 0.0;
  const model::AllowedArc arc = model::allowed_arcs(unit.forbidden_deg).front();
  return arc.from_rad + 0.5 * arc.span_rad;
}

// The orders that make a unit's allocated command, its steering held at `angle_before` [rad]
// while an azimuth idles; `angle_now` is where its steering is [rad] (the thrust cut). A unit
// at capacity c delivers c times its drive's thrust (the plant): its shaft is ordered for T/c.
ActuatorCommands::Unit unit_order(const model::UnitDrive& drive, const model::UnitCommand& c,
                                  double angle_before, double angle_now, double capacity) {
  const model::ThrusterUnit& unit = drive.unit();
  ActuatorCommands::Unit order;
  order.thrust_N = c.thrust_N;
  double thrust = c.thrust_N;
  switch (unit.type) {
    case model::UnitType::kAzimuth: {
      const bool idle = c.thrust_N < kIdleThrustFraction * unit.max_thrust_N;
      // The command's direction, unwrapped next to the order before (no needless turn).
      order.angle_rad =
          idle ? angle_before
               : angle_before + std::remainder(c.angle_rad - angle_before, 2.0 * std::numbers::pi);
      // Cut by cos of the turn the servo still makes (it may go the long way round).
      const double left = std::abs(drive.turn_rad(angle_now, order.angle_rad));
      thrust *= left >= 0.5 * std::numbers::pi ? 0.0 : std::cos(left);
      break;
    }
    case model::UnitType::kPropellerRudder:
      order.angle_rad = drive.rudder_angle_for(c.rudder_force_N, c.thrust_N);
      break;
    default:
      break;
  }
  // The plant gives capacity × loss factor × the drive's thrust: the shaft is ordered for the rest.
  const double factor = capacity * (unit.type == model::UnitType::kAzimuth
                                        ? model::loss_factor(unit.loss, order.angle_rad)
                                        : 1.0);
  order.n_rps = factor > 0.0 ? drive.shaft_speed_for(thrust / factor) : 0.0;
  return order;
}

// The allocation of one control step (the file comment). An azimuth the optimum sends across a
// forbidden sector the short way (so round the far side, or through it) is first held within a
// quarter turn of where it points, clear of the sector; that allocation is taken when it meets
// the demand.
// Without it an azimuth beside a forbidden sector is sent from one edge of the sector to the
// other whenever the demand's surge changes sign: round the far side, at no thrust, again and
// again (seen on the supply vessel with a main azimuth lost in a beam sea).
model::LayoutAllocation steered_allocation(const model::LayoutAllocator& allocator,
                                           const std::vector<model::UnitDrive>& drives,
                                           const std::vector<double>& capacity,
                                           const Eigen::Vector3d& tau_d_b,
                                           const sim::ConstVectorRef& x) {
  model::LayoutAllocation a = allocator.allocate(tau_d_b, capacity);
  std::vector<model::ThrusterUnit> units;  // copied only when an azimuth is held (rare)
  for (std::size_t k = 0; k < drives.size(); ++k) {
    const double angle = x[VesselPlant::kUnits + 2 * static_cast<Eigen::Index>(k) + 1];
    const model::UnitCommand& c = a.units[k];
    if (c.thrust_N < kIdleThrustFraction * drives[k].unit().max_thrust_N ||
        !drives[k].short_way_blocked(angle, c.angle_rad)) {
      continue;
    }
    const auto reach = drives[k].reachable(angle, 0.5 * std::numbers::pi);
    if (!reach || reach->span_rad < 1e-6) continue;
    // The rest of the circle forbidden: from the window's end round to its start [deg].
    const auto deg = [](double rad) {
      const double d = core::rad_to_deg(core::wrap_2pi(rad));
      return d >= 360.0 ? 0.0 : d;
    };
    if (units.empty()) units = allocator.units();
    units[k].forbidden_deg = {{deg(reach->from_rad + reach->span_rad), deg(reach->from_rad)}};
  }
  if (units.empty()) return a;
  model::LayoutAllocation b = model::LayoutAllocator(std::move(units)).allocate(tau_d_b, capacity);
  return b.met ? b : a;
}

// The trim of a layout: steering at rest, or each unit at the steady state of the allocation of
// the surge force x_needed_N.
void trim_units(const VesselConfig& vessel, const VesselPlant& plant, double x_needed_N,
                InitialTrim& trim) {
  const auto& drives = plant.drives();
  model::LayoutAllocation a;
  if (x_needed_N != 0.0) {
    a = model::LayoutAllocator(vessel.thrusters).allocate({x_needed_N, 0.0, 0.0}, plant.capacity());
  }
  for (std::size_t k = 0; k < drives.size(); ++k) {
    const double rest = rest_angle_rad(drives[k].unit());
    ActuatorCommands::Unit order{0.0, rest, 0.0};
    if (!a.units.empty()) {
      order = unit_order(drives[k], a.units[k], rest, rest, plant.capacity()[k]);
    }
    if (!a.units.empty() && drives[k].unit().type == model::UnitType::kAzimuth) {
      order.angle_rad = a.units[k].thrust_N > 0.0 ? a.units[k].angle_rad : rest;
      const double c =
          plant.capacity()[k] * model::loss_factor(drives[k].unit().loss, order.angle_rad);
      order.n_rps = c > 0.0 ? drives[k].shaft_speed_for(a.units[k].thrust_N / c) : 0.0;
    }
    const Eigen::Index i = Plant::kUnits + 2 * static_cast<Eigen::Index>(k);
    trim.x0[i] = order.n_rps;
    trim.x0[i + 1] = order.angle_rad;
    trim.commands.units.push_back(order);
  }
}

}  // namespace

InitialTrim initial_trim(const ScenarioSpec& spec, const VesselConfig& vessel,
                         const VesselPlant& plant) {
  InitialTrim trim;
  trim.x0 = plant.initial_state(core::deg_to_rad(spec.initial_heading_deg));
  const JoystickParams& js = vessel.joystick;
  const double u0 = spec.initial_surge_mps;
  const double x_needed =
      u0 == 0.0 ? 0.0 : -plant.hull().hydrodynamic_forces({u0, 0, 0}, {u0, 0, 0}).x();
  if (!plant.drives().empty()) trim_units(vessel, plant, x_needed, trim);
  if (u0 == 0.0) return trim;
  trim.x0[Plant::kHull + Hull::kSurge] = u0;
  trim.demand_pct.x() = 100.0 * x_needed / js.max_surge_N;
  trim.lever_pct.x() = lever_pct_for_fraction(x_needed / js.max_surge_N, js.lever_exponent);
  if (!plant.drives().empty()) return trim;
  const double n = plant.propeller().shaft_speed_for_thrust(0.5 * x_needed);
  trim.x0.segment<4>(Plant::kPort) = plant.propeller().steady_state(n, u0);
  trim.x0.segment<4>(Plant::kStb) = plant.propeller().steady_state(n, u0);
  trim.commands.n_port_rps = trim.commands.n_stb_rps = n;
  return trim;
}

ControlTask::ControlTask(const ScenarioSpec& spec, const VesselConfig& vessel,
                         const VesselPlant& plant, const InitialTrim& trim, std::uint64_t seed,
                         const model::Wind* wind)
    : joystick_params_(vessel.joystick),
      period_s_(1.0 / vessel.joystick.control_rate_hz),
      dt_s_(spec.dt_s),
      propeller_(plant.propeller()),
      allocator_(plant.propeller(), plant.rudder(), plant.tunnel(), plant.layout(),
                 vessel.allocation),
      plant_(plant),
      joystick_(spec.joystick, trim.lever_pct),
      rudder_(spec.rudder, plant.rudder(), plant.hull(), vessel.layout.p_port_rudder_b.x(),
              spec.dt_s),
      allocation_options_(vessel.allocation),
      capacity_(plant.capacity()),
      demand_pct_(trim.demand_pct),
      commands_(trim.commands) {
  if (!plant.drives().empty()) layout_allocator_.emplace(vessel.thrusters);
  if (spec.heading_hold) heading_hold_.emplace(heading_hold_params(spec, vessel));
  if (!spec.setpoints.empty()) {
    const Eigen::Vector3d eta0_n = trim.x0.segment<3>(Plant::kHull + Hull::kNorth);
    dp_.emplace(spec, vessel, plant.hull(), eta0_n, period_s_);
    estimator_.emplace(spec, vessel, plant, seed, period_s_, eta0_n, wind);
  }
  if (spec.failure) failure_.emplace(*spec.failure, vessel);
}

void ControlTask::apply_failure(double t) {
  if (!failure_ || failure_applied_ || !failure_->detected_at(t)) return;
  failure_applied_ = true;
  if (!plant_.drives().empty()) {
    for (std::size_t k = 0; k < capacity_.size(); ++k) capacity_[k] *= failure_->capacity()[k];
    return;
  }
  allocator_ = model::ThrustAllocator(plant_.propeller(), plant_.rudder(), plant_.tunnel(),
                                      plant_.layout(), failure_->allocation(allocation_options_));
}

const Eigen::Vector3d& ControlTask::setpoint_n() const noexcept {
  return dp_ ? dp_->setpoint_n() : kNoSetpoint;
}

const Eigen::Vector3d& ControlTask::bias_hat_n() const noexcept {
  return dp_ ? dp_->bias_hat_n() : kNoBias;
}

void ControlTask::step(double t, const sim::ConstVectorRef& x, const sim::ConstVectorRef& u) {
  const JoystickParams& js = joystick_params_;
  apply_failure(t);
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
  double psi_dp = x[Plant::kHull + Hull::kYaw];  // the heading the DP loop sees
  if (dp_) {
    const DpMotion motion = estimator_->update(t, x, u);
    psi_dp = motion.eta_n.z();
    if (const std::optional<DpDemand> demand = dp_->control(t, motion.eta_n, motion.nu_b)) {
      in.tau_d_b = demand->tau_b;
      dp_demand_b_ = demand->tau_b;
      if (demand->hold_split) in.hold_forces = forces_N_;
    }
  }
  if (!plant_.drives().empty()) {
    const ActuatorCommands before = commands_;
    const model::LayoutAllocation a = allocate_units(in.tau_d_b, x);
    if (dp_) dp_->integrate_bias(psi_dp, a.met);
    unmet_max_ = unmet_max_.cwiseMax(a.tau_unmet_b.cwiseAbs());
    if (changed) record_command(t, before, joystick_tau_b, a.tau_unmet_b);
    return;
  }
  in.surge_speed = x[Plant::kHull + Hull::kSurge];
  const model::ThrustAllocationResult a = allocator_.allocate(in);
  if (dp_) {
    dp_->integrate_bias(psi_dp, a.status == model::AllocationStatus::kOk);
  }
  const ActuatorCommands before = commands_;
  commands_ = {a.n_port, a.n_stb, a.rudder_port, a.rudder_stb, a.n_tunnel, {}};
  forces_N_ = a.forces;
  const std::optional<double>& rudder_rad =
      rudder_.advance(t, before.rudder_stb_rad, x[Plant::kHull + Hull::kSurge]);
  if (rudder_rad) commands_.rudder_port_rad = commands_.rudder_stb_rad = *rudder_rad;
  unmet_max_ = unmet_max_.cwiseMax(a.tau_unmet_b.cwiseAbs());
  if (changed) record_command(t, before, joystick_tau_b, a.tau_unmet_b);
}

model::LayoutAllocation ControlTask::allocate_units(const Eigen::Vector3d& tau_d_b,
                                                    const sim::ConstVectorRef& x) {
  model::LayoutAllocation a =
      steered_allocation(*layout_allocator_, plant_.drives(), capacity_, tau_d_b, x);
  const auto& drives = plant_.drives();
  for (std::size_t k = 0; k < drives.size(); ++k) {
    const double angle_now = x[Plant::kUnits + 2 * static_cast<Eigen::Index>(k) + 1];
    commands_.units[k] =
        unit_order(drives[k], a.units[k], commands_.units[k].angle_rad, angle_now, capacity_[k]);
  }
  return a;
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
  c.tau_unmet = tau_unmet_b;
  if (!plant_.drives().empty()) {  // the model's actuators are not there
    c.n_port_rps = c.n_stb_rps = c.n_tunnel_rps = core::kMissing;
    c.rudder_port_deg = c.rudder_stb_deg = core::kMissing;
    command_truth_.push_back(c);
    return;
  }
  c.n_port_rps = commands_.n_port_rps;
  c.n_stb_rps = commands_.n_stb_rps;
  c.rudder_port_deg = core::rad_to_deg(commands_.rudder_port_rad);
  c.rudder_stb_deg = core::rad_to_deg(commands_.rudder_stb_rad);
  c.n_tunnel_rps = commands_.n_tunnel_rps;
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
