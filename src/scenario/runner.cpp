#include "dynpos/scenario/runner.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <tuple>

#include "dynpos/control/dp_controller.hpp"
#include "dynpos/control/reference_model.hpp"
#include "dynpos/core/angle.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/core/rotation.hpp"
#include "dynpos/hybrid/integral_jump.hpp"
#include "dynpos/model/delay_line.hpp"
#include "dynpos/model/environment.hpp"
#include "dynpos/model/sea_state.hpp"
#include "dynpos/model/thrust_allocation.hpp"
#include "dynpos/scenario/joystick_lever.hpp"
#include "dynpos/scenario/vessel_plant.hpp"
#include "dynpos/sim/sim_time.hpp"
#include "dynpos/sim/simulator.hpp"
#include "sensor_logger.hpp"
#include "vessel_motion.hpp"

namespace dynpos::scenario {
namespace {

using Plant = VesselPlant;
using model::Hull;

// Actuator commands before their dead times.
struct Commands {
  double n_port = 0, n_stb = 0, rudder_port = 0, rudder_stb = 0, n_tunnel = 0;
};

// The truth log's channels, in column order (names are roles of docs/log-format.md; SI).
// (Size deduced from the list, so a channel cannot be left unnamed.)
constexpr std::pair<const char*, const char*> kTruthChannels[] = {
    {"north", "m"},
    {"east", "m"},
    {"down", "m"},
    {"heading", "rad"},
    {"roll", "rad"},
    {"pitch", "rad"},
    {"u", "m/s"},
    {"v", "m/s"},
    {"w", "m/s"},
    {"p", "rad/s"},
    {"q", "rad/s"},
    {"r", "rad/s"},
    {"rpm.port", "rps"},
    {"rpm.stb", "rps"},
    {"rpm.tunnel", "rps"},
    {"thrust.port", "N"},
    {"thrust.stb", "N"},
    {"thrust.tunnel", "N"},
    {"power.port", "W"},
    {"power.stb", "W"},
    {"power.tunnel", "W"},
    {"rudder.port", "rad"},
    {"rudder.stb", "rad"},
    {"command.surge", "1"},
    {"command.sway", "1"},
    {"command.yaw", "1"},
    {"lever.surge", "1"},
    {"lever.sway", "1"},
    {"lever.yaw", "1"},
    {"wind_speed", "m/s"},
    {"wind_dir", "rad"},
    {"current.north", "m/s"},
    {"current.east", "m/s"},
    {"setpoint.north", "m"},
    {"setpoint.east", "m"},
    {"setpoint.heading", "rad"},
    {"bias_estimate.north", "N"},
    {"bias_estimate.east", "N"},
    {"bias_estimate.yaw", "N*m"},
    {"load.north", "N"},
    {"load.east", "N"},
    {"load.yaw", "N*m"},
};

// The trial logger's command channels, after the sensors (logger units).
constexpr std::pair<const char*, const char*> kCommandChannels[] = {
    {"command.surge", "%"},         {"command.sway", "%"},         {"command.yaw", "%"},
    {"lever.surge", "%"},           {"lever.sway", "%"},           {"lever.yaw", "%"},
    {"command.rpm.port", "rpm"},    {"command.rpm.stb", "rpm"},    {"command.rpm.tunnel", "rpm"},
    {"command.thrust.port", "kN"},  {"command.thrust.stb", "kN"},  {"command.thrust.tunnel", "kN"},
    {"command.rudder.port", "deg"}, {"command.rudder.stb", "deg"}, {"setpoint.north", "m"},
    {"setpoint.east", "m"},         {"setpoint.heading", "deg"},
};

nlohmann::json scenario_json(const ScenarioSpec& spec) {
  nlohmann::json j;
  j["name"] = spec.name;
  j["description"] = spec.description;
  j["duration_s"] = spec.duration_s;
  j["dt_s"] = spec.dt_s;
  j["log_rate_hz"] = spec.log_rate_hz;
  j["initial_heading_deg"] = spec.initial_heading_deg;
  j["initial_surge_mps"] = spec.initial_surge_mps;
  j["settle_s"] = spec.settle_s;
  j["start_utc"] = spec.start_utc;
  const EnvironmentSpec& e = spec.environment;
  j["rudder"] = nlohmann::json::array();
  for (const RudderCommand& r : spec.rudder) {
    j["rudder"].push_back(
        {{"t_s", r.t_s},
         {"angle_deg", r.release ? nlohmann::json(nullptr) : nlohmann::json(r.angle_deg)},
         {"release", r.release}});
  }
  j["loads"] = nlohmann::json::array();
  for (const LoadEvent& e : spec.loads) {
    j["loads"].push_back({{"t_on_s", e.t_on_s},
                          {"t_off_s", e.t_off_s < 1e299 ? nlohmann::json(e.t_off_s) : nullptr},
                          {"north_N", e.north_N},
                          {"east_N", e.east_N},
                          {"yaw_Nm", e.yaw_Nm}});
  }
  j["environment"] = {{"current_speed_mps", e.current_speed_mps},
                      {"current_to_deg", e.current_to_deg},
                      {"wind_speed_mps", e.wind_speed_mps},
                      {"wind_from_deg", e.wind_from_deg},
                      {"hs_m", e.hs_m},
                      {"tp_s", e.tp_s},
                      {"wave_from_deg", e.wave_from_deg},
                      {"wave_components", e.wave_components}};
  return j;
}

// Largest unmet allocation demand per DOF over a run.
struct UnmetSummary {
  Eigen::Vector3d max = Eigen::Vector3d::Zero();
  void add(const Eigen::Vector3d& unmet) { max = max.cwiseMax(unmet.cwiseAbs()); }
};

nlohmann::json fopdt_json(const model::FopdtTruth& f) {
  return {{"T_s", f.time_constant}, {"delay_s", f.dead_time}};
}

}  // namespace

ScenarioRun run_scenario(const ScenarioSpec& spec, const VesselConfig& vessel, std::uint64_t seed) {
  spec.validate();
  vessel.validate();
  const double dt = spec.dt_s;
  const Plant plant(vessel);
  const model::ThrustAllocator allocator(plant.propeller(), plant.rudder(), plant.tunnel(),
                                         plant.layout(), vessel.allocation);

  // Environment, each source with its own seeded stream.
  const EnvironmentSpec& env = spec.environment;
  model::CurrentParams current_params = vessel.current;
  current_params.speed_mps = env.current_speed_mps;
  current_params.to_rad = core::deg_to_rad(env.current_to_deg);
  model::WindParams wind_params = vessel.wind;
  wind_params.speed_mps = env.wind_speed_mps;
  wind_params.from_rad = core::deg_to_rad(env.wind_from_deg);
  model::SeaStateParams sea;
  sea.hs_m = env.hs_m;
  sea.tp_s = env.tp_s;
  sea.from_rad = core::deg_to_rad(env.wave_from_deg);
  sea.components = env.wave_components;
  const double log_period = 1.0 / spec.log_rate_hz;
  model::Current current(current_params, seed, dt);
  model::Wind wind(wind_params, seed, dt);
  model::Bias bias(model::bias_for_sea_state(vessel.bias, env.hs_m), seed, dt);
  model::WaveMotion waves(sea, vessel.waves, seed, log_period);
  std::vector<model::StepLoad> loads;
  for (const LoadEvent& e : spec.loads) {
    loads.push_back({e.t_on_s, e.t_off_s, Eigen::Vector3d(e.north_N, e.east_N, e.yaw_Nm)});
  }

  // Operator commands and their dead times.
  const JoystickParams& js = vessel.joystick;
  // The lever (surge, sway, yaw) in % of full deflection as the operator set it, and the demand
  // it makes through the lever curve (with auto heading, including the heading controller's
  // moment), in % of the joystick maxima: what the allocation gets and the log's command.*.
  Eigen::Vector3d lever_pct = Eigen::Vector3d::Zero();
  Eigen::Vector3d demand_pct = Eigen::Vector3d::Zero();
  Eigen::VectorXd x0 = plant.initial_state(core::deg_to_rad(spec.initial_heading_deg));
  Commands cmd;
  if (spec.initial_surge_mps != 0.0) {
    const double u0 = spec.initial_surge_mps;
    x0[Plant::kHull + Hull::kSurge] = u0;
    const double x_needed = -plant.hull().hydrodynamic_forces({u0, 0, 0}, {u0, 0, 0}).x();
    demand_pct.x() = 100.0 * x_needed / js.max_surge_N;
    lever_pct.x() = lever_pct_for_fraction(x_needed / js.max_surge_N, js.lever_exponent);
    const double n = plant.propeller().shaft_speed_for_thrust(0.5 * x_needed);
    x0.segment<4>(Plant::kPort) = plant.propeller().steady_state(n, u0);
    x0.segment<4>(Plant::kStb) = plant.propeller().steady_state(n, u0);
    cmd.n_port = cmd.n_stb = n;
  }
  model::DelayLine delay_port(vessel.propeller.dead_time, dt, cmd.n_port);
  model::DelayLine delay_stb(vessel.propeller.dead_time, dt, cmd.n_stb);
  model::DelayLine delay_rudder_port(vessel.rudder.dead_time, dt, 0.0);
  model::DelayLine delay_rudder_stb(vessel.rudder.dead_time, dt, 0.0);
  model::DelayLine delay_tunnel(vessel.tunnel.dead_time, dt, 0.0);

  sim::SimulatorOptions options;
  options.dt = dt;
  // The simulation runs settle_s before the scenario's t = 0; every task works in scenario
  // time t = (k − k_settle)·dt, exact on the grid like the simulator's own, and the loggers
  // record from t = 0 on.
  const sim::TimeGrid grid(dt);
  const sim::Tick settle_ticks = grid.ticks(spec.settle_s, "settle_s");
  const auto scenario_time = [&](const sim::TaskContext& c) {
    return grid.time(c.tick() - settle_ticks);
  };
  options.end_time = spec.settle_s + spec.duration_s;
  sim::Simulator simulator(plant, options);

  nlohmann::json truth;
  truth["seed"] = seed;
  truth["scenario"] = scenario_json(spec);
  truth["vessel"] = vessel.to_json();
  truth["commands"] = nlohmann::json::array();
  truth["propeller_steps"] = nlohmann::json::array();
  truth["lever_arms"] = nlohmann::json::object();
  for (const sensors::GnssParams& g : vessel.sensors.gnss) {
    const Eigen::Vector3d& l = g.lever_arm_b;
    truth["lever_arms"][g.name] = {l.x(), l.y(), l.z()};
  }
  for (const sensors::MruParams& m : vessel.sensors.mru) {
    const Eigen::Vector3d& l = m.lever_arm_b;
    truth["lever_arms"][m.name] = {l.x(), l.y(), l.z()};
  }
  truth["mru_acceleration"] = sensors::to_string(vessel.sensors.mru_acceleration);

  // DP mode: controller (5.35)–(5.38) on the low-frequency motion (an ideal observer), its
  // model M from the hull and D from the hull's linear damping at rest.
  const bool dp_mode = !spec.setpoints.empty();
  control::DpControllerParams dp_params;
  dp_params.M = plant.hull().mass_matrix();
  dp_params.M(1, 2) = dp_params.M(2, 1) = 0.5 * (dp_params.M(1, 2) + dp_params.M(2, 1));
  dp_params.D =
      Eigen::Vector3d(vessel.hull.x_u_Ns_m, vessel.hull.y_v_Ns_m, vessel.hull.n_r_Nms).asDiagonal();
  const control::DpController dp(dp_params);
  control::ReferenceModel reference(control::ReferenceModelParams{},
                                    x0.segment<3>(Plant::kHull + Hull::kNorth));
  const control::OperatingCircle circle;
  Eigen::Vector3d bias_hat = Eigen::Vector3d::Zero();
  // Hybrid integral action (spec.hybrid_integral): the previous x₂ sample and the last jump.
  Eigen::Vector3d prev_x2 = Eigen::Vector3d::Zero();
  double prev_x2_time = -1e300, last_jump_time = -1e299;
  if (spec.hybrid_integral) {
    const hybrid::IntegralJumpParams& hp = *spec.hybrid_integral;
    truth["hybrid"] = {{"rule", "practical (5.64)-(5.67), b_hat += Lambda R(psi) x2"},
                       {"lambda", {hp.lambda.x(), hp.lambda.y(), hp.lambda.z()}},
                       {"epsilon1", hp.epsilon1},
                       {"epsilon2", hp.epsilon2},
                       {"sigma", hp.sigma},
                       {"dwell_s", hp.dwell_s},
                       {"jump_times_s", nlohmann::json::array()}};
  }
  std::size_t next_setpoint = 0;
  bool dp_active = false;
  Eigen::Vector3d setpoint = Eigen::Vector3d::Constant(core::kMissing);
  truth["setpoints"] = nlohmann::json::array();
  auto apply_setpoint = [&](const SetpointCommand& sp, double t) {
    setpoint = {sp.north_m, sp.east_m, core::deg_to_rad(sp.heading_deg)};
    if (!truth["setpoints"].empty()) truth["setpoints"].back()["t_end_s"] = t;
    truth["setpoints"].push_back({{"name", sp.name},
                                  {"t_start_s", t},
                                  {"north_m", sp.north_m},
                                  {"east_m", sp.east_m},
                                  {"heading_deg", sp.heading_deg}});
    dp_active = true;
  };

  // Control task: joystick demand or DP → allocation, at the control rate; manual rudders.
  std::size_t next_command = 0;
  std::size_t next_rudder = 0;
  std::optional<double> rudder_override;  // [rad], both rudders
  truth["rudder_steps"] = nlohmann::json::array();
  UnmetSummary unmet;
  // The last allocated forces f = (T₁, T₂, Y₁, Y₂, T₃) [N]: logged, and held in DP.
  Eigen::Matrix<double, 5, 1> last_forces = Eigen::Matrix<double, 5, 1>::Zero();
  // Auto heading (spec.heading_hold): PID gains from the joystick's ω and ζ.
  double heading_integral_Nm = 0.0;
  const double psi_hold = core::deg_to_rad(spec.initial_heading_deg);
  const double inertia_z = vessel.hull.iz_kgm2 + vessel.hull.n_rdot_kgm2;
  const double w_h = js.heading_hold_omega_rad_s;
  const double kp_heading = inertia_z * w_h * w_h;
  const double kd_heading =
      std::max(0.0, 2.0 * js.heading_hold_zeta * w_h * inertia_z - vessel.hull.n_r_Nms);
  const double ki_heading = kp_heading * w_h / 10.0;  // integral time 10/ω
  simulator.add_periodic_task("control", 1.0 / js.control_rate_hz, 0.0, [&](sim::TaskContext& c) {
    const double t = scenario_time(c);
    bool changed = false;
    while (next_command < spec.joystick.size() && spec.joystick[next_command].t_s <= t + 1e-9) {
      const JoystickCommand& j = spec.joystick[next_command++];
      lever_pct = {j.surge_pct, j.sway_pct, j.yaw_pct};
      changed = true;
    }
    demand_pct = 100.0 * lever_to_demand_fraction(lever_pct, js.lever_exponent);
    if (spec.heading_hold) {
      // Auto heading: PID on the low-frequency heading (an ideal observer), added to the
      // operator's yaw demand within the joystick's yaw range; the integral stops while the
      // demand is saturated (anti-windup).
      const double psi_err = core::angle_diff(c.state()[Plant::kHull + Hull::kYaw], psi_hold);
      const double r = c.state()[Plant::kHull + Hull::kYawRate];
      const double yaw_Nm = -kp_heading * psi_err - kd_heading * r - heading_integral_Nm;
      const double fraction = demand_pct.z() / 100.0 + yaw_Nm / js.max_yaw_Nm;
      const double clamped = std::clamp(fraction, -1.0, 1.0);
      demand_pct.z() = 100.0 * clamped;
      if (fraction == clamped) heading_integral_Nm += ki_heading * psi_err / js.control_rate_hz;
    }
    model::ThrustAllocationInput in;
    std::optional<Eigen::Vector3d> dp_x2;  // x₂ of this DP step, for the integral action
    const Eigen::Vector3d joystick_tau_b =
        (demand_pct / 100.0)
            .cwiseProduct(Eigen::Vector3d(js.max_surge_N, js.max_sway_N, js.max_yaw_Nm));
    in.tau_d_b = joystick_tau_b;
    if (dp_mode) {
      const Eigen::Vector3d eta = c.state().segment<3>(Plant::kHull + Hull::kNorth);
      const Eigen::Vector3d nu = c.state().segment<3>(Plant::kHull + Hull::kSurge);
      while (next_setpoint < spec.setpoints.size()) {
        const SetpointCommand& sp = spec.setpoints[next_setpoint];
        const bool timed = sp.t_s >= 0.0 && sp.t_s <= t + 1e-9;
        const bool on_reach = sp.t_s < 0.0 && dp_active && circle.reached(eta, setpoint);
        if (!timed && !on_reach) break;
        if (on_reach) truth["setpoints"].back()["t_reached_s"] = t;
        apply_setpoint(sp, t);
        ++next_setpoint;
      }
      // The first time the setpoint in force is inside its operating circle (section 3.5.2),
      // whether the next setpoint follows on reach or at its time.
      if (dp_active && !truth["setpoints"].back().contains("t_reached_s") &&
          circle.reached(eta, setpoint)) {
        truth["setpoints"].back()["t_reached_s"] = t;
      }
      if (dp_active) {
        const double dt_control = 1.0 / js.control_rate_hz;
        reference.step(setpoint, dt_control);
        const control::DpCommand cmd_dp = dp.control(eta, nu, reference.reference(), bias_hat);
        dp_x2 = cmd_dp.x2;
        in.tau_d_b = cmd_dp.tau_b;
        // Stationkeeping (reference within 1 % of its rate limits of rest): hold the thrusters'
        // split (allocation hold_weight), so the allocation does not switch between its two
        // ways of making a yaw moment faster than the propellers follow. During a setpoint
        // change the split is free, as the 4-corner legs need.
        if (reference.at_rest(0.01)) in.hold_forces = last_forces;
        if (spec.hybrid_integral) {
          // Hybrid integral action, practical rule (5.64)–(5.67): ẋ₂ from the last two control
          // samples (only if both are after the last jump), x̂₃ from the closed loop (5.44).
          const hybrid::IntegralJumpParams& hp = *spec.hybrid_integral;
          if (prev_x2_time >= last_jump_time && t - last_jump_time >= hp.dwell_s) {
            const Eigen::Vector3d x2_dot = (cmd_dp.x2 - prev_x2) / (t - prev_x2_time);
            const Eigen::Vector3d x3_hat = hybrid::estimate_integral_error(
                dp_params.M, dp_params.Kd, cmd_dp.x1, cmd_dp.x2, x2_dot, eta.z());
            if (hybrid::in_integral_jump_set(hp, dp_params.Ki, cmd_dp.x1, cmd_dp.x2, x3_hat,
                                             eta.z())) {
              // (5.47), within the controller's anti-windup bound.
              bias_hat = (bias_hat + hybrid::integral_jump(hp, cmd_dp.x2, eta.z()))
                             .cwiseMax(-dp_params.bias_limit)
                             .cwiseMin(dp_params.bias_limit);
              last_jump_time = t;
              truth["hybrid"]["jump_times_s"].push_back(t);
            }
          }
          prev_x2 = cmd_dp.x2;
          prev_x2_time = t;
        }
      }
    }
    in.surge_speed = c.state()[Plant::kHull + Hull::kSurge];
    const model::ThrustAllocationResult a = allocator.allocate(in);
    if (dp_x2 && a.status == model::AllocationStatus::kOk) {
      // Integral action (5.36) with conditional integration: frozen while the allocation
      // cannot meet τ_d, so saturated thrust (a large setpoint change, a squall) does not wind
      // up the bias estimate.
      bias_hat = dp.advance_bias(bias_hat, c.state()[Plant::kHull + Hull::kYaw], *dp_x2,
                                 1.0 / js.control_rate_hz);
    }
    const Commands before = cmd;
    cmd = {a.n_port, a.n_stb, a.rudder_port, a.rudder_stb, a.n_tunnel};
    last_forces = a.forces;
    while (next_rudder < spec.rudder.size() && spec.rudder[next_rudder].t_s <= t + 1e-9) {
      const RudderCommand& rc = spec.rudder[next_rudder++];
      const double from = rudder_override.value_or(before.rudder_stb);
      rudder_override =
          rc.release ? std::nullopt : std::optional<double>(core::deg_to_rad(rc.angle_deg));
      if (rudder_override) {
        const double to =
            std::clamp(*rudder_override, -vessel.rudder.max_angle, vessel.rudder.max_angle);
        const double u0 = c.state()[Plant::kHull + Hull::kSurge];
        nlohmann::json step = {
            {"t_s", t},
            {"from_deg", core::rad_to_deg(from)},
            {"to_deg", core::rad_to_deg(to)},
            {"surge_mps", u0},
            {"servo", fopdt_json(model::rudder_step_truth(plant.rudder(), from, to, dt))}};
        if (u0 > 0.1) {
          const Hull::Nomoto n = plant.hull().nomoto(u0, vessel.layout.p_port_rudder_b.x());
          step["nomoto"] = {{"T1_s", n.t1_s}, {"T2_s", n.t2_s}, {"T3_s", n.t3_s}, {"Tr_s", n.tr_s}};
        }
        truth["rudder_steps"].push_back(step);
      }
    }
    if (rudder_override) cmd.rudder_port = cmd.rudder_stb = *rudder_override;
    unmet.add(a.tau_unmet_b);
    if (changed) {
      truth["commands"].push_back(
          {{"t_s", t},
           {"surge_pct", lever_pct.x()},
           {"sway_pct", lever_pct.y()},
           {"yaw_pct", lever_pct.z()},
           {"demand_surge_N", joystick_tau_b.x()},
           {"demand_sway_N", joystick_tau_b.y()},
           {"demand_yaw_Nm", joystick_tau_b.z()},
           {"n_port_rps", cmd.n_port},
           {"n_stb_rps", cmd.n_stb},
           {"rudder_port_deg", core::rad_to_deg(cmd.rudder_port)},
           {"rudder_stb_deg", core::rad_to_deg(cmd.rudder_stb)},
           {"n_tunnel_rps", cmd.n_tunnel},
           {"tau_unmet", {a.tau_unmet_b.x(), a.tau_unmet_b.y(), a.tau_unmet_b.z()}}});
      // Both main propellers (one model): the sway tables 3.27 and 3.29 use the starboard and
      // the port propeller respectively.
      for (const auto& [name, n_from, n_to] : {std::tuple{"port", before.n_port, cmd.n_port},
                                               std::tuple{"stb", before.n_stb, cmd.n_stb}}) {
        if (std::abs(n_to - n_from) <= 1e-3) continue;
        const model::ThrusterStepTruth step =
            model::thruster_step_truth(plant.propeller(), n_from, n_to, dt);
        truth["propeller_steps"].push_back({{"t_s", t},
                                            {"thruster", name},
                                            {"n_from_rps", n_from},
                                            {"n_to_rps", n_to},
                                            {"shaft_speed", fopdt_json(step.shaft_speed)},
                                            {"thrust", fopdt_json(step.thrust)}});
      }
    }
  });

  // Actuator dead times and the environment, every tick (sample and hold).
  simulator.add_every_tick_task("actuators+environment", [&](sim::TaskContext& c) {
    Eigen::VectorXd& u = c.mutable_input();
    u[Plant::kCmdPort] = delay_port.push(cmd.n_port);
    u[Plant::kCmdStb] = delay_stb.push(cmd.n_stb);
    u[Plant::kCmdRudderPort] = delay_rudder_port.push(cmd.rudder_port);
    u[Plant::kCmdRudderStb] = delay_rudder_stb.push(cmd.rudder_stb);
    u[Plant::kCmdTunnel] = delay_tunnel.push(cmd.n_tunnel);
    current.step();
    wind.step();
    bias.step();
    const Eigen::VectorXd& x = c.state();
    const double psi = x[Plant::kHull + Hull::kYaw];
    const double cs = std::cos(psi), sn = std::sin(psi);
    const double uu = x[Plant::kHull + Hull::kSurge], vv = x[Plant::kHull + Hull::kSway];
    const Eigen::Vector2d velocity_n(cs * uu - sn * vv, sn * uu + cs * vv);
    u.segment<3>(Plant::kTauEnvBody) = wind.force_b(psi, velocity_n) + waves.drift_force_b(psi);
    u.segment<3>(Plant::kForceNed) = bias.value_n() + model::step_loads_n(loads, scenario_time(c));
    u.segment<2>(Plant::kCurrentNed) = current.velocity_n();
  });

  // Loggers at the log rate: the truth (low-frequency state + wave-frequency motion) and the
  // trial logger (sensors, commands, setpoints).
  core::Log truth_log;
  for (const auto& [name, unit] : kTruthChannels) truth_log.declare_channel(name, unit);
  // A sensor rate or latency that does not fit the log's tick grid is bad input (the vessel
  // file together with the scenario's log rate).
  detail::SensorLogger sensor_logger = [&] {
    try {
      return detail::SensorLogger(vessel, plant.propeller(), plant.tunnel(), spec.log_rate_hz,
                                  seed);
    } catch (const std::invalid_argument& e) {
      throw core::InputError(
          {vessel.source.empty() ? spec.source : vessel.source, {}, {}, {}}, e.what(),
          fmt::format("the log rate is {} Hz: give the sensor a rate that divides it and a "
                      "latency of whole log periods, or change the log rate (--log-rate)",
                      spec.log_rate_hz));
    }
  }();
  core::Log log;
  sensor_logger.declare(log);
  for (const auto& [name, unit] : kCommandChannels) log.declare_channel(name, unit);
  const auto rows = static_cast<std::size_t>(std::floor(spec.duration_s * spec.log_rate_hz)) + 1;
  truth_log.reserve(rows);
  log.reserve(rows);
  std::array<double, std::size(kTruthChannels)> row{};
  std::vector<double> measured_row(sensor_logger.channel_count() + std::size(kCommandChannels));
  std::size_t log_tick = 0;
  Eigen::VectorXd dxdt(Plant::kStateSize);
  simulator.add_periodic_task("log", log_period, 0.0, [&](sim::TaskContext& c) {
    const double t = scenario_time(c);
    if (t < -0.5 * dt) return;  // settling: nothing is logged
    const Eigen::VectorXd& x = c.state();
    const Eigen::Vector2d current_n = c.input().segment<2>(Plant::kCurrentNed);
    const ActuatorState a = plant.actuators(x, current_n);
    plant.flow(t, x, c.input(), dxdt);
    const model::WaveMotion6 wf =
        waves.motion(x[Plant::kHull + Hull::kYaw], dxdt[Plant::kHull + Hull::kYaw],
                     dxdt[Plant::kHull + Hull::kYawRate]);
    waves.advance();
    detail::TruthSample truth_now;
    truth_now.motion =
        detail::compose_motion(x.segment<10>(Plant::kHull), dxdt.segment<10>(Plant::kHull), wf);
    truth_now.shaft_speed_rps = {a.port.shaft_speed, a.stb.shaft_speed, a.tunnel.shaft_speed};
    truth_now.power_W = {a.port.power, a.stb.power, a.tunnel.power};
    truth_now.rudder_rad = {x[Plant::kRudderPort], x[Plant::kRudderStb]};
    truth_now.wind_speed_mps = wind.speed_mps();
    truth_now.wind_from_rad = core::wrap_2pi(wind.from_rad());
    const sensors::RigidBodyMotion& m = truth_now.motion;
    const Eigen::Vector3d v_b = m.v_b();
    std::size_t i = 0;
    for (int k = 0; k < 3; ++k) row[i++] = m.p_n[k];
    row[i++] = core::wrap_2pi(m.theta.z());
    row[i++] = m.theta.x();
    row[i++] = m.theta.y();
    for (int k = 0; k < 3; ++k) row[i++] = v_b[k];
    for (int k = 0; k < 3; ++k) row[i++] = m.omega_nb_b[k];
    for (double n : truth_now.shaft_speed_rps) row[i++] = n;
    row[i++] = a.port.thrust;
    row[i++] = a.stb.thrust;
    row[i++] = a.tunnel.thrust;
    for (double p : truth_now.power_W) row[i++] = p;
    row[i++] = truth_now.rudder_rad[0];
    row[i++] = truth_now.rudder_rad[1];
    row[i++] = demand_pct.x() / 100.0;
    row[i++] = demand_pct.y() / 100.0;
    row[i++] = demand_pct.z() / 100.0;
    for (int k = 0; k < 3; ++k) row[i++] = lever_pct[k] / 100.0;
    row[i++] = truth_now.wind_speed_mps;
    row[i++] = truth_now.wind_from_rad;
    row[i++] = current_n.x();
    row[i++] = current_n.y();
    row[i++] = setpoint.x();
    row[i++] = setpoint.y();
    row[i++] = dp_active ? core::wrap_2pi(setpoint.z()) : core::kMissing;
    for (int k = 0; k < 3; ++k) row[i++] = dp_active ? bias_hat[k] : core::kMissing;
    const Eigen::Vector3d load_n = model::step_loads_n(loads, t);
    for (int k = 0; k < 3; ++k) row[i++] = load_n[k];
    truth_log.append_row(t, row);

    const std::span<double> measured(measured_row);
    sensor_logger.record(log_tick++, truth_now, measured.first(sensor_logger.channel_count()));
    i = sensor_logger.channel_count();
    for (int k = 0; k < 3; ++k) measured_row[i++] = demand_pct[k];
    for (int k = 0; k < 3; ++k) measured_row[i++] = lever_pct[k];
    measured_row[i++] = cmd.n_port * 60.0;
    measured_row[i++] = cmd.n_stb * 60.0;
    measured_row[i++] = cmd.n_tunnel * 60.0;
    for (int j : {model::ThrustConfiguration::kThrustPort, model::ThrustConfiguration::kThrustStb,
                  model::ThrustConfiguration::kTunnel}) {
      measured_row[i++] = last_forces[j] * 1e-3;
    }
    measured_row[i++] = core::rad_to_deg(cmd.rudder_port);
    measured_row[i++] = core::rad_to_deg(cmd.rudder_stb);
    measured_row[i++] = setpoint.x();
    measured_row[i++] = setpoint.y();
    measured_row[i++] = dp_active ? core::rad_to_deg(core::wrap_2pi(setpoint.z())) : core::kMissing;
    log.append_row(t, measured_row);
  });

  const sim::SimResult result = simulator.run(x0);
  if (!result.ok()) {
    throw std::runtime_error(fmt::format("simulation of '{}' stopped at t = {:.2f} s: {}",
                                         spec.name, result.final_time, result.message));
  }

  // True time constants the model defines (thesis tables 3.23–3.36 are what they compare to).
  nlohmann::json tc;
  const double x_rudder = vessel.layout.p_port_rudder_b.x();
  for (const double knots : {3.0, 6.0}) {
    const Hull::Nomoto n = plant.hull().nomoto(knots * 1852.0 / 3600.0, x_rudder);
    tc[fmt::format("nomoto_{:.0f}kn", knots)] = {
        {"T1_s", n.t1_s}, {"T2_s", n.t2_s}, {"T3_s", n.t3_s}, {"Tr_s", n.tr_s}};
  }
  tc["rudder_0_to_20deg"] =
      fopdt_json(model::rudder_step_truth(plant.rudder(), 0.0, core::deg_to_rad(20.0), dt));
  truth["time_constants"] = tc;
  truth["allocation_unmet_max"] = {unmet.max.x(), unmet.max.y(), unmet.max.z()};
  truth["units"] = "SI unless a key names its unit";
  truth["start_utc"] = spec.start_utc;
  ScenarioRun run;
  run.log = std::move(log);
  run.truth_log = std::move(truth_log);
  run.truth = std::move(truth);
  run.start_utc = spec.start_utc;
  run.geoid_separation_m = vessel.sensors.origin.height_m;
  return run;
}

}  // namespace dynpos::scenario
