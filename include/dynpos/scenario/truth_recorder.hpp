#pragma once
/// \file
/// The truth log of a run (truth.csv): one row per log tick with the true motion, the
/// actuators' states, the operator's lever and the demand it makes, the weather, the DP
/// setpoint and bias estimate and the loads, in SI units (channels in docs/log-format.md).
///
/// Built on sim::LogRecorder: each channel is a sim::RecordedSignal that reads the tick's
/// VesselSample or the control task's held outputs.

#include <Eigen/Core>
#include <vector>

#include "dynpos/core/log.hpp"
#include "dynpos/scenario/control_task.hpp"
#include "dynpos/scenario/vessel_sample.hpp"
#include "dynpos/sim/log_recorder.hpp"

namespace dynpos::scenario {

/// Records the truth log of a run (see the file comment).
class TruthRecorder {
 public:
  /// Declares the truth channels in `log` (new: no channels, no rows); `log` and `control`
  /// must outlive the recorder.
  TruthRecorder(core::Log& log, const ControlTask& control);
  TruthRecorder(const TruthRecorder&) = delete;  // the signals refer to this recorder
  TruthRecorder& operator=(const TruthRecorder&) = delete;

  /// Appends the row at context.time() (scenario time) from `sample` and the control task's
  /// outputs now.
  void record(const sim::TaskContext& context, const VesselSample& sample);

 private:
  std::vector<sim::RecordedSignal> signals();
  std::vector<sim::RecordedSignal> motion_signals();
  std::vector<sim::RecordedSignal> actuator_signals();
  std::vector<sim::RecordedSignal> unit_signals();
  std::vector<sim::RecordedSignal> command_and_weather_signals();
  std::vector<sim::RecordedSignal> observer_signals();

  const ControlTask& control_;
  const VesselSample* sample_ = nullptr;           // the sample being recorded
  Eigen::Vector3d v_b_ = Eigen::Vector3d::Zero();  // its BODY velocity
  sim::LogRecorder recorder_;
};

}  // namespace dynpos::scenario
