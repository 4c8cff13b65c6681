#pragma once
/// \file
/// A third-order reference model for DP setpoint changes (Fossen 2011, ch. 12): per DOF
///
///     x⃛_d + (2ζ+1)ω ẍ_d + (2ζ+1)ω² ẋ_d + ω³ x_d = ω³ r
///
/// with the velocity ẋ_d limited, so a 50 m setpoint change is sailed at a steady speed. The
/// heading is taken the short way round (the setpoint is unwrapped next to the current ψ_d).

#include <Eigen/Core>

#include "dynpos/control/dp_controller.hpp"

namespace dynpos::control {

struct ReferenceModelParams {
  Eigen::Vector3d omega{0.05, 0.05, 0.08};    ///< ω [rad/s] (N, E, ψ). Source: reasoned, slower
                                              ///< than the DP loop (≈ 0.1 rad/s).
  double zeta = 1.0;                          ///< ζ [-], 1 = critically damped (no overshoot)
  Eigen::Vector3d max_rate{0.5, 0.5, 0.035};  ///< |ẋ_d| limits [m/s, m/s, rad/s]. Source:
                                              ///< reasoned — ≈ 1 kn and 2 °/s, DP practice.
  void validate() const;
};

/// State (x_d, ẋ_d, ẍ_d) per DOF; advance with step().
class ReferenceModel {
 public:
  explicit ReferenceModel(const ReferenceModelParams& params, const Eigen::Vector3d& eta0);
  /// Advances by dt [s] towards setpoint r = (N, E, ψ) [m, m, rad] (10 explicit substeps).
  void step(const Eigen::Vector3d& setpoint, double dt);
  /// Resets to rest at η.
  void reset(const Eigen::Vector3d& eta);
  DpReference reference() const;
  /// At rest: every |ẋ_d| within `fraction` of its max_rate (e.g. 0.01), i.e. the reference has
  /// finished a setpoint change and the DP loop is stationkeeping.
  bool at_rest(double fraction) const noexcept;

 private:
  ReferenceModelParams params_;
  Eigen::Vector3d x_, v_, a_;
};

/// The "setpoint reached" test of the DP 4-corner maneuver (thesis 3.5.2): inside a circle of
/// radius_m around the setpoint and with heading within heading_tol_rad.
struct OperatingCircle {
  double radius_m = 2.0;           ///< Source: reasoned — the thesis gives no value; 2 m is a
                                   ///< common DP operating-circle setting for a small vessel.
  double heading_tol_rad = 0.035;  ///< ≈ 2°. Source: reasoned, as radius_m.
  bool reached(const Eigen::Vector3d& eta, const Eigen::Vector3d& setpoint) const;
};

}  // namespace dynpos::control
