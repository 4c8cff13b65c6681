#pragma once
/// \file
/// The control task of a scenario run, at the joystick's control rate: the operator's lever
/// through the lever curve (with auto heading, control/heading_hold.hpp) or, in DP mode, the DP
/// loop (dp_task.hpp) makes the demand τ_d; the thrust allocation turns it into actuator
/// commands; manual rudder steps override the rudders. It keeps the commands it gives (which
/// the actuators' dead times and the loggers read) and the truth of what it did: each joystick
/// command, each propeller step with its Smith truth, the rudder steps and setpoints.
///
/// A vessel with a [[thruster]] layout is allocated by model::LayoutAllocator (an azimuth the
/// optimum sends across a forbidden sector the short way is held within a quarter turn of where
/// it points while that meets the demand, so it does not swing from one edge of the sector to
/// the other), each unit's force turned into its orders (model/unit_drive.hpp): shaft speed for
/// the thrust, an azimuth's direction (kept while its thrust is below 1 % of its rating, so an idle
/// unit does not swing about) and a rudder's angle. An azimuth's shaft speed order is cut by cos of
/// the angle it still has to turn (none beyond 90°), as DP systems do, so that it does not push the
/// wrong way while it slews.
///
/// The run starts from an InitialTrim: at rest, or at the scenario's initial surge speed with
/// the main propellers at the shaft speed that holds it and the lever that demands it.

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "dynpos/control/heading_hold.hpp"
#include "dynpos/model/layout_allocator.hpp"
#include "dynpos/model/thrust_allocation.hpp"
#include "dynpos/model/thruster.hpp"
#include "dynpos/scenario/actuator_commands.hpp"
#include "dynpos/scenario/dp_estimator.hpp"
#include "dynpos/scenario/dp_task.hpp"
#include "dynpos/scenario/operator_commands.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/trial_truth.hpp"
#include "dynpos/scenario/unit_failure.hpp"
#include "dynpos/scenario/vessel_config.hpp"
#include "dynpos/scenario/vessel_plant.hpp"

namespace dynpos::scenario {

/// The state and commands a run starts from.
struct InitialTrim {
  Eigen::VectorXd x0;                                   ///< the plant's initial state (VesselPlant)
  Eigen::Vector3d lever_pct = Eigen::Vector3d::Zero();  ///< the lever (surge, sway, yaw) [%]
  Eigen::Vector3d demand_pct = Eigen::Vector3d::Zero();  ///< its demand [% of the maxima]
  ActuatorCommands commands;                             ///< held before t = 0
};

/// The trim of `spec` on `plant` (see the file comment): surge speed u₀ with the lever that
/// demands the hull's resistance X(u₀), both main propellers at the shaft speed giving half of
/// it, in their steady state at advance speed u₀.
InitialTrim initial_trim(const ScenarioSpec& spec, const VesselConfig& vessel,
                         const VesselPlant& plant);

/// The control task (see the file comment).
class ControlTask {
 public:
  /// The control of `spec` on `vessel` and its `plant`, from `trim`; `seed` is the run's master
  /// seed (the DP system's measurement noise and waves); `wind` the run's wind, which the DP
  /// observer's wind feedforward measures (nullptr: none; it must outlive the task). Throws
  /// std::invalid_argument on bad heading-hold or DP parameters, core::InputError on a failure
  /// the vessel does not have.
  ControlTask(const ScenarioSpec& spec, const VesselConfig& vessel, const VesselPlant& plant,
              const InitialTrim& trim, std::uint64_t seed, const model::Wind* wind = nullptr);

  /// One control step at scenario time t [s] with the plant's state x (its low-frequency
  /// motion) and held input u: DP runs on what the scenario's observer makes of it
  /// (dp_estimator.hpp); the joystick modes on the low-frequency motion.
  void step(double t, const sim::ConstVectorRef& x, const sim::ConstVectorRef& u);

  /// The period of the control steps [s], 1/control_rate_hz.
  double period_s() const noexcept { return period_s_; }

  /// The lever (surge, sway, yaw) as the operator set it [% of full deflection].
  const Eigen::Vector3d& lever_pct() const noexcept { return joystick_.lever_pct(); }
  /// The demand the lever makes (with auto heading, its moment) [% of the joystick maxima].
  const Eigen::Vector3d& demand_pct() const noexcept { return demand_pct_; }
  /// The actuator commands of the last step, before their dead times.
  const ActuatorCommands& commands() const noexcept { return commands_; }
  /// The forces f = (T₁, T₂, Y₁, Y₂, T₃) [N] of the last allocation.
  const Eigen::Matrix<double, 5, 1>& forces_N() const noexcept { return forces_N_; }
  /// The plant the task commands.
  const VesselPlant& plant() const noexcept { return plant_; }
  /// True once a DP setpoint is in force.
  bool dp_active() const noexcept { return dp_ && dp_->active(); }
  /// The DP setpoint in force (N, E, ψ) [m, m, rad]; core::kMissing outside DP.
  const Eigen::Vector3d& setpoint_n() const noexcept;
  /// The DP bias estimate b̂ (NED) [N, N, N·m]; zero outside DP.
  const Eigen::Vector3d& bias_hat_n() const noexcept;
  /// The DP controller's demand τ_d (5.38) of the last step (BODY) [N, N, N·m]; zero outside DP.
  const Eigen::Vector3d& dp_demand_b() const noexcept { return dp_demand_b_; }
  /// The DP system's measurement and observer; nullptr outside DP.
  const DpEstimator* estimator() const noexcept { return estimator_ ? &*estimator_ : nullptr; }
  /// The run's failure as it happens, if it has one.
  const std::optional<UnitFailure>& failure() const noexcept { return failure_; }

  /// Writes what the task did into `truth`: commands, propeller_steps, rudder_steps,
  /// setpoints, hybrid (with hybrid integral action) and allocation_unmet_max.
  void write_truth(TrialTruth& truth) const;

 private:
  void record_command(double t, const ActuatorCommands& before, const Eigen::Vector3d& demand_b,
                      const Eigen::Vector3d& tau_unmet_b);
  // A layout's allocation of tau_d_b at state x into commands_.units; its unmet part.
  model::LayoutAllocation allocate_units(const Eigen::Vector3d& tau_d_b,
                                         const sim::ConstVectorRef& x);
  // From the failure's detection on: the allocation without the failed units (once).
  void apply_failure(double t);

  JoystickParams joystick_params_;
  double period_s_;
  double dt_s_;
  model::Thruster propeller_;  // the main propellers' model, for their step truth
  model::ThrustAllocator allocator_;
  const VesselPlant& plant_;
  std::optional<model::LayoutAllocator> layout_allocator_;  // a [[thruster]] layout's
  JoystickSchedule joystick_;
  RudderSchedule rudder_;
  std::optional<control::HeadingHold> heading_hold_;
  std::optional<DpTask> dp_;
  std::optional<DpEstimator> estimator_;
  std::optional<UnitFailure> failure_;
  bool failure_applied_ = false;
  model::ThrustAllocationOptions allocation_options_;  // the vessel's, for a failure
  std::vector<double> capacity_;                       // a layout's units' capacity now
  Eigen::Vector3d dp_demand_b_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d demand_pct_;
  ActuatorCommands commands_;
  Eigen::Matrix<double, 5, 1> forces_N_ = Eigen::Matrix<double, 5, 1>::Zero();
  Eigen::Vector3d unmet_max_ = Eigen::Vector3d::Zero();
  std::vector<CommandTruth> command_truth_;
  std::vector<PropellerStepTruth> propeller_steps_;
};

}  // namespace dynpos::scenario
