#include "dynpos/sim/log_recorder.hpp"

#include <stdexcept>
#include <utility>

namespace dynpos::sim {

RecordedSignal state_signal(std::string name, std::string unit, Eigen::Index index) {
  return RecordedSignal{std::move(name), std::move(unit), core::Interp::kLinear,
                        [index](const TaskContext& context) { return context.state()(index); }};
}

RecordedSignal input_signal(std::string name, std::string unit, Eigen::Index index) {
  return RecordedSignal{std::move(name), std::move(unit), core::Interp::kHold,
                        [index](const TaskContext& context) { return context.input()(index); }};
}

LogRecorder::LogRecorder(core::Log& log, std::vector<RecordedSignal> signals)
    : log_(log), signals_(std::move(signals)), row_(signals_.size()) {
  if (!log_.empty() || !log_.channels().empty()) {
    throw std::invalid_argument("LogRecorder: the log must be new (no channels and no rows)");
  }
  for (const RecordedSignal& signal : signals_) {
    if (!signal.value) {
      throw std::invalid_argument("LogRecorder: signal '" + signal.name +
                                  "' has no value function");
    }
    log_.declare_channel(signal.name, signal.unit, signal.interp);
  }
}

void LogRecorder::record(const TaskContext& context) {
  for (std::size_t i = 0; i < signals_.size(); ++i) row_[i] = signals_[i].value(context);
  log_.append_row(context.time(), row_);
}

void LogRecorder::attach(Simulator& simulator, double period_s) {
  simulator.add_periodic_task("log", period_s, 0.0,
                              [this](TaskContext& context) { record(context); });
}

}  // namespace dynpos::sim
