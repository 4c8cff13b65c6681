#pragma once
/// \file
/// The trial logger of a run (log.csv): every sensor of the vessel at its own rate with its
/// noise and latency (missing between its samples), then the operator's lever and demand, the
/// actuator commands and the DP setpoint, in the units real loggers use (deg, rpm, kW, kN;
/// channels in docs/log-format.md).

#include <cstdint>
#include <memory>
#include <vector>

#include "dynpos/core/log.hpp"
#include "dynpos/scenario/control_task.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/vessel_config.hpp"
#include "dynpos/scenario/vessel_plant.hpp"
#include "dynpos/scenario/vessel_sample.hpp"

namespace dynpos::scenario {

namespace detail {
class SensorLogger;
}

/// Records the trial log of a run (see the file comment).
class TrialLogger {
 public:
  /// Declares the channels in `log` (new); the sensors of `vessel` with noise streams from
  /// `seed`, on the log rate of `spec`. `log` and `control` must outlive the logger. Throws
  /// core::InputError naming the vessel file (or the scenario's) if a sensor's rate or latency
  /// does not fit the log's tick grid.
  TrialLogger(core::Log& log, const ScenarioSpec& spec, const VesselConfig& vessel,
              const VesselPlant& plant, std::uint64_t seed, const ControlTask& control);
  ~TrialLogger();
  TrialLogger(const TrialLogger&) = delete;
  TrialLogger& operator=(const TrialLogger&) = delete;

  /// Appends the row at scenario time t [s]: the sensors on `sample` (log ticks are
  /// consecutive from the first call) and the control task's outputs now.
  void record(double t, const VesselSample& sample);

 private:
  void record_setpoint(std::size_t i);  // the last three columns, from row_[i]

  core::Log& log_;
  const ControlTask& control_;
  std::vector<DropoutEvent> gnss_dropouts_;  // the scenario's: no GNSS fix is logged in them
  std::unique_ptr<detail::SensorLogger> sensors_;
  std::size_t tick_ = 0;
  std::vector<double> row_;
};

}  // namespace dynpos::scenario
