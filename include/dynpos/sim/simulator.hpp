#pragma once
/// \file
/// The continuous–discrete simulator of a HybridSystem with periodic sample-and-hold tasks.
///
/// The simulator owns time, sampling and the order of events. Time is the integer tick k on
/// the grid t_k = k·dt (sim_time.hpp). A run from x(0) = x₀ to t_K = end_time does, for
/// k = 0, 1, …, K:
///
///  1. Tasks. Every periodic task whose schedule fires at k runs, in the order the tasks were
///     added. A task sees t_k, k, x(t_k) and the held input u; it may write u (sample and hold:
///     controllers, sensors driving actuators) and, explicitly through mutable_state(), the
///     state (e.g. the discrete part of x). Later tasks at the same tick see earlier tasks'
///     writes. Loggers are tasks too, so a logger added last records what the others did.
///  2. Jumps. While x ∈ D and the dwell-time rule allows it (no jump yet, or t − t_last ≥ τ_D),
///     x ← g(t, x, u). A jump at the same instant as a previous one needs τ_D = 0; if x is still
///     in D after max_jumps_per_instant jumps at one instant, the run stops with status kZeno.
///     Then, if check_flow_set is on and x ∉ C, the run stops with status kLeftFlowSet.
///  3. Flow (only for k < K). One RK4 step over [t_k, t_{k+1}] with u held constant. If event
///     location is on and the system has a guard γ with γ(t_k) > 0 ≥ γ(t_{k+1}), the crossing
///     time t* is located by the Illinois (modified regula falsi) method, each trial point being
///     a single RK4 step of length t* − t_k from x(t_k), until the bracket is shorter than
///     event_time_tolerance; the state is advanced to the end of the bracket where γ ≤ 0 (so
///     x is on the D side), step 2 is applied at t* (jumps and the flow-set check), and the
///     rest of the step [t*, t_{k+1}] is integrated by one RK4 step, itself searched again for
///     a crossing, at most max_events_per_step times. Tasks never run at t*: held inputs
///     change only at ticks.
///
/// The run also stops with status kNonFinite when the state stops being finite. A stopped run is
/// a result with a status and a message, never an exception; bad options throw from validate().
/// Apart from the recorded jump times, a step does not allocate.

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "dynpos/sim/dwell_time.hpp"
#include "dynpos/sim/hybrid_system.hpp"
#include "dynpos/sim/rk4.hpp"
#include "dynpos/sim/sim_time.hpp"

namespace dynpos::sim {

/// Options of Simulator; validate() before use (the Simulator constructor does).
struct SimulatorOptions {
  double dt = 0.01;                     ///< integration step and tick [s], > 0
  double end_time = 10.0;               ///< [s], ≥ 0, an integer multiple of dt
  double dwell_time = 0.0;              ///< τ_D: least time between two jumps [s], ≥ 0
  int max_jumps_per_instant = 100;      ///< Zeno cap: jumps at one instant, ≥ 1
  bool locate_events = true;            ///< locate jump times by the guard, if there is one
  double event_time_tolerance = 1e-10;  ///< bracket width that ends event location [s], > 0
  int max_events_per_step = 16;         ///< located events inside one step, ≥ 1
  bool check_flow_set = true;           ///< stop with kLeftFlowSet when x ∉ C and no jump

  /// Throws std::invalid_argument naming the first bad option and its valid range.
  void validate() const;
};

/// Why a run ended.
enum class SimStatus {
  kOk,           ///< reached end_time
  kZeno,         ///< x stayed in D after max_jumps_per_instant jumps at one instant
  kLeftFlowSet,  ///< x ∉ C and no jump allowed: the solution cannot be continued
  kNonFinite,    ///< the state became NaN or infinite
};

/// A short name of a status ("ok", "zeno", "left flow set", "non-finite").
const char* to_string(SimStatus status) noexcept;

/// The outcome of Simulator::run().
struct SimResult {
  SimStatus status = SimStatus::kOk;
  std::string message;             ///< empty when ok; otherwise what happened, when and why
  std::int64_t steps = 0;          ///< flow steps taken (K when the run completed)
  Tick final_tick = 0;             ///< the tick the run ended at
  double final_time = 0.0;         ///< [s] t at which the run ended (t* inside a step if so)
  Eigen::VectorXd final_state;     ///< x at final_time
  std::vector<double> jump_times;  ///< [s] the time of every jump, in order

