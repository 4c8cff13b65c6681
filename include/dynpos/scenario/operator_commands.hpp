#pragma once
/// \file
/// The operator's commands of a run, each a schedule the control task asks at every control
/// step: the joystick lever, manual rudder steps and DP setpoints (ScenarioSpec). A command is
/// due at the first control step at or after its time (within 1e-9 s of rounding). The rudder
/// and setpoint schedules also keep the truth of what they did (trial_truth.hpp).

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "dynpos/control/reference_model.hpp"
#include "dynpos/model/hull.hpp"
#include "dynpos/model/rudder.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/trial_truth.hpp"

namespace dynpos::scenario {

/// The joystick lever over a run: each JoystickCommand holds from its time on.
class JoystickSchedule {
 public:
  /// Commands sorted by time; the lever starts at initial_lever_pct (surge, sway, yaw) [%].
  JoystickSchedule(std::vector<JoystickCommand> commands, const Eigen::Vector3d& initial_lever_pct);

  /// Applies every command due at t [s]; true if one was.
  bool advance(double t);

  /// The lever (surge, sway, yaw) in % of full deflection.
  const Eigen::Vector3d& lever_pct() const noexcept { return lever_pct_; }

 private:
  std::vector<JoystickCommand> commands_;
  std::size_t next_ = 0;
  Eigen::Vector3d lever_pct_;
};

/// Manual rudder steps: both rudders held at the commanded angle over the allocation's, until
/// a release. Each step (not a release) is recorded with the servo's Smith truth from the angle
/// the rudders were commanded to before it, and the hull's Nomoto truth at the surge speed of
/// the step when above 0.1 m/s.
class RudderSchedule {
 public:
  /// Commands sorted by time, for `rudder` (its servo and angle limit), `hull` (Nomoto) with
  /// the rudders x_rudder_m [m] from the control origin; dt_s [s] is the step of the servo
  /// truth's simulation.
  RudderSchedule(std::vector<RudderCommand> commands, const model::Rudder& rudder,
                 const model::Hull& hull, double x_rudder_m, double dt_s);

  /// Applies every command due at t [s]. rudder_before_rad [rad] is the rudder command of the
  /// previous control step (a step starts there unless an override was in force) and
  /// surge_mps [m/s] the surge speed now. Returns the angle that overrides both rudders'
  /// commands [rad] (not limited: the servo limits it), or nothing.
  const std::optional<double>& advance(double t, double rudder_before_rad, double surge_mps);

  const std::optional<double>& override_rad() const noexcept { return override_rad_; }
  const std::vector<RudderStepTruth>& steps() const noexcept { return steps_; }

 private:
  std::vector<RudderCommand> commands_;
  model::Rudder rudder_;
  model::Hull hull_;
  double x_rudder_m_;
  double dt_s_;
  std::size_t next_ = 0;
  std::optional<double> override_rad_;
  std::vector<RudderStepTruth> steps_;
};

/// DP setpoints: a timed setpoint applies at its time, an untimed one (t_s < 0) when the
/// vessel is inside the operating circle of the one in force (thesis 3.5.2). Each applied
/// setpoint is recorded with its start, its end and the first time its circle was reached.
class SetpointSchedule {
 public:
  explicit SetpointSchedule(std::vector<SetpointCommand> setpoints,
                            const control::OperatingCircle& circle = {});

  /// Applies the setpoints due at t [s] with the low-frequency position η = (N, E, ψ)
  /// [m, m, rad], and records when the one in force is first reached.
  void advance(double t, const Eigen::Vector3d& eta_n);

  /// True once a setpoint is in force.
  bool active() const noexcept { return active_; }
  /// The setpoint in force (N, E, ψ) [m, m, rad]; core::kMissing before the first.
  const Eigen::Vector3d& setpoint_n() const noexcept { return setpoint_n_; }
  const std::vector<SetpointTruth>& legs() const noexcept { return legs_; }

 private:
  void apply(const SetpointCommand& setpoint, double t);

  std::vector<SetpointCommand> setpoints_;
  control::OperatingCircle circle_;
  std::size_t next_ = 0;
  bool active_ = false;
  Eigen::Vector3d setpoint_n_;
  std::vector<SetpointTruth> legs_;
};

}  // namespace dynpos::scenario
