#pragma once
/// \file
/// Quasi-static DP capability (DNV-ST-0111 Levels 1 and 2): for each direction of the weather
/// relative to the bow, the strongest environment whose mean load (times the reserve for
/// dynamics) the thrusters can balance within their limits, intact or with actuators lost.
///
/// Level 1: the standard's environment table and the thrusters' rated thrust at rest (the
/// rudders lift only in their propellers' slipstream). Level 2: the vessel's own thrust losses as
/// the model has them (the propellers' thrust, the tunnel's and the rudders' lift at the current's
/// inflow) and any environment table, e.g. a site's. Wind, waves and current come from the same
/// direction.
///
/// The vessel's own load models give the mean load (model/environment.hpp wind coefficients,
/// model/hull.hpp damping and added mass in the current's relative flow, model/sea_state.hpp
/// mean drift); the standard's generic Level 1 coefficients are not used.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "dynpos/capability/environment_table.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::capability {

/// The mean environmental load (X [N], Y [N], N [N·m]) in BODY on the vessel at rest, wind,
/// waves and current all coming from from_rel_rad [rad] off the bow (0 head-on, π/2 from
/// starboard), without any reserve.
Eigen::Vector3d mean_environment_load_b(const scenario::VesselConfig& vessel,
                                        const Environment& environment, double from_rel_rad);

/// The surge inflow speed of the current at the thrusters [m/s] (positive from ahead).
double current_inflow_mps(double current_mps, double from_rel_rad);

/// The range of a bisection's tolerance on the wind [m/s]: finer than 1e-6 m/s means nothing
/// to a vessel, and a tolerance below one ulp of the wind could never be reached.
inline constexpr double kMinWindTolerance_mps = 1e-6;
inline constexpr double kMaxWindTolerance_mps = 10.0;
/// The most halvings of a bisection between two rows: a bracket of 10⁹ m/s narrowed to 1e-6 m/s
/// takes 50; the bisection also ends when the midpoint cannot be told from either end.
inline constexpr int kMaxBisections = 64;

/// Options of a quasi-static rose.
struct QuasiStaticOptions {
  int level = 1;                                      ///< 1 or 2
  EnvironmentTable environment = dnv_level1_table();  ///< wind → waves and current
  double dynamic_allowance = kDynamicAllowance;       ///< factor on the load, ≥ 1
  double direction_step_deg = 10.0;                   ///< 0, step, …, < 360 [deg]
  double wind_tolerance_mps = 0.01;  ///< bisection ends within this [m/s], 1e-6 … 10
  /// Throws core::InputError naming the first bad option (request keys: level,
  /// dynamic_allowance, direction_step, wind_tolerance) or a bad environment table.
  void validate() const;
};

/// Throws core::InputError (option "direction_step") unless step_deg is finite, > 0, at most
/// 360 and divides 360 into at most 3600 directions.
void check_direction_step(double step_deg);

/// Throws core::InputError (option "wind_tolerance") unless tolerance_mps is within
/// [kMinWindTolerance_mps, kMaxWindTolerance_mps].
void check_wind_tolerance(double tolerance_mps);

/// True while a bisection of [lo, hi] should go on: wider than `tolerance`, fewer than
/// kMaxBisections halvings done, and a midpoint strictly between the ends.
bool bisect_further(double lo, double hi, double tolerance, int halvings);

/// One direction of a rose.
struct CapabilityPoint {
  double direction_deg = 0.0;  ///< where the weather comes from, off the bow, clockwise [deg]
  int dp_number = 0;           ///< the largest table row held, with every row below it
  double max_wind_mps = 0.0;   ///< the strongest wind held, between the rows
  /// The table's last row (at level 3: the last the simulator takes, H_s ≤ 8 m) is held:
  /// max_wind_mps is a floor.
  bool beyond_table = false;
  /// The actuators at a limit at max_wind_mps, joined by '+' (a layout's units: at a limit in
  /// the allocation of the first wind not held, the bisection's other end); "none" beyond the
  /// table.
  std::string limiting;
  std::string failure;  ///< the case: "none" (intact) or the actuator lost
};

/// The capability at one direction [rad off the bow] with the actuators in `failed` lost (on
/// top of the capacities of vessel.allocation). A vessel with a [[thruster]] layout is balanced
/// by its units (model/layout_allocator.hpp; an azimuth's disc as its 32-sided polygon, up to
/// 0.48 % short) at their ratings at both levels, `failed` naming units and "group:NAME"s.
CapabilityPoint quasi_static_point(const scenario::VesselConfig& vessel,
                                   const std::vector<std::string>& failed, double from_rel_rad,
                                   const QuasiStaticOptions& options);

/// The rose: one point per direction step, with the actuators in `failed` lost.
std::vector<CapabilityPoint> quasi_static_rose(const scenario::VesselConfig& vessel,
                                               const std::vector<std::string>& failed,
                                               const QuasiStaticOptions& options);

/// The single failures of the vessel: each actuator of the model lost alone (actuator_names()),
/// or each unit and each redundancy group ("group:NAME") of a [[thruster]] layout.
std::vector<std::string> single_failures(const scenario::VesselConfig& vessel);

/// Throws core::InputError (option `key`) naming the cases unless `name` is one of
/// single_failures(vessel).
void check_failure(const scenario::VesselConfig& vessel, const std::string& name, const char* key);

/// Per direction the smallest capability over `roses` (each a rose of one failure case, same
/// directions): DNV's worst-case failure; `failure` says which case it is there.
std::vector<CapabilityPoint> worst_case(const std::vector<std::vector<CapabilityPoint>>& roses);

}  // namespace dynpos::capability
