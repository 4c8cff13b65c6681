#pragma once
/// \file
/// The thrust configuration (2.37) of R/V Gunnerus before the retrofit: the map from actuator
/// forces to the generalised force τ_b = (X, Y, N) in BODY about the control origin.
///
/// BODY: x forward, y starboard, z down; N is positive about +z, i.e. it turns the bow to
/// starboard. A force (F_x, F_y) at (x, y) gives X = F_x, Y = F_y, N = x·F_y − y·F_x. So the port
/// propeller (y < 0) pushing ahead gives N > 0 (bow to starboard), the starboard one N < 0, and
/// the bow tunnel thruster pushing to starboard N > 0. In (2.37) the thesis writes the tunnel
/// moment as −l₃·F₃; with our explicit signed x the same physics reads +x₃·F₃ (x₃ > 0).
///
/// Linearised (extended thrust) form used by the allocation: f = (T₁, T₂, Y₁, Y₂, T₃), with
/// T₁, T₂ the port/starboard propeller thrusts along BODY x, Y₁, Y₂ the rudder side forces along
/// BODY y at the rudders (rudder drag neglected), T₃ the tunnel side force; τ = B·f.

#include <Eigen/Core>
#include <vector>

#include "dynpos/core/param_range.hpp"

namespace dynpos::model {

/// Actuator positions in BODY relative to the control origin. Defaults: R/V Gunnerus.
struct ThrustConfigurationParams {
  /// Port propeller position (x, y) [m]. Source: reasoned — 31 m vessel, propellers ≈ 2 m
  /// forward of the transom, shafts 5.4 m apart in a 9.6 m beam.
  Eigen::Vector2d p_port_propeller_b{-13.0, -2.7};
  /// Starboard propeller position (x, y) [m]. Source: mirror of the port propeller.
  Eigen::Vector2d p_stb_propeller_b{-13.0, 2.7};
  /// Port rudder position (centre of pressure) [m]. Source: reasoned — 1.5 m aft of the
  /// propeller, on the shaft line.
  Eigen::Vector2d p_port_rudder_b{-14.5, -2.7};
  /// Starboard rudder position [m]. Source: mirror of the port rudder.
  Eigen::Vector2d p_stb_rudder_b{-14.5, 2.7};
  /// Tunnel thruster position [m]. Source: as TunnelThrusterParams::x, on the centre line.
  Eigen::Vector2d p_tunnel_b{12.5, 0.0};

  /// Throws core::InputError naming the first bad field (outside its range, param_fields, or
  /// a layout that is not port/starboard symmetric in sign: port y < 0 < starboard y, tunnel x >
  /// rudder x).
  void validate() const;
};

/// The positions as the keys of the vessel file's [layout] section, each with its unit and range
/// (core/param_range.hpp): the one table validate(), the file reader and the docs use.
std::vector<core::ParamField> param_fields(ThrustConfigurationParams& params);

/// Forces produced by the actuators, each at its own position.
struct ActuatorForces {
  double thrust_port = 0.0;  ///< port propeller thrust along BODY x [N]
  double thrust_stb = 0.0;   ///< starboard propeller thrust along BODY x [N]
  Eigen::Vector2d rudder_port_b = Eigen::Vector2d::Zero();  ///< port rudder (F_x, F_y) [N]
  Eigen::Vector2d rudder_stb_b = Eigen::Vector2d::Zero();   ///< starboard rudder (F_x, F_y) [N]
  double tunnel = 0.0;                                      ///< tunnel side force along BODY y [N]
};

/// The thrust configuration: const geometry.
class ThrustConfiguration {
 public:
  using Matrix = Eigen::Matrix<double, 3, 5>;
  using Forces = Eigen::Matrix<double, 5, 1>;  ///< f = (T₁, T₂, Y₁, Y₂, T₃)
  static constexpr int kThrustPort = 0;
  static constexpr int kThrustStb = 1;
  static constexpr int kRudderPort = 2;
  static constexpr int kRudderStb = 3;
  static constexpr int kTunnel = 4;

  explicit ThrustConfiguration(const ThrustConfigurationParams& params = {});

  const ThrustConfigurationParams& params() const noexcept { return params_; }

  /// τ_b = Σ (F_x, F_y, x·F_y − y·F_x) over all actuators, the full form of (2.37).
  Eigen::Vector3d tau(const ActuatorForces& forces) const noexcept;

  /// The linearised configuration matrix B ∈ ℝ^{3×5} with τ = B·f (file comment).
  const Matrix& matrix() const noexcept { return B_; }

  /// The water-relative velocity (u, v) at point p_b [m] for body velocity (u, v, r):
  /// (u − y·r, v + x·r).
  static Eigen::Vector2d velocity_at(const Eigen::Vector3d& nu_b,
                                     const Eigen::Vector2d& p_b) noexcept;

 private:
  ThrustConfigurationParams params_;
  Matrix B_;
};

}  // namespace dynpos::model
