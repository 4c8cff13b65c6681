#pragma once
/// \file
/// The case studies of thesis section 5.3: the first-order system (5.68)–(5.80) and the DP
/// vessel (5.81)–(5.92) under disturbance steps, with the conventional integral action
/// (JumpSet::kNone), the ideal jump set or the sampled one. A run returns values: metrics and
/// the time series for plots.
///
/// Event order (sim/simulator.hpp): at every tick t_k = k·dt, first the disturbance steps due
/// at t_k change the true disturbance (d, or b in NED), then the derivative sampler (every
/// T_s, sampled jump set only) writes its estimate, then the metrics sample the state, then
/// the jumps happen (at most one per dwell time), then one RK4 step.
///
/// Metrics, on the tick grid:
///  - settle_s[i]: the time after step i until the integral-state error (x₂ = d − d̂, or
///    x₃ = b − b̂ per DOF) stays within settle_band (5 %) of that step's size until the next
///    step (or the end); absent when it does not settle within that window. For a vector step
///    each DOF has its own band, settle_band·|Δb_j| (DOFs the step does not move use
///    settle_band·max_j |Δb_j|, in their own unit).
///  - residual[i]: the largest |error_j| / |Δ_j| at the end of step i's window.
///  - iae, peak_error: ∫|e|dt (trapezoidal) and max |e| of the position error e: x₁ for the
///    first-order system; for DP the horizontal distance √(x₁,₁² + x₁,₂²) [m], with the heading
///    error reported apart (heading_iae [rad·s], heading_peak [rad]).
///  - v_increase_at_jumps: the largest V(x⁺) − V(x) over all jumps (absent without jumps). For
///    the ideal jump sets it is ≤ 0 up to rounding (Theorems 6 and 7); the sampled sets may
///    let noise trigger a jump that raises V, and this is where it shows.

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dynpos/hybrid/dp_hybrid_system.hpp"
#include "dynpos/hybrid/first_order_system.hpp"
#include "dynpos/hybrid/jump_set.hpp"
#include "dynpos/hybrid/trace.hpp"
#include "dynpos/sim/simulator.hpp"

namespace dynpos::hybrid {

/// A step of the disturbance d of the first-order system by `delta` at time_s [s].
struct DisturbanceStep {
  double time_s = 0.0;
  double delta = 0.0;
};

/// A step of the DP bias b (NED) by delta_n [N, N, N·m] at time_s [s].
struct BiasStep {
  double time_s = 0.0;
  Eigen::Vector3d delta_n = Eigen::Vector3d::Zero();
};

/// Simulation settings shared by both case studies. Times are integer multiples of dt.
struct CaseTiming {
  double dt_s = 1e-3;             ///< RK4 step and tick [s], > 0
  double end_time_s = 60.0;       ///< [s], > 0
  double dwell_time_s = 0.1;      ///< least time between jumps [s], ≥ 0 (thesis: 0.1 s)
  double sample_period_s = 0.03;  ///< derivative sampling period T_s [s], > 0 (thesis: 0.03 s)
  double noise_power = 0.0;       ///< derivative noise power (derivative_sampler.hpp), ≥ 0
  double log_period_s = 0.01;     ///< trace rows every this many seconds [s], > 0
  double settle_band = 0.05;      ///< settling band as a fraction of the step size, in (0, 1)
  std::uint64_t seed = 1;         ///< master seed of the derivative noise

  /// Throws std::invalid_argument naming the first bad setting and its valid range.
  void validate() const;
};

/// The first-order case study; the defaults are section 5.3.1 (ideal jump set).
struct FirstOrderCaseOptions {
  FirstOrderParams params;  ///< params.jump_set selects conventional, ideal or sampled
  std::vector<DisturbanceStep> steps = {{5.0, 100.0}, {30.0, -50.0}};
  CaseTiming timing = {.noise_power = 0.1};  ///< section 5.3.1; noise power 0.1

  /// Throws std::invalid_argument naming the first bad option (steps must be inside the run,
  /// on the tick grid, in increasing time order, with delta ≠ 0).
  void validate() const;
};

/// The DP case study; the defaults are section 5.3.2 (ideal jump set).
struct DpCaseOptions {
  DpHybridParams params;  ///< params.jump_set selects conventional, ideal or sampled
  std::vector<BiasStep> steps = {{10.0, Eigen::Vector3d(3000.0, 2000.0, 1000.0)}};  // (5.91)
  CaseTiming timing = {.noise_power = 20.0};  ///< section 5.3.2; noise power 20

  /// Throws std::invalid_argument naming the first bad option (as FirstOrderCaseOptions).
  void validate() const;
};

/// The measures of one run (see the file comment).
struct CaseMetrics {
  int jumps = 0;
  std::vector<std::optional<double>> settle_s;  ///< [s] per step; absent: not settled
  std::vector<double> residual;                 ///< per step, fraction of the step left
  double iae = 0.0;                             ///< ∫|e|dt [unit of e · s]
  double peak_error = 0.0;                      ///< max |e| [unit of e]
  double heading_iae = 0.0;                     ///< DP only [rad·s]; NaN for first order
  double heading_peak = 0.0;                    ///< DP only [rad]; NaN for first order
  std::optional<double> v_increase_at_jumps;    ///< max V(x⁺) − V(x); absent: no jumps
  double v_max = 0.0;                           ///< max V over the run, a scale for the above
};

/// The outcome of a case-study run.
struct CaseResult {
  std::string case_name;  ///< "first-order" or "dp"
  JumpSet jump_set = JumpSet::kNone;
  sim::SimStatus status = sim::SimStatus::kOk;
  std::string message;             ///< empty when ok
  std::string error_label;         ///< what e of iae/peak_error is
  std::string error_unit;          ///< its unit ("" for the dimensionless first-order system)
  std::vector<double> step_times;  ///< [s]
  std::vector<double> jump_times;  ///< [s]
  CaseMetrics metrics;
  /// Rows every log period, plus two rows at each jump and at each disturbance step (before and
  /// after). Channels, first order: x1, x2, V, d, d_hat. DP: x1.surge, x1.sway, x1.yaw
  /// [m, m, rad], x2.surge, x2.sway, x2.yaw [m/s, m/s, rad/s], x3.north, x3.east, x3.yaw
  /// [N, N, N·m], V.
  Trace trace;

  bool ok() const noexcept { return status == sim::SimStatus::kOk; }
};

/// Runs the first-order case study. Throws std::invalid_argument if the options are invalid
/// (including a violated Theorem 6); a run that stops early is reported in the result.
CaseResult run_first_order_case(const FirstOrderCaseOptions& options);

/// Runs the DP case study. Throws std::invalid_argument if the options are invalid
/// (including a violated Theorem 7); a run that stops early is reported in the result.
CaseResult run_dp_case(const DpCaseOptions& options);

}  // namespace dynpos::hybrid
