#pragma once
/// \file
/// LogRecorder: a sink that appends simulator samples to a core::Log, one row per firing.
///
/// The recorder does no I/O: it fills an in-memory Log, which the caller writes out (io module)
/// after the run. It is attached to the simulator as an ordinary periodic task, so it samples
/// at t_k before the jumps of that tick (see the event order in simulator.hpp); add it after the
/// controller and sensor tasks to record their held outputs of the same tick.

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "dynpos/core/log.hpp"
#include "dynpos/sim/simulator.hpp"

namespace dynpos::sim {

/// One recorded channel: its name, unit and how to read its value at a tick.
struct RecordedSignal {
  std::string name;
  std::string unit;  ///< e.g. "m", "rad", "1"
  core::Interp interp = core::Interp::kLinear;
  std::function<double(const TaskContext&)> value;
};

/// The state component x[index] as a channel.
RecordedSignal state_signal(std::string name, std::string unit, Eigen::Index index);

/// The held input component u[index] as a channel (interpolated by zero-order hold).
RecordedSignal input_signal(std::string name, std::string unit, Eigen::Index index);

/// Appends rows of recorded signals to a Log it does not own.
class LogRecorder {
 public:
  /// Declares one channel per signal in `log`, which must have no channels and no rows and must
  /// outlive the recorder. Throws std::invalid_argument otherwise or if a signal has no value.
  LogRecorder(core::Log& log, std::vector<RecordedSignal> signals);

  /// Appends one row at t = context.time() with every signal's value.
  void record(const TaskContext& context);

  /// Adds a task named "log" to `simulator` that calls record() every period_s [s] from t = 0.
  /// The recorder must outlive the simulator's runs; one run per log (times must increase).
  void attach(Simulator& simulator, double period_s);

 private:
  core::Log& log_;
  std::vector<RecordedSignal> signals_;
  std::vector<double> row_;
};

}  // namespace dynpos::sim
