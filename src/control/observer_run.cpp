#include "dynpos/control/observer_run.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace dynpos::control {
namespace {

constexpr double kNever = -std::numeric_limits<double>::infinity();

// The last sample of one input at or before the step being taken.
template <class Value>
struct Held {
  double t_s = kNever;
  Value value{};
  bool seen() const noexcept { return t_s > kNever; }
};

// The inputs as the steps reach them: the last sample of each, in time order.
class InputCursor {
 public:
  explicit InputCursor(const ObserverInputs& in) : in_(in) {}

  // Takes every sample at or before t [s] (with a tolerance for the step grid's round-off).
  void advance_to(double t_s) {
    const double limit = t_s + 1e-9 * std::max(1.0, std::abs(t_s));
    for (; next_ < in_.t_s.size() && in_.t_s[next_] <= limit; ++next_) {
      const std::size_t i = next_;
      const double t = in_.t_s[i];
      if (!std::isnan(in_.north_m[i]) && !std::isnan(in_.east_m[i])) {
        position = {t, Eigen::Vector2d(in_.north_m[i], in_.east_m[i])};
      }
      if (!std::isnan(in_.heading_rad[i])) heading = {t, in_.heading_rad[i]};
      if (!in_.tau_b[i].hasNaN()) {
        tau = {in_.tau_sampled_s.empty() ? t : in_.tau_sampled_s[i], in_.tau_b[i]};
      }
    }
  }

  Held<Eigen::Vector2d> position;
  Held<double> heading;
  Held<Eigen::Vector3d> tau;

 private:
  const ObserverInputs& in_;
  std::size_t next_ = 0;
};

void check_inputs(const ObserverInputs& in) {
  const std::size_t n = in.t_s.size();
  if (in.north_m.size() != n || in.east_m.size() != n || in.heading_rad.size() != n ||
      in.tau_b.size() != n || (!in.tau_sampled_s.empty() && in.tau_sampled_s.size() != n)) {
    throw std::invalid_argument("observer run: the inputs differ in length");
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(in.t_s[i]) || (i > 0 && !(in.t_s[i] > in.t_s[i - 1]))) {
      throw std::invalid_argument("observer run: time is not finite and increasing at sample " +
                                  std::to_string(i));
    }
  }
}

// The first time with a position, a heading and a complete τ; the cursor is left there.
double start_time(InputCursor& cursor, const ObserverInputs& in) {
  for (const double t : in.t_s) {
    cursor.advance_to(t);
    if (cursor.position.seen() && cursor.heading.seen() && cursor.tau.seen()) return t;
  }
  throw std::invalid_argument(
      "observer run: no time with a position, a heading and the thrust of every unit");
}

// The measurement at step time t_k (previous step at t_prev): see the file comment.
Eigen::Vector3d measurement(const InputCursor& c, double t_k, double t_prev, bool hold,
                            double max_hold_s) {
  const auto usable = [&](double t_sample) {
    return hold ? t_k - t_sample <= max_hold_s : t_sample > t_prev;
  };
  Eigen::Vector3d y = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  if (usable(c.position.t_s)) y.head<2>() = c.position.value;
  if (usable(c.heading.t_s)) y.z() = c.heading.value;
  return y;
}

template <class Observer>
ObserverTrack run(Observer& observer, InputCursor& cursor, const ObserverInputs& in, double t0,
                  const ObserverRunOptions& options) {
  ObserverTrack track;
  track.start_s = t0;
  const double dt = 1.0 / options.rate_hz;
  const bool hold = options.holds_measurements();
  const double t_end = in.t_s.back();
  double t_prev = kNever;
  for (long k = 0;; ++k) {
    const double t_k = t0 + static_cast<double>(k) * dt;
    const double t_next = t0 + static_cast<double>(k + 1) * dt;
    if (t_next > t_end + 1e-9 * std::max(1.0, std::abs(t_end))) break;
    cursor.advance_to(t_k);
    const Eigen::Vector3d y = measurement(cursor, t_k, t_prev, hold, options.max_hold_s);
    if (std::isnan(y.x())) {
      ++track.coasting_steps;
    } else {
      ++track.position_steps;
    }
    if (t_k - cursor.tau.t_s > options.max_hold_s) ++track.stale_thrust_steps;
    observer.step(y, cursor.tau.value, dt);
    track.t_s.push_back(t_next);
    track.estimate.push_back(observer.estimate());
    track.position_age_s.push_back(t_next - cursor.position.t_s);
    t_prev = t_k;
  }
  if (track.t_s.empty()) {
    throw std::invalid_argument("observer run: the inputs end before the first step");
  }
  return track;
}

}  // namespace

void ObserverRunOptions::validate() const {
  if (kind != ObserverKind::kPassive && kind != ObserverKind::kEkf) {
    throw std::invalid_argument("observer run: the observer must be passive or ekf");
  }
  if (!(std::isfinite(rate_hz) && rate_hz > 0.0)) {
    throw std::invalid_argument("observer run: the rate must be finite and > 0");
  }
  if (!(std::isfinite(max_hold_s) && max_hold_s > 0.0)) {
    throw std::invalid_argument("observer run: the longest hold must be finite and > 0");
  }
  if (kind == ObserverKind::kPassive && hold_measurements == false) {
    // Continuous in time, it takes a step without a measurement for a loss (passive_observer.hpp).
    throw std::invalid_argument("observer run: the passive observer runs on held measurements");
  }
}

bool ObserverRunOptions::holds_measurements() const noexcept {
  return hold_measurements.value_or(kind == ObserverKind::kPassive);
}

ObserverTrack run_observer(const ObserverModel& model, const ObserverInputs& inputs,
                           const ObserverRunOptions& options) {
  options.validate();
  model.validate();
  check_inputs(inputs);
  InputCursor cursor(inputs);
  const double t0 = start_time(cursor, inputs);
  const Eigen::Vector3d eta0(cursor.position.value.x(), cursor.position.value.y(),
                             cursor.heading.value);
  if (options.kind == ObserverKind::kPassive) {
    PassiveObserver o(model, passive_observer_gains(model, options.passive), eta0);
    return run(o, cursor, inputs, t0, options);
  }
  // Each fix is taken once: the steps between fixes are no loss of the position.
  EkfObserverTuning tuning = options.ekf;
  tuning.measurement_lost_after_s = options.max_hold_s;
  EkfObserver o(model, tuning, eta0);
  return run(o, cursor, inputs, t0, options);
}

}  // namespace dynpos::control