  bool ok() const noexcept { return status == SimStatus::kOk; }
};

/// What a periodic task sees and may change at its tick.
class TaskContext {
 public:
  TaskContext(Tick tick, double time, Eigen::VectorXd& state, Eigen::VectorXd& input)
      : tick_(tick), time_(time), state_(state), input_(input) {}

  Tick tick() const noexcept { return tick_; }
  /// t_k = k·dt [s].
  double time() const noexcept { return time_; }
  /// x(t_k).
  const Eigen::VectorXd& state() const noexcept { return state_; }
  /// The state, for a task that updates it on purpose (e.g. the discrete part); keep its size.
  Eigen::VectorXd& mutable_state() noexcept { return state_; }
  /// The held input u.
  const Eigen::VectorXd& input() const noexcept { return input_; }
  /// The held input u, to be written by sample-and-hold tasks; keep its size.
  Eigen::VectorXd& mutable_input() noexcept { return input_; }

 private:
  Tick tick_;
  double time_;
  Eigen::VectorXd& state_;
  Eigen::VectorXd& input_;
};

/// A periodic task: controller, sensor, logger.
using TaskFunction = std::function<void(TaskContext&)>;

/// Called after every jump with t [s], x before and x after.
using JumpObserver =
    std::function<void(double t, const Eigen::VectorXd& x_minus, const Eigen::VectorXd& x_plus)>;

/// Simulates a HybridSystem with sample-and-hold tasks; see the file comment for the event order.
class Simulator {
 public:
  /// A simulator of `system` (kept by reference: it must outlive the simulator).
  /// Throws std::invalid_argument if the options are invalid.
  Simulator(const HybridSystem& system, SimulatorOptions options);

  const SimulatorOptions& options() const noexcept { return options_; }
  const TimeGrid& grid() const noexcept { return grid_; }

  /// Adds a task that fires every period_s [s] from offset_s [s] (both integer multiples of dt;
  /// period > 0, offset ≥ 0). Tasks at the same tick fire in the order they were added.
  /// Throws std::invalid_argument on a period or offset off the grid.
  void add_periodic_task(std::string name, double period_s, double offset_s, TaskFunction task);

  /// Adds a task that fires at every tick.
  void add_every_tick_task(std::string name, TaskFunction task);

  /// Sets the observer called after each jump (empty to remove it).
  void set_jump_observer(JumpObserver observer) { jump_observer_ = std::move(observer); }

  /// The held input u at the start of each run (size system.input_size(); default zeros).
  /// Throws std::invalid_argument on a wrong size.
  void set_initial_input(Eigen::VectorXd u0);

  /// Runs from x(0) = x0 to end_time. Throws std::invalid_argument if x0 has the wrong size;
  /// everything that happens during the run is reported in the result.
  SimResult run(const Eigen::VectorXd& x0);

 private:
  struct Task {
    std::string name;
    PeriodicSchedule schedule;
    TaskFunction function;
  };

  // Step 2 of the event order at time t; returns false (and fills result) to stop the run.
  bool jump_and_check(double t, SimResult& result);
  // Step 3 over [t_k, t_k + dt]; returns false (and fills result) to stop the run.
  bool flow_step(Tick k, SimResult& result);
  // The first time in (t0, t0 + h] where the guard is ≤ 0, starting from x_start_ at t0.
  double locate_event(double t0, double h, double g0, double g1);
  void integrate(double t0, double h, const Eigen::VectorXd& from, Eigen::VectorXd& to);
  bool stop(SimResult& result, SimStatus status, double t, std::string message);

  const HybridSystem& system_;
  SimulatorOptions options_;
  TimeGrid grid_;
  std::vector<Task> tasks_;
  JumpObserver jump_observer_;
  Eigen::VectorXd u0_;

  // Run state and workspace, sized once per run.
  Eigen::VectorXd x_;
  Eigen::VectorXd u_;
  Eigen::VectorXd x_start_;
  Eigen::VectorXd x_end_;
  Eigen::VectorXd x_trial_;
  Eigen::VectorXd x_plus_;
  Rk4<> rk4_;
  DwellTime dwell_;
};

}  // namespace dynpos::sim
