#pragma once
/// \file
/// DP capability with the failure as it happens (DNV-ST-0111 Level 3 with its transient; IMCA
/// M 190 asks for the excursion after a worst-case failure, a footprint rather than a
/// post-failure rose): the virtual vessel holds position at heading 0 under its DP controller in
/// the weather of one environment-table row from one direction; after settle_s the named
/// failure trips (scenario::UnitFailure: the units' drives are cut, the allocation redistributes)
/// and the run goes on for after_s. Per direction and row, over `seeds` runs seeded
/// seed, seed + 1, …: the largest horizontal excursion of the control origin from its
/// pre-failure mean and the time to it, the largest heading excursion and the recovery, with the
/// meanings of truth.json's `failure` (scenario::FailureTruth). The point holds when every run's
/// excursions stay within the footprints. Each run depends on its seed, direction and row alone,
/// so the footprint does not depend on the number of jobs.

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dynpos/capability/environment_table.hpp"
#include "dynpos/control/observer.hpp"
#include "dynpos/scenario/vessel_config.hpp"

namespace dynpos::capability {

/// Options of a transient footprint.
struct TransientOptions {
  EnvironmentTable environment = dnv_level1_table();  ///< wind → waves and current
  /// The rows (DP numbers) run. Source: reasoned — Beaufort 4–6 (5.4–10.7 m/s), the weather of
  /// the virtual Gunnerus' single failures at level 1.
  std::vector<int> rows{3, 4, 5};
  double direction_step_deg = 10.0;  ///< 0, step, …, < 360 [deg]
  double settle_s = 300.0;           ///< intact stationkeeping before the failure [s], ≥ 60
  double after_s = 300.0;            ///< run after the failure [s], > 0
  double footprint_m = 5.0;          ///< largest excursion held [m], > 0
  double footprint_deg = 3.0;        ///< largest heading excursion held [deg], > 0
  unsigned seeds = 1;                ///< runs per point, 1 … 1000
  std::uint64_t seed = 1;            ///< the first run's seed
  control::ObserverKind observer = control::ObserverKind::kIdeal;  ///< what the DP loop runs on
  unsigned jobs = 0;  ///< parallel runs; 0 = every core
  /// Throws core::InputError naming the first bad option (request keys: rows, direction_step,
  /// settle, after, footprint, footprint_deg, seeds).
  void validate() const;
};

/// One run of a point.
struct TransientRun {
  std::uint64_t seed = 0;
  double peak_excursion_m = 0.0;     ///< from the pre-failure mean position [m]
  double time_to_peak_s = 0.0;       ///< from the failure [s]
  double peak_heading_deg = 0.0;     ///< |heading − pre-failure mean| [deg]
  std::optional<double> recovery_s;  ///< back within the pre-failure footprint; none: never
  /// The true environmental load's mean over the pre-failure minute (BODY) [N, N, N·m].
  Eigen::Vector3d load_b = Eigen::Vector3d::Zero();
  /// The observer's bias estimate's mean over the same minute (BODY); the true load's with the
  /// ideal and the raw loop, which have no bias estimate of their own.
  Eigen::Vector3d estimated_load_b = Eigen::Vector3d::Zero();
};

/// One direction and row.
struct TransientPoint {
  double direction_deg = 0.0;  ///< the weather comes from, relative to the bow [deg]
  int dp_number = 0;           ///< the environment row
  double wind_mps = 0.0;
  std::string failure;
  std::vector<TransientRun> runs;  ///< per seed
  double peak_excursion_m = 0.0;   ///< the largest over the runs
  double time_to_peak_s = 0.0;     ///< of that run
  double peak_heading_deg = 0.0;   ///< the largest over the runs
  bool holds = false;              ///< every run within both footprints
};

/// The footprint of `failure` (a unit, "group:NAME" or a model actuator, as
/// scenario::FailureEvent names it) on `vessel`: per direction, then per row.
std::vector<TransientPoint> transient_footprint(const scenario::VesselConfig& vessel,
                                                const std::string& failure,
                                                const TransientOptions& options);

}  // namespace dynpos::capability
