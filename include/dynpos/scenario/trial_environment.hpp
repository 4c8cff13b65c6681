#pragma once
/// \file
/// The weather and water of a run: current, wind, the bias (2.22) and waves from the scenario's
/// environment and the vessel's variation and response models, each with its own seeded
/// stream (model/environment.hpp, model/sea_state.hpp), and the scenario's step loads.
///
/// The simulator advances it: an every-tick task calls step(), which moves the current, wind
/// and bias one tick on (sample and hold) and writes the environment's part of the plant's
/// held input (VesselPlant::kTauEnvBody, kForceNed, kCurrentNed). The wave-frequency motion is
/// only needed where the loggers sample it, so the wave generator runs on the log grid: step()
/// moves it to the sample of each tick the loggers record at (TrialClock::logs_at), before
/// they read it.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "dynpos/model/environment.hpp"
#include "dynpos/model/sea_state.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/trial_clock.hpp"
#include "dynpos/scenario/vessel_config.hpp"
#include "dynpos/sim/hybrid_system.hpp"

namespace dynpos::scenario {

/// The sea state of `env`: its waves (H_s, T_p, direction, components).
model::SeaStateParams sea_state(const EnvironmentSpec& env);

/// The environment of a run (see the file comment).
class TrialEnvironment {
 public:
  /// The environment of `spec` on `vessel` with master seed `seed`, on the ticks of `clock`.
  TrialEnvironment(const ScenarioSpec& spec, const VesselConfig& vessel, std::uint64_t seed,
                   const TrialClock& clock);

  /// Simulator tick k with the plant's state x (VesselPlant): advances every source and writes
  /// the wind and wave-drift force (BODY), the bias and step loads (NED) and the current (NED)
  /// into the held input u.
  void step(sim::Tick k, const sim::ConstVectorRef& x, sim::VectorRef u);

  const model::Wind& wind() const noexcept { return wind_; }
  /// The wave generator, at the sample of the last tick the loggers record at.
  const model::WaveMotion& waves() const noexcept { return waves_; }
  /// The scenario's step loads at scenario time t [s] (NED) [N, N, N·m].
  Eigen::Vector3d load_n(double t) const noexcept { return model::step_loads_n(loads_, t); }

 private:
  TrialClock clock_;
  model::Current current_;
  model::Wind wind_;
  model::Bias bias_;
  model::WaveMotion waves_;
  std::vector<model::StepLoad> loads_;
  bool waves_sampled_ = false;
};

}  // namespace dynpos::scenario
