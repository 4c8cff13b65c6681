#include "dynpos/sim/simulator.hpp"

#include "format_number.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

namespace dynpos::sim {

namespace {

void require(bool condition, const std::string& message) {
  if (!condition) throw std::invalid_argument("SimulatorOptions: " + message);
}

// Slack in the dwell-time comparison t − t_last ≥ τ_D: the two times are products k·dt (or
// located event times) with rounding errors of a few ulp of t, far below 1e-6·dt for any run
// shorter than ~10⁹ ticks, so a dwell time of exactly n·dt is honoured at the n-th tick.
constexpr double kDwellSlackPerDt = 1e-6;

}  // namespace

void SimulatorOptions::validate() const {
  require(std::isfinite(dt) && dt > 0.0,
          "dt = " + detail::format_number(dt) + " s must be finite and > 0");
  require(std::isfinite(end_time) && end_time >= 0.0,
          "end_time = " + detail::format_number(end_time) + " s must be finite and >= 0");
  // Throws if end_time is not an integer multiple of dt.
  (void)TimeGrid(dt).ticks(end_time, "SimulatorOptions: end_time");
  require(std::isfinite(dwell_time) && dwell_time >= 0.0,
          "dwell_time = " + detail::format_number(dwell_time) + " s must be finite and >= 0");
  require(max_jumps_per_instant >= 1,
          "max_jumps_per_instant = " + std::to_string(max_jumps_per_instant) + " must be >= 1");
  require(std::isfinite(event_time_tolerance) && event_time_tolerance > 0.0,
          "event_time_tolerance = " + detail::format_number(event_time_tolerance) +
              " s must be finite and > 0");
  require(max_events_per_step >= 1,
          "max_events_per_step = " + std::to_string(max_events_per_step) + " must be >= 1");
}

const char* to_string(SimStatus status) noexcept {
  switch (status) {
    case SimStatus::kOk:
      return "ok";
    case SimStatus::kZeno:
      return "zeno";
    case SimStatus::kLeftFlowSet:
      return "left flow set";
    case SimStatus::kNonFinite:
      return "non-finite";
  }
  return "unknown";
}

Simulator::Simulator(const HybridSystem& system, SimulatorOptions options)
    : system_(system),
      options_((options.validate(), options)),
      grid_(options_.dt),
      dwell_(options_.dwell_time, kDwellSlackPerDt * options_.dt) {
  if (system_.state_size() < 1) throw std::invalid_argument("Simulator: state_size() must be >= 1");
  if (system_.input_size() < 0) throw std::invalid_argument("Simulator: input_size() must be >= 0");
  u0_ = Eigen::VectorXd::Zero(system_.input_size());
}

void Simulator::add_periodic_task(std::string name, double period_s, double offset_s,
                                  TaskFunction task) {
  const std::string what = "task '" + name + "'";
  PeriodicSchedule schedule;
  schedule.period = grid_.ticks_for_period(period_s, what + " period");
  schedule.offset = grid_.ticks(offset_s, what + " offset");
  tasks_.push_back(Task{std::move(name), schedule, std::move(task)});
}

void Simulator::add_every_tick_task(std::string name, TaskFunction task) {
  tasks_.push_back(Task{std::move(name), PeriodicSchedule{1, 0}, std::move(task)});
}

void Simulator::set_initial_input(Eigen::VectorXd u0) {
  if (u0.size() != system_.input_size()) {
    throw std::invalid_argument("Simulator: initial input has size " + std::to_string(u0.size()) +
                                ", the system's input_size() is " +
                                std::to_string(system_.input_size()));
  }
  u0_ = std::move(u0);
}

SimResult Simulator::run(const Eigen::VectorXd& x0) {
  const Eigen::Index n = system_.state_size();
  if (x0.size() != n) {
    throw std::invalid_argument("Simulator::run: initial state has size " +
                                std::to_string(x0.size()) + ", the system's state_size() is " +
                                std::to_string(n));
  }
  x_ = x0;
  u_ = u0_;
  x_start_.resize(n);
  x_end_.resize(n);
  x_trial_.resize(n);
  x_plus_.resize(n);
  rk4_ = Rk4<>(n);
  dwell_.reset();

  SimResult result;
  const Tick end_tick = grid_.ticks(options_.end_time, "end_time");
  for (Tick k = 0; k <= end_tick; ++k) {
    const double t = grid_.time(k);
    result.final_tick = k;
    // 1. Tasks, in the order they were added.
    for (Task& task : tasks_) {
      if (!task.schedule.fires_at(k)) continue;
      TaskContext context(k, t, x_, u_);
      task.function(context);
      if (x_.size() != n || u_.size() != system_.input_size()) {
        throw std::logic_error("Simulator: task '" + task.name +
                               "' changed the size of the state or the input");
      }
    }
    if (!x_.allFinite()) {
      stop(result, SimStatus::kNonFinite, t,
           "state not finite after the tasks at t = " + detail::format_number(t) + " s");
      return result;
    }
    // 2. Jumps and the flow-set check.
    if (!jump_and_check(t, result)) return result;
    if (k == end_tick) break;
    // 3. Flow.
    if (!flow_step(k, result)) return result;
    ++result.steps;
  }
  result.final_time = grid_.time(end_tick);
  result.final_state = x_;
  return result;
}

bool Simulator::jump_and_check(double t, SimResult& result) {
  int jumps_here = 0;
  bool dwell_blocked = false;
  while (system_.in_jump_set(t, x_, u_)) {
    if (!dwell_.allows(t)) {
      dwell_blocked = true;
      break;
    }
    if (jumps_here == options_.max_jumps_per_instant) {
      return stop(result, SimStatus::kZeno, t,
                  "Zeno behaviour: x still in the jump set D after " + std::to_string(jumps_here) +
                      " jumps at t = " + detail::format_number(t) +
                      " s; a dwell_time > 0 or a jump map that leaves D avoids it");
    }
    system_.jump(t, x_, u_, x_plus_);
    if (jump_observer_) jump_observer_(t, x_, x_plus_);
    x_.swap(x_plus_);  // swaps buffers, no allocation
    ++jumps_here;
    dwell_.record_jump(t);
    result.jump_times.push_back(t);
    if (!x_.allFinite()) {
      return stop(result, SimStatus::kNonFinite, t,
                  "state not finite after a jump at t = " + detail::format_number(t) + " s");
    }
  }
  if (options_.check_flow_set && !system_.in_flow_set(t, x_, u_)) {
    return stop(result, SimStatus::kLeftFlowSet, t,
                dwell_blocked
                    ? "x is outside the flow set C at t = " + detail::format_number(t) +
                          " s and in D, but the dwell time " +
                          detail::format_number(options_.dwell_time) +
                          " s since the last jump at " +
                          detail::format_number(*dwell_.last_jump_time()) + " s forbids a jump"
                    : "x is outside both the flow set C and the jump set D at t = " +
                          detail::format_number(t) + " s");
  }
  return true;
}

void Simulator::integrate(double t0, double h, const Eigen::VectorXd& from, Eigen::VectorXd& to) {
  const auto f = [this](double t, const Eigen::VectorXd& x, Eigen::VectorXd& dxdt) {
    system_.flow(t, x, u_, dxdt);
  };
  rk4_.step(f, t0, h, from, to);
}

bool Simulator::flow_step(Tick k, SimResult& result) {
  double t0 = grid_.time(k);
  const double t_end = grid_.time(k + 1);
  double h = t_end - t0;
  x_start_ = x_;
  integrate(t0, h, x_start_, x_end_);
  if (options_.locate_events && system_.has_guard()) {
    double g0 = system_.guard(t0, x_start_, u_);
    double g1 = system_.guard(t0 + h, x_end_, u_);
    int events = 0;
    while (g0 > 0.0 && g1 <= 0.0) {
      if (events == options_.max_events_per_step) {
        return stop(
            result, SimStatus::kZeno, t0,
            "Zeno behaviour: more than " + std::to_string(events) +
                " located events inside the step from t = " + detail::format_number(grid_.time(k)) +
                " s; raise dwell_time or max_events_per_step if this is intended");
      }
      ++events;
      const double tau = locate_event(t0, h, g0, g1);
      integrate(t0, tau, x_start_, x_);
      const double t_event = t0 + tau;
      if (!x_.allFinite()) {
        return stop(result, SimStatus::kNonFinite, t_event,
                    "state not finite at t = " + detail::format_number(t_event) + " s");
      }
      if (!jump_and_check(t_event, result)) return false;
      t0 = t_event;
      h = t_end - t0;
      x_start_ = x_;
      if (h <= 0.0) {
        x_end_ = x_;
        break;
      }
      integrate(t0, h, x_start_, x_end_);
      g0 = system_.guard(t0, x_start_, u_);
      g1 = system_.guard(t_end, x_end_, u_);
    }
  }
  x_.swap(x_end_);
  if (!x_.allFinite()) {
    return stop(result, SimStatus::kNonFinite, t_end,
                "state not finite after the step to t = " + detail::format_number(t_end) + " s");
  }
  return true;
}

double Simulator::locate_event(double t0, double h, double g0, double g1) {
  // Illinois method on τ ∈ [a, b] with γ(a) > 0 ≥ γ(b): the regula falsi point, and when one
  // end is kept twice in a row its γ is halved so that both ends converge.
  double a = 0.0;
  double b = h;
  double ga = g0;
  double gb = g1;
  int kept = 0;  // +1: b was kept last time, −1: a was kept last time
  constexpr int kMaxIterations = 200;
  for (int i = 0; i < kMaxIterations && b - a > options_.event_time_tolerance; ++i) {
    double tau = (a * gb - b * ga) / (gb - ga);
    if (!(tau > a && tau < b)) tau = 0.5 * (a + b);
    integrate(t0, tau, x_start_, x_trial_);
    const double g = system_.guard(t0 + tau, x_trial_, u_);
    if (g > 0.0) {
      a = tau;
      ga = g;
      if (kept == 1) gb *= 0.5;
      kept = 1;
    } else {
      b = tau;
      gb = g;
      if (kept == -1) ga *= 0.5;
      kept = -1;
    }
  }
  return b;
}

bool Simulator::stop(SimResult& result, SimStatus status, double t, std::string message) {
  result.status = status;
  result.message = std::move(message);
  result.final_time = t;
  result.final_state = x_;
  return false;
}

}  // namespace dynpos::sim
