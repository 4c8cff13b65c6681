#include "dynpos/scenario/runner.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dynpos/core/angle.hpp"
#include "dynpos/core/error.hpp"
#include "dynpos/ident/failure_test.hpp"
#include "dynpos/model/rudder.hpp"
#include "dynpos/scenario/actuator_commands.hpp"
#include "dynpos/scenario/control_task.hpp"
#include "dynpos/scenario/trial_clock.hpp"
#include "dynpos/scenario/trial_environment.hpp"
#include "dynpos/scenario/trial_logger.hpp"
#include "dynpos/scenario/truth_recorder.hpp"
#include "dynpos/scenario/vessel_plant.hpp"
#include "dynpos/scenario/vessel_sample.hpp"
#include "dynpos/sim/sim_time.hpp"
#include "dynpos/sim/simulator.hpp"

namespace dynpos::scenario {
namespace {

// The control task ticks on the scenario's grid: its period (vessel file) must be a whole
// number of dt_s (scenario), by the simulator's own rule (sim::TimeGrid).
void check_control_rate(const ScenarioSpec& spec, const VesselConfig& vessel) {
  const double rate_hz = vessel.joystick.control_rate_hz;
  try {
    (void)sim::TimeGrid(spec.dt_s).ticks_for_rate(rate_hz, "control");
  } catch (const std::invalid_argument&) {
    throw core::InputError(
        {vessel.source.empty() ? spec.source : vessel.source, {}, {}, "joystick.control_rate_hz"},
        fmt::format("{} Hz: the control period 1/{} s is not a whole number of the scenario's "
                    "time step dt_s = {} s",
                    rate_hz, rate_hz, spec.dt_s),
        "give a rate whose period is a whole number of steps, e.g. 1, 2, 4, 5 or 10 Hz");
  }
}

// True time constants the model defines (thesis tables 3.23–3.36 are what they compare to).
TimeConstantsTruth time_constants(const VesselConfig& vessel, const VesselPlant& plant,
                                  double dt_s) {
  // The rudder's lever of the Nomoto gain; a layout's aftmost unit stands for it.
  double x_rudder = vessel.layout.p_port_rudder_b.x();
  for (std::size_t k = 0; k < vessel.thrusters.size(); ++k) {
    x_rudder = k == 0 ? vessel.thrusters[k].x_m : std::min(x_rudder, vessel.thrusters[k].x_m);
  }
  const auto nomoto_at = [&](double knots) {
    return nomoto_truth(plant.hull().nomoto(knots * 1852.0 / 3600.0, x_rudder));
  };
  TimeConstantsTruth tc;
  tc.nomoto_3kn = nomoto_at(3.0);
  tc.nomoto_6kn = nomoto_at(6.0);
  if (!plant.drives().empty()) {  // the model's rudder is not on board
    tc.rudder_0_to_20deg = {core::kMissing, core::kMissing};
    return tc;
  }
  tc.rudder_0_to_20deg =
      model::rudder_step_truth(plant.rudder(), 0.0, core::deg_to_rad(20.0), dt_s);
  return tc;
}

// The failure of a run and the response of the control origin's true motion `track` to it.
FailureTruth failure_truth(const UnitFailure& failure, const VesselConfig& vessel,
                           const ident::FailureTestInput& track) {
  const ident::FailureEvent e = ident::failure_excursion(track, failure.time_s());
  FailureTruth f;
  f.time_s = failure.time_s();
  f.unit = failure.name();
  f.units = failure.units(vessel);
  f.footprint_m = e.footprint_m.value_or(core::kMissing);
  f.peak_excursion_m = e.peak_excursion_m.value_or(core::kMissing);
  f.time_to_peak_s = e.time_to_peak_s.value_or(core::kMissing);
  f.recovery_s = e.recovery_s;
  f.peak_heading_deg = core::rad_to_deg(e.peak_heading_rad.value_or(core::kMissing));
  return f;
}

// The truth of a finished run: its inputs, what the control task did, the model's constants.
TrialTruth trial_truth(const ScenarioSpec& spec, const VesselConfig& vessel, std::uint64_t seed,
                       const VesselPlant& plant, const ControlTask& control) {
  TrialTruth truth;
  truth.seed = seed;
  truth.scenario = trial_scenario(spec);
  truth.vessel = vessel.to_json();
  for (const sensors::GnssParams& g : vessel.sensors.gnss) truth.lever_arms[g.name] = g.lever_arm_b;
  for (const sensors::MruParams& m : vessel.sensors.mru) truth.lever_arms[m.name] = m.lever_arm_b;
  truth.mru_acceleration = vessel.sensors.mru_acceleration;
  control.write_truth(truth);
  truth.time_constants = time_constants(vessel, plant, spec.dt_s);
  truth.start_utc = spec.start_utc;
  truth.observer = std::string(control::observer_name(spec.observer));
  return truth;
}

// The run, its rows kept (sink empty) or handed to `sink` every `block_rows` rows and at the end.
ScenarioRun simulate(const ScenarioSpec& spec, const VesselConfig& vessel, std::uint64_t seed,
                     const RunBlockSink& sink, std::size_t block_rows) {
  spec.validate();
  vessel.validate();
  check_simulated(vessel, spec);
  const VesselPlant plant(vessel);
  const TrialClock clock(spec);
  TrialEnvironment environment(spec, vessel, seed, clock);
  const InitialTrim trim = initial_trim(spec, vessel, plant);
  ActuatorDelays delays(vessel, spec.dt_s, trim.commands);
  check_control_rate(spec, vessel);
  ControlTask control(spec, vessel, plant, trim, seed, &environment.wind());

  ScenarioRun run;
  TruthRecorder truth_recorder(run.truth_log, control);
  TrialLogger trial_logger(run.log, spec, vessel, plant, seed, control);
  const auto rows = static_cast<std::size_t>(std::floor(spec.duration_s * spec.log_rate_hz)) + 1;
  const std::size_t held = sink ? std::min(rows, std::max<std::size_t>(block_rows, 1)) : rows;
  run.truth_log.reserve(held);
  run.log.reserve(held);
  VesselSampler sampler(plant, environment);
  ident::FailureTestInput track;  // the control origin's true motion, for a failure's truth
  const auto hand_over = [&] {
    sink(run.log, run.truth_log);
    run.log.clear_rows();
    run.truth_log.clear_rows();
  };

  // The event order of a tick (sim/simulator.hpp): control at its rate, then the actuators'
  // dead times and the environment every tick (sample and hold), then the loggers at theirs.
  sim::SimulatorOptions options;
  options.dt = spec.dt_s;
  options.end_time = clock.end_time_s();
  sim::Simulator simulator(plant, options);
  simulator.add_periodic_task("control", control.period_s(), 0.0, [&](sim::TaskContext& c) {
    control.step(clock.time(c.tick()), c.state(), c.input());
  });
  simulator.add_every_tick_task("actuators", [&](sim::TaskContext& c) {
    delays.step(control.commands(), c.mutable_input());
    if (control.failure())
      control.failure()->cut(clock.time(c.tick()), c.state(), c.mutable_input());
  });
  simulator.add_every_tick_task("environment", [&](sim::TaskContext& c) {
    environment.step(c.tick(), c.state(), c.mutable_input());
  });
  simulator.add_periodic_task("log", clock.log_period_s(), 0.0, [&](sim::TaskContext& c) {
    if (!clock.logs_at(c.tick())) return;  // settling: nothing is logged
    const sim::TaskContext at = clock.scenario_context(c);
    const VesselSample& sample = sampler.sample(at.time(), c.state(), c.input());
    truth_recorder.record(at, sample);
    if (control.failure()) {
      track.t_s.push_back(at.time());
      track.north_m.push_back(sample.motion.p_n.x());
      track.east_m.push_back(sample.motion.p_n.y());
      track.heading_rad.push_back(sample.motion.theta.z());
    }
    trial_logger.record(at.time(), sample);
    if (sink && run.log.size() >= held) hand_over();
  });

  const sim::SimResult result = simulator.run(trim.x0);
  if (!result.ok()) {
    throw std::runtime_error(fmt::format("simulation of '{}' stopped at t = {:.2f} s: {}",
                                         spec.name, result.final_time, result.message));
  }
  if (sink && !run.log.empty()) hand_over();
  run.truth = trial_truth(spec, vessel, seed, plant, control);
  if (control.failure()) run.truth.failure = failure_truth(*control.failure(), vessel, track);
  run.start_utc = spec.start_utc;
  run.device_files = spec.device_files;
  run.geoid_separation_m = vessel.sensors.origin.height_m;
  return run;
}

}  // namespace

ScenarioRun run_scenario(const ScenarioSpec& spec, const VesselConfig& vessel, std::uint64_t seed) {
  return simulate(spec, vessel, seed, {}, 0);
}

ScenarioRun stream_scenario(const ScenarioSpec& spec, const VesselConfig& vessel,
                            std::uint64_t seed, const RunBlockSink& sink, std::size_t block_rows) {
  if (!sink) throw std::invalid_argument("stream_scenario: no sink");
  return simulate(spec, vessel, seed, sink, block_rows);
}

}  // namespace dynpos::scenario
