#pragma once
/// \file
/// The thrust a DP system knows from its actuators' feedback (what its observer is given):
/// τ_b = (X, Y, N) in BODY from each unit's logged thrust and steering angle, by the vessel's own
/// actuator models, as the simulator makes the force (vessel_plant.hpp).
///
/// A [[thruster]] layout: a unit's thrust T gives its shaft speed (UnitDrive::shaft_speed_for)
/// and UnitDrive::outputs() its force at the logged angle: an azimuth T·(cos α, sin α) times its
/// loss factor at α, a propeller with a rudder T ahead and the side force (κ·max(T, 0) + c)·δ/δ_max
/// at the rudder, a tunnel T to starboard (2.2).
///
/// The model's own units (the 2014 Gunnerus): T₁, T₂ the propellers' thrust along x, T₃ the
/// tunnel's side force, and each rudder's lift and drag from its model (model/rudder.hpp) at the
/// logged angle δ in its propeller's slipstream at T₁ (T₂), with the vessel at rest in the water;
/// τ by (2.37). The inflow is not logged (the current is what is being estimated), and at DP
/// speeds the slipstream carries the rudder: its dynamic pressure η·4T/(πD²) is 2.2 kPa at 10 kN
/// on the Gunnerus, ½ρV² 0.13 kPa at 0.5 m/s. A propeller going astern gives no slipstream over
/// its rudder, which then makes no force at rest.

#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

#include "dynpos/model/rudder.hpp"
#include "dynpos/model/thrust_configuration.hpp"
#include "dynpos/model/unit_drive.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::scenario {

/// The feedback of one unit: the log roles (docs/log-format.md) of its thrust and its angle.
struct FeedbackChannel {
  std::string unit;         ///< "port", "stb", "tunnel" or a layout unit's name
  std::string thrust_role;  ///< "thrust.NAME" [N]
  std::string angle_role;   ///< "rudder.NAME" or "azimuth.NAME" [rad]; empty: the unit has none
};

/// τ_b of a vessel's actuators from their feedback (see the file comment).
class ThrustFeedback {
 public:
  /// The units of `vessel`: its [[thruster]] layout, else the model's port, stb and tunnel.
  explicit ThrustFeedback(const VesselConfig& vessel);

  /// One per unit, in layout order (the model: port, stb, tunnel).
  const std::vector<FeedbackChannel>& channels() const noexcept { return channels_; }

  /// τ_b (X [N], Y [N], N [N·m]) from each unit's thrust [N] (signed: ahead, to starboard) and
  /// angle [rad] (ignored for a unit without one), in channels() order. Throws
  /// std::invalid_argument when a span's length is not the number of units.
  Eigen::Vector3d tau_b(std::span<const double> thrust_N, std::span<const double> angle_rad) const;

 private:
  Eigen::Vector3d model_tau_b(std::span<const double> thrust_N,
                              std::span<const double> angle_rad) const;

  std::vector<FeedbackChannel> channels_;
  model::Rudder rudder_;
  model::ThrustConfiguration layout_;
  std::vector<model::UnitDrive> drives_;  // a layout's units; empty: the model's
};

}  // namespace dynpos::scenario
