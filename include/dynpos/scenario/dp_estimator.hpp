#pragma once
/// \file
/// What the DP controller of a run sees (ScenarioSpec::observer). The DP system measures the
/// control origin's position (its GNSS, corrected to the control origin) and heading (its gyro):
/// the low-frequency motion plus the wave-frequency motion of the run's sea (the same wave
/// components as the loggers', sampled at the control rate) plus white noise of the vessel's first
/// GNSS receiver and its gyro; a GNSS dropout (ScenarioSpec::gnss_dropouts) leaves the position
/// missing. Its rate gyro (the first MRU's) measures the yaw rate, LF plus WF, with the MRU's rate
/// noise; the EKF uses it. The observer (control/passive_observer.hpp, control/ekf_observer.hpp)
/// filters it with the thrust the actuators give (the DP system's thrust feedback) on the
/// controller's model M, D and the wave peak frequency 2π/T_p of the scenario's sea.
///
/// "ideal" hands the controller the true low-frequency motion; "raw" the measurement itself with
/// the measured velocity (low- plus wave-frequency), as a DP system without a wave filter would.

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <variant>

#include "dynpos/control/ekf_observer.hpp"
#include "dynpos/control/observer.hpp"
#include "dynpos/control/passive_observer.hpp"
#include "dynpos/model/sea_state.hpp"
#include "dynpos/scenario/scenario_spec.hpp"
#include "dynpos/scenario/vessel_config.hpp"
#include "dynpos/scenario/vessel_plant.hpp"
#include "dynpos/sim/noise.hpp"

namespace dynpos::scenario {

/// The observer model of the DP controller of `vessel` (M, D as dp_controller_params) with the
/// wave model at the peaks of `sea`'s wave-frequency motion (model::response_peak_frequency):
/// what a DP system sets from the peak period its operator enters.
control::ObserverModel observer_model(const VesselConfig& vessel, const model::Hull& hull,
                                      const model::SeaStateParams& sea);

/// observer_model() in the sea of `spec`.
control::ObserverModel observer_model(const ScenarioSpec& spec, const VesselConfig& vessel,
                                      const model::Hull& hull);

/// The motion the DP controller runs on.
struct DpMotion {
  Eigen::Vector3d eta_n = Eigen::Vector3d::Zero();  ///< (N, E, ψ) [m, m, rad]
  Eigen::Vector3d nu_b = Eigen::Vector3d::Zero();   ///< (u, v, r) BODY [m/s, m/s, rad/s]
};

/// The DP system's measurement and observer (see the file comment).
class DpEstimator {
 public:
  /// For `spec` on `plant` with master seed `seed`, stepped every period_s [s] from η₀.
  DpEstimator(const ScenarioSpec& spec, const VesselConfig& vessel, const VesselPlant& plant,
              std::uint64_t seed, double period_s, const Eigen::Vector3d& eta0_n);

  /// The control step at scenario time t [s] (≥ 0, on the control grid) with the plant's state x
  /// and held input u: measures, steps the observer, and returns what the controller runs on.
  DpMotion update(double t, const sim::ConstVectorRef& x, const sim::ConstVectorRef& u);

  control::ObserverKind kind() const noexcept { return kind_; }
  /// The observer's estimate; nullopt for "ideal" and "raw".
  std::optional<control::ObserverEstimate> estimate() const;

 private:
  // The measurement y = (N, E, ψ) at t; position NaN during a GNSS dropout. Sets wf_velocity_b_.
  Eigen::Vector3d measure(double t, const sim::ConstVectorRef& x);

  std::vector<DropoutEvent> gnss_dropouts_;  // the scenario's
  const VesselPlant& plant_;
  control::ObserverKind kind_;
  double period_s_;
  model::WaveMotion waves_;
  long sample_ = -1;  // the wave generator's sample
  sim::WhiteNoise north_noise_, east_noise_, heading_noise_, rate_noise_;
  double yaw_rate_ = 0.0;  // the rate gyro's at the last measurement [rad/s]
  Eigen::Vector3d wf_velocity_b_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d last_raw_ = Eigen::Vector3d::Zero();  // "raw": the last measured position
  std::variant<std::monostate, control::PassiveObserver, control::EkfObserver> observer_;
};

}  // namespace dynpos::scenario
