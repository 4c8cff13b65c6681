#pragma once
/// \file
/// HullDrive: the vessel's hull (model/hull.hpp) driven by what a sea-trial log holds instead of
/// by the simulator's actuator states — each unit's thrust and angle feedback, the gyro heading
/// and the wind the wind sensor measured — so that the motion (u, v, r) it gives can be set
/// against the logged motion (the output-error fit of `identify vessel`, the re-simulation of
/// `compare-trial`).
///
/// The force is the simulator's own: the model's units through model::model_unit_forces at the
/// hull's velocity through the water (rudder inflow, propeller advance speed and the tunnel's
/// speed loss from the thrust the feedback gives at rest, as the logger computes it), a
/// [[thruster]] layout through ThrustFeedback; the wind through model::relative_wind_force_b;
/// ν̇ through model::Hull::derivatives in a given current. The heading is the logged one
/// (an input, so a slow heading drift of the model does not turn the current and the wind).

#include <Eigen/Core>
#include <vector>

#include "dynpos/model/hull.hpp"
#include "dynpos/model/rudder.hpp"
#include "dynpos/model/thrust_configuration.hpp"
#include "dynpos/model/thruster.hpp"
#include "dynpos/model/tunnel_thruster.hpp"
#include "dynpos/scenario/thrust_feedback.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::scenario {

/// The logged inputs of one test on one time axis, SI, no missing value.
struct DriveSeries {
  std::vector<double> time_s;  ///< strictly increasing [s]
  std::vector<double> heading_rad;
  /// Per unit in ThrustFeedback::channels() order: the logged thrust [N] (the DP system's
  /// feedback: the thrust of the measured shaft speed at rest) and angle [rad] (zeros for a unit
  /// without one).
  std::vector<std::vector<double>> thrust_N;
  std::vector<std::vector<double>> angle_rad;
  /// The true wind speed [m/s] and the direction it comes from [rad]; empty: no wind force.
  std::vector<double> wind_speed_mps;
  std::vector<double> wind_from_rad;

  std::size_t size() const noexcept { return time_s.size(); }
};

/// The inputs of a DriveSeries at every RK4 stage that depend on the log and the units alone,
/// so that a series simulated many times with different hulls (the fit) mixes, wraps and maps
/// them once. Point 2i is sample i, point 2i + 1 the middle of samples i and i + 1.
struct DriveStages {
  std::vector<double> heading_rad, cos_heading, sin_heading;  ///< per point
  std::vector<double> wind_speed_mps, wind_from_rad;          ///< per point; empty: no wind
  std::size_t units = 0;
  /// Per point, `units` values each: the model's units' shaft speeds [rps] (port, stb, tunnel;
  /// from the logged thrust at rest) or a layout's thrusts [N]; and their angles [rad].
  std::vector<double> input, angle;

  std::size_t points() const noexcept { return heading_rad.size(); }
};

class HullDrive {
 public:
  /// The hull, units and wind coefficients of `vessel` (validated).
  explicit HullDrive(const VesselConfig& vessel);

  const ThrustFeedback& feedback() const noexcept { return feedback_; }
  const model::Hull& hull() const noexcept { return hull_; }

  /// The units' τ_b (X [N], Y [N], N [N·m]) at sample i of `series` for velocity through the
  /// water nu_r (BODY).
  Eigen::Vector3d actuator_tau_b(const DriveSeries& series, std::size_t i,
                                 const Eigen::Vector3d& nu_r) const;

  /// ν = (u, v, r) over ground at every sample of `series` from ν = nu0 at its first, in the
  /// current v_c(t) = current_n + current_rate_n·(t − t₀) (NED) [m/s, m/s²], a slowly varying
  /// current taken as constant in each step: RK4 from sample to sample, the inputs of a step's
  /// middle the mean of its ends (angles along the shorter arc).
  std::vector<Eigen::Vector3d> simulate(
      const DriveSeries& series, const Eigen::Vector3d& nu0, const Eigen::Vector2d& current_n,
      const Eigen::Vector2d& current_rate_n = Eigen::Vector2d::Zero()) const;

  /// The stage inputs of `series` for this drive's units (a drive with the same units gives the
  /// same).
  DriveStages stages(const DriveSeries& series) const;

  /// simulate() with the stage inputs of `series` given: the same result.
  std::vector<Eigen::Vector3d> simulate(const DriveSeries& series, const DriveStages& stages,
                                        const Eigen::Vector3d& nu0,
                                        const Eigen::Vector2d& current_n,
                                        const Eigen::Vector2d& current_rate_n) const;

 private:
  // Appends to `out` the stage inputs of samples i and j mixed by weight w of j.
  void add_point(const DriveSeries& series, std::size_t i, std::size_t j, double w,
                 DriveStages& out) const;
  // τ_b of the units at point p for velocity through the water nu_r (BODY).
  Eigen::Vector3d point_tau_b(const DriveStages& stages, std::size_t p,
                              const Eigen::Vector3d& nu_r) const;
  // ν̇ at point p.
  Eigen::Vector3d nu_dot(const DriveStages& stages, std::size_t p, const Eigen::Vector3d& nu,
                         const Eigen::Vector2d& current_n) const;

  model::Hull hull_;
  model::Thruster propeller_;
  model::Rudder rudder_;
  model::TunnelThruster tunnel_;
  model::ThrustConfiguration layout_;
  model::WindParams wind_;
  ThrustFeedback feedback_;
  bool model_units_;  // the model's own units, else a [[thruster]] layout
};

}  // namespace dynpos::scenario
